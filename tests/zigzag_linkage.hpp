// The zigzag strip with rigid panels against a closed-form linkage (tests/test_zigzag_pull.cpp
// for the strip generator, tests/test_zigzag_fold_path.cpp for the pattern path).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "elements/crease_law.hpp"
#include "elements/drive_gauge.hpp"
#include "generators/zigzag.hpp"
#include "solvers/solver.hpp"

namespace finseg::test {

// Rigid panels of length a joined by linear creases (stiffness k, resting in the folded state
// at panel angle theta): the two links between the clamped crease 1 and the pulled crease 3
// are an isosceles triangle, so every fold angle is a closed-form function of the pulled
// crease's height z. Energy of the five creases, J.
inline double linkage_energy(double z, double a, double theta, double k) {
  const double D = 2 * a * std::cos(theta);
  const double d = std::hypot(D, z);
  const double gamma = std::atan2(z, D), beta = std::acos(d / (2 * a));
  const double a1 = -(gamma - beta - theta), a2 = -2 * beta, a3 = 2 * (gamma + beta);
  const double d1 = a1 - 2 * theta, d2 = a2 + 2 * theta, d3 = a3 - 2 * theta;
  return k * (d1 * d1 + d2 * d2) + 0.5 * k * d3 * d3;  // creases 1, 2 twice by symmetry
}

// The default strip without contact and gravity, panels 10^4 times stiffer than paper, creases
// linear (2e-3 N m/rad) built by `build`: the gauge force is the linkage's dE/dz within 0.5 %
// once the crease has risen 5 mm.
inline void expect_rigid_panel_linkage(Model (*build)(const ZigzagSpec&)) {
  ZigzagSpec spec;
  spec.contact = false;
  spec.gravity = false;
  const double k = 2e-3, a = spec.length / spec.panels;
  spec.crease_laws.clear();
  for (int c = 0; c < 5; ++c) {
    spec.crease_laws.push_back(std::make_shared<LinearCreaseLaw>(k, zigzag_fold_angle(spec, c)));
  }
  const double EI = spec.youngs_modulus * spec.width * std::pow(spec.thickness, 3) / 12;
  spec.overrides.bending_rigidity = 1e4 * EI;
  const Model m = build(spec);
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

}  // namespace finseg::test
