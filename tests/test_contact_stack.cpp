// A strip folded flat into 20 layers (a FOLD pattern with its folded coordinates,
// patterns/stack_pattern.hpp) pressed between a clamped base and a loaded top plate, static
// solver. Every layer touches the ones above and below, not only its neighbours along the
// sheet. References: the limit (penetration below a quarter of the thickness for
// every pair), equilibrium (the base carries exactly the load; Newton's third law through the
// stack) and the order of the layers (none passes through another).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "collision/contact_forces.hpp"
#include "contact_test_util.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "patterns/pattern_checks.hpp"
#include "patterns/stack_pattern.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace contact_stack_test {

struct StackResult {
  SolverStats stats;
  ContactSummary contact;
  int base = -1, top = -1;
  std::vector<double> layer_lo, layer_hi;  // lowest / highest centroid z of each layer, m
  int segments = 0;
};

// `layers` layers of `cells` x `cells` cells of 5 mm, paper 0.1 mm thick (4 GPa), folds one
// thickness wide; base and top plate 20 mm square, set down at 1 % of the thickness into the stack
// so that their friction anchors hold the top plate from the start; `load` N on the top plate.
StackResult press_stack(int layers, int cells, double load) {
  const double t = 1e-4, cell = 5e-3;
  CreasePattern pat = folded_stack_pattern(layers, cells, cell, t);
  validate_pattern(pat, "<stack>");
  PatternSheetSpec spec;
  spec.thickness = t;
  spec.youngs_modulus = 4e9;
  spec.density = 800;
  // The sheet's fold angle has FOLD's opposite sign: valleys at -90 deg, mountains at +90 deg.
  spec.valley_law = std::make_shared<LinearCreaseLaw>(1e-3, -0.5 * kPi);
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(1e-3, 0.5 * kPi);
  Model m = build_pattern_model(pat, spec, "<stack>");
  StackResult r;
  r.segments = static_cast<int>(m.bodies.size());
  const double L = cells * cell, set_in = 0.01 * t;
  const Vec3 centre(0.5 * L, 0.5 * L, 0);
  r.base = static_cast<int>(m.bodies.size());
  m.bodies.push_back(test::plate("base", 1e-3, Vec3(20e-3, 20e-3, t),
                                 centre + Vec3(0, 0, -t + set_in), Mat3::Identity(), true));
  r.top = r.base + 1;
  m.bodies.push_back(
      test::plate("top", 1e-3, Vec3(20e-3, 20e-3, t), centre + Vec3(0, 0, layers * t - set_in)));
  m.loads.push_back({r.top, Vec3::Zero(), Vec3(0, 0, -load), Vec3::Zero(), false});
  // docs/contact.md's 80 g/m^2 paper: 1 N at 10 um, anchor friction (static solver).
  ContactSuggestion paper;
  paper.stiffness = 3e7;
  paper.damping = 4.4;
  paper.damping_depth = 1e-5;
  paper.tangential_stiffness = 1.5e5;
  paper.tangential_damping = 4.4;
  m.contact = test::anchor_contact(paper, 0.5, 0.4);
  m.finalize_dofs();
  State s = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  set.load_steps = 4;
  r.stats = run_solver(m, s, set, [](const State&, const BodyForces&) {});
  r.contact = contact_summary(m, s);
  r.layer_lo.assign(layers, 1e9);
  r.layer_hi.assign(layers, -1e9);
  const int per = cells + 1;
  for (int i = 0; i < r.segments; ++i) {
    const int col = m.bodies[i].panel / cells;  // one segment per face, faces by column
    if (col % per == cells) continue;           // a fold
    const int k = col / per;
    r.layer_lo[k] = std::min(r.layer_lo[k], s.p_W[i].z());
    r.layer_hi[k] = std::max(r.layer_hi[k], s.p_W[i].z());
  }
  return r;
}

void check_stack(int layers, int cells, double load) {
  const double t = 1e-4;
  const StackResult r = press_stack(layers, cells, load);
  ASSERT_EQ(r.stats.status, "ok") << r.stats.message;
  double on_base = 0, on_top = 0, deepest = 0;
  int between_layers = 0;
  for (const ContactPairForce& p : r.contact.pairs) {
    deepest = std::max(deepest, p.max_penetration);
    EXPECT_LT(p.max_penetration, 0.25 * t) << p.a << "-" << p.b;
    if (p.b == r.base) on_base += p.f_b_W.z();
    if (p.b == r.top) on_top += p.f_b_W.z();
    if (p.b < r.base) ++between_layers;
  }
  // The base carries the load and the top plate passes it on (forces on them: down, up).
  EXPECT_NEAR(-on_base / load, 1.0, 1e-3);
  EXPECT_NEAR(on_top / load, 1.0, 1e-3);
  for (int k = 0; k + 1 < layers; ++k) {
    EXPECT_GT(r.layer_lo[k + 1], r.layer_hi[k]) << "layers " << k + 1 << " and " << k + 2;
    EXPECT_GT(r.layer_lo[k + 1] - r.layer_lo[k], 0.5 * t) << "layers " << k + 1 << ", " << k + 2;
  }
  // Every interface carries the load through all its facing cells but those beside the fold.
  EXPECT_GE(between_layers, (cells - 1) * cells * (layers - 1));
  std::printf(
      "stack of %d layers, %d segments, %.1f N: %zu touching pairs (%d between layers), "
      "%d points, max penetration %.3g t, %ld Newton iterations\n",
      layers, r.segments, load, r.contact.pairs.size(), between_layers, r.contact.active,
      deepest / t, static_cast<long>(r.stats.newton_iterations));
}

// 2 x 2 cells per layer (a few seconds in Release).
TEST(ContactStack, TwentyFoldedLayersPressedTogetherStayApart) {
  check_stack(20, 2, 5.0);
}

// 3 x 3 cells per layer; 20 layers of them take about 15 s (Release only, scripts/test.sh),
// 5 layers run everywhere.
TEST(ContactStack, TwentyFinerFoldedLayersPressedTogetherStayApart) {
  check_stack(20, 3, 5.0);
}
TEST(ContactStack, FiveFinerFoldedLayersPressedTogetherStayApart) {
  check_stack(5, 3, 5.0);
}

}  // namespace contact_stack_test
}  // namespace finseg
