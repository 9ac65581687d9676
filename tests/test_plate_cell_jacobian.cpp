// The plate cells' curvature corrections (docs/stiffness.md, "Cell curvature correction"):
// their couples are the exact gradient of their energy (the relative rotations read through
// the inverse left Jacobian of SO(3)), and their Jacobian, with the turning of the side frames,
// matches central differences on a folded Miura sheet bent and twisted well beyond small
// rotations.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <memory>

#include "elements/assemble.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "jacobian_test_util.hpp"
#include "patterns/miura_pattern.hpp"
#include "solvers/dofs.hpp"

namespace finseg {
namespace plate_cell_jacobian_test {

Model miura_sheet(bool with_plate_cells, bool triangles = false) {
  MiuraSpec ms;
  ms.rows = 2;
  ms.columns = 2;
  ms.fold_angle = 0.6;
  PatternSheetSpec spec;
  spec.thickness = 1e-3;
  spec.youngs_modulus = 1e9;
  spec.poisson_ratio = 0.3;
  spec.density = 1000;
  spec.subdivisions = 3;
  spec.triangle_cells = triangles;  // the consistent cell Hessian (docs/stiffness.md)
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(1e-3, 0.0);
  spec.valley_law = spec.mountain_law;
  Model m = build_pattern_model(miura_crease_pattern(ms), spec);
  if (!with_plate_cells) m.plate_cells.clear();
  return m;
}

// Every segment turned by up to 0.15 rad and moved by up to 20 um: relative rotations of a
// few tenths of a radian across the cells' sides.
State bent(const Model& m) {
  State s = initial_state(m);
  Eigen::VectorXd dq(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) dq[i] = (i % 6 < 3 ? 2e-5 : 0.15) * std::sin(1.3 * i + 0.7);
  apply_pose_increment(m, s, dq);
  return s;
}

TEST(PlateCells, JacobianMatchesCentralDifferencesWhenBent) {
  const Model m = miura_sheet(true), bare = miura_sheet(false);
  ASSERT_FALSE(m.plate_cells.empty());
  const State s = bent(m);
  const Eigen::MatrixXd J = test::pose_jacobian(m, s) - test::pose_jacobian(bare, s);
  const Eigen::MatrixXd fd =
      test::fd_pose_jacobian(m, s, 1e-7) - test::fd_pose_jacobian(bare, s, 1e-7);
  const double scale = J.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0);
  EXPECT_LT((J - fd).cwiseAbs().maxCoeff(), 1e-6 * scale) << "largest entry " << scale;
}

// The couples are minus the gradient of the energy: the energy's change along a small
// rotation of every segment equals minus the couples' work, to second order.
TEST(PlateCells, CouplesAreTheEnergysGradient) {
  const Model m = miura_sheet(true), bare = miura_sheet(false);
  const State s = bent(m);
  Eigen::VectorXd dq(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) dq[i] = i % 6 < 3 ? 0.0 : std::cos(0.9 * i);
  const double h = 1e-6;
  auto energy = [&](const Model& model, double a) {
    State x = s;
    apply_pose_increment(model, x, a * dq);
    BodyForces f;
    compute_forces(model, x, f);
    return f.potential_energy;
  };
  auto power = [&](const Model& model) {
    BodyForces f;
    compute_forces(model, s, f);
    return generalized_forces(model, f).dot(dq);
  };
  const double dE = (energy(m, h) - energy(m, -h) - energy(bare, h) + energy(bare, -h)) / (2 * h);
  const double work = power(m) - power(bare);
  ASSERT_GT(std::abs(work), 0);
  EXPECT_NEAR(dE, -work, 1e-7 * std::abs(work));
}

// State::plate_correction_scale (the static solver's corrections-last stage, docs/solvers.md)
// multiplies the corrections' energy, couples and Jacobian, and leaves the consistent cell
// Hessian of triangles, which holds the whole bending, alone.
TEST(PlateCells, TheCorrectionScaleScalesCorrectionsOnly) {
  const auto energy_and_forces = [](const Model& m, const State& s) {
    BodyForces f;
    compute_forces(m, s, f);
    Eigen::VectorXd g = generalized_forces(m, f);
    g.conservativeResize(g.size() + 1);
    g[g.size() - 1] = f.potential_energy;
    return g;
  };
  const Model m = miura_sheet(true), bare = miura_sheet(false);
  ASSERT_TRUE(m.plate_cells.front().correction);
  const State s = bent(m);
  State part = s;
  part.plate_correction_scale = 0.4;
  const Eigen::VectorXd full = energy_and_forces(m, s) - energy_and_forces(bare, s);
  const Eigen::VectorXd scaled = energy_and_forces(m, part) - energy_and_forces(bare, part);
  ASSERT_GT(full.norm(), 0);
  EXPECT_LT((scaled - 0.4 * full).norm(), 1e-9 * full.norm());
  const Eigen::MatrixXd J = test::pose_jacobian(m, s) - test::pose_jacobian(bare, s);
  const Eigen::MatrixXd Jp = test::pose_jacobian(m, part) - test::pose_jacobian(bare, part);
  EXPECT_LT((Jp - 0.4 * J).cwiseAbs().maxCoeff(), 1e-9 * J.cwiseAbs().maxCoeff());

  const Model tri = miura_sheet(true, true);
  ASSERT_FALSE(tri.plate_cells.empty());
  ASSERT_FALSE(tri.plate_cells.front().correction);
  const State st = bent(tri);
  State off = st;
  off.plate_correction_scale = 0;
  EXPECT_EQ(energy_and_forces(tri, st), energy_and_forces(tri, off));
}

}  // namespace plate_cell_jacobian_test
}  // namespace finseg
