// The explicit and implicit solvers, run with damping from rest under a suddenly applied
// tip load, settle where the static solver puts the cantilever.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "elastica_reference.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace validation_solvers_test {

// A stocky strip (L / t = 10) on 4 segments: its highest frequency is only ~85 times its
// first, so the explicit solver settles in ~1e5 steps. All three solvers share the model.
CantileverSpec stocky_strip() {
  CantileverSpec s = validation::slender_strip(4);
  s.thickness = 1e-2;
  s.tip_force = Vec3(0, 0, -2 * bending_rigidity(s) / (s.length * s.length));  // alpha = 2
  return s;
}

// First bending angular frequency from beam theory, rad/s.
double omega1(const CantileverSpec& s) {
  return reference::cantilever_omega(1, s.length, bending_rigidity(s),
                                     s.density * s.width * s.thickness);
}

// Tip after a damped run from the flat state; damping ratio zeta1 of the first mode.
Vec3 settled_tip(SolverKind kind, double zeta1, double periods) {
  CantileverSpec s = stocky_strip();
  s.damping_time = 2 * zeta1 / omega1(s);
  const Model model = build_cantilever_model(s);
  State state = initial_state(model);
  SolverSettings settings;
  settings.kind = kind;
  settings.t_end = periods * 2 * std::numbers::pi / omega1(s);
  settings.rtol = 1e-3;
  const SolverStats stats = run_solver(model, state, settings, {});
  EXPECT_EQ(stats.status, "ok") << stats.message;
  EXPECT_LT(validation::largest_speed(state, s.length), 1e-6 * s.length * omega1(s));
  return validation::probe_position(model, state, "tip");
}

TEST(SolverAgreement, DynamicSolversSettleOnStaticCantilever) {
  const CantileverSpec s = stocky_strip();
  const Model model = build_cantilever_model(s);
  const Vec3 tip_static = validation::probe_position(model, validation::solve_static(model), "tip");
  // Large deflection: the check compares a genuinely nonlinear equilibrium.
  ASSERT_GT(-tip_static.z(), 0.4 * s.length);
  // Explicit: light damping (stiffness-proportional damping shortens its stable step).
  const Vec3 tip_explicit = settled_tip(SolverKind::Explicit, 0.06, 40);
  // Implicit: critical damping of the first mode; backward Euler takes long steps.
  const Vec3 tip_implicit = settled_tip(SolverKind::Implicit, 1.0, 5);
  std::printf("tip static (%.7f, %.7f), explicit (%.7f, %.7f), implicit (%.7f, %.7f) m\n",
              tip_static.x(), tip_static.z(), tip_explicit.x(), tip_explicit.z(), tip_implicit.x(),
              tip_implicit.z());
  EXPECT_LT((tip_explicit - tip_static).norm(), 1e-6 * s.length);
  EXPECT_LT((tip_implicit - tip_static).norm(), 1e-6 * s.length);
}

}  // namespace validation_solvers_test
}  // namespace finseg
