// Quasi-static pull of the zigzag: equilibrium and the rigid-panel closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "elements/assemble.hpp"
#include "elements/crease_law.hpp"
#include "generators/zigzag.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace {

Vec3 total_weight(const Model& m) {
  Vec3 w = Vec3::Zero();
  for (const BodyDef& b : m.bodies) w += b.mass * m.gravity_W;
  return w;
}

// Force the clamps exert on the structure: the fixed bodies are held in equilibrium.
Vec3 clamp_reaction(const Model& m, const BodyForces& f) {
  Vec3 r = Vec3::Zero();
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    if (m.bodies[i].fixed) r -= f.f_W[i];
  }
  return r;
}

TEST(ZigzagPull, GaugeReactionsAndWeightBalance) {
  ZigzagSpec spec;
  spec.contact = false;
  const Model m = build_zigzag_model(spec);
  State st = initial_state(m);
  SolverSettings set;
  int checked = 0;
  const SolverStats stats = run_solver(m, st, set, [&](const State& s, const BodyForces& f) {
    const Vec3 gauge = drive_force(m, s, 0);
    const Vec3 sum = gauge + clamp_reaction(m, f) + total_weight(m);
    EXPECT_LE(sum.norm(), 1e-3 * gauge.norm()) << "at drive " << s.drive_s[0] << " m";
    ++checked;
  });
  ASSERT_EQ(stats.status, "ok") << stats.message;
  EXPECT_GT(checked, 50);
}

// Rigid panels joined by linear creases (stiffness k, resting in the folded state): the
// two links between the clamped crease 1 and the pulled crease 3 are an isosceles triangle,
// so every fold angle is a closed-form function of the pulled crease's height z.
double linkage_energy(double z, double a, double theta, double k) {
  const double D = 2 * a * std::cos(theta);
  const double d = std::hypot(D, z);
  const double gamma = std::atan2(z, D), beta = std::acos(d / (2 * a));
  const double a1 = -(gamma - beta - theta), a2 = -2 * beta, a3 = 2 * (gamma + beta);
  const double d1 = a1 - 2 * theta, d2 = a2 + 2 * theta, d3 = a3 - 2 * theta;
  return k * (d1 * d1 + d2 * d2) + 0.5 * k * d3 * d3;  // creases 1, 2 twice by symmetry
}

TEST(ZigzagPull, RigidPanelLimitMatchesClosedForm) {
  ZigzagSpec spec;
  spec.contact = false;
  spec.gravity = false;
  const double k = 2e-3, a = spec.length / spec.panels;
  spec.crease_laws.clear();
  for (int c = 0; c < 5; ++c) {
    spec.crease_laws.push_back(std::make_shared<LinearCreaseLaw>(k, zigzag_fold_angle(spec, c)));
  }
  const double EI = spec.youngs_modulus * spec.width * std::pow(spec.thickness, 3) / 12;
  spec.overrides.bending_rigidity = 1e4 * EI;  // panels 10^4 times stiffer than paper
  const Model m = build_zigzag_model(spec);
  State st = initial_state(m);
  SolverSettings set;
  const Vec3 start = m.drives[0].start_W;
  int checked = 0;
  const SolverStats stats = run_solver(m, st, set, [&](const State& s, const BodyForces&) {
    const DriveDef& d = m.drives[0];
    const double z = (s.p_W[d.body] + s.R_WB[d.body] * d.point_B - start).z();
    if (z < 5e-3) return;
    const double h = 1e-6;
    const double F_ref = (linkage_energy(z + h, a, spec.fold_angle, k) -
                          linkage_energy(z - h, a, spec.fold_angle, k)) /
                         (2 * h);
    const double F = drive_force(m, s, 0).z();
    EXPECT_NEAR(F / F_ref, 1.0, 5e-3) << "at z = " << z << " m";
    ++checked;
  });
  ASSERT_EQ(stats.status, "ok") << stats.message;
  EXPECT_GT(checked, 50);
}

}  // namespace
}  // namespace finseg
