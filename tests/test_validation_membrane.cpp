// In-plane (membrane) stiffness of sheets cut from patterns against plane-stress elasticity:
// the energy of every uniform strain on rectangular and triangulated segmentations
// (1/2 A e^T C e, C = E t / (1 - nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]]), and a
// free strip pulled along its length contracting across by -nu times its stretch with the
// stiffness E t W (docs/stiffness.md, "Cell membrane correction").
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "elements/assemble.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "generators/sheet.hpp"
#include "jacobian_test_util.hpp"
#include "patterns/crease_pattern.hpp"
#include "patterns/miura_pattern.hpp"
#include "patterns/stack_pattern.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace validation_membrane_test {

constexpr double kE = 1e9, kNu = 0.3, kT = 1e-3;

// Rectangles [x0, x1] x [0, w] side by side (flat F edges between them).
CreasePattern row_of_rectangles(const std::vector<double>& x, double w) {
  CreasePattern p;
  for (double xi : x) {
    p.vertices_flat_m.push_back({xi, 0});
    p.vertices_flat_m.push_back({xi, w});
  }
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const int a = static_cast<int>(2 * k);
    p.faces.push_back({a, a + 2, a + 3, a + 1});
  }
  p.edges = edges_from_faces(p.faces);
  derive_edge_faces(p, "<membrane>");
  return p;
}

// The unit square as four triangles around its centre.
CreasePattern square_fan() {
  CreasePattern p;
  p.vertices_flat_m = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  p.faces = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  p.edges = edges_from_faces(p.faces);
  derive_edge_faces(p, "<membrane>");
  return p;
}

PatternSheetSpec sheet(int n) {
  PatternSheetSpec s;
  s.thickness = kT;
  s.youngs_modulus = kE;
  s.poisson_ratio = kNu;
  s.density = 1000;
  s.subdivisions = n;
  return s;
}

// Energy of the sheet with every segment moved as the uniform strain e = (e_xx, e_yy, g_xy)
// moves its centroid (no rotation: the strain's rotation is zero).
double strained_energy(const Model& m, const Vec3& e) {
  State s = initial_state(m);
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    const Vec3 x = m.bodies[b].p0_W;
    s.p_W[b] = x + Vec3(e[0] * x.x() + 0.5 * e[2] * x.y(), 0.5 * e[2] * x.x() + e[1] * x.y(), 0);
  }
  BodyForces f;
  compute_forces(m, s, f);
  return f.potential_energy;
}

double plane_stress_energy(double area, const Vec3& e) {
  Mat3 C;
  C << 1, kNu, 0, kNu, 1, 0, 0, 0, 0.5 * (1 - kNu);
  return 0.5 * area * kE * kT / (1 - kNu * kNu) * e.dot(C * e);
}

TEST(MembraneCells, UniformStrainsStoreThePlaneStressEnergy) {
  const std::vector<Vec3> strains = {
      {1e-4, 0, 0}, {0, 1e-4, 0}, {0, 0, 1e-4}, {2e-4, -0.7e-4, 1.3e-4}};
  for (const auto& [name, p, n, area] :
       {std::tuple{"rectangles", row_of_rectangles({0, 0.3, 1.0}, 0.4), 4, 0.4},
        {"triangles", square_fan(), 3, 1.0}}) {
    const Model m = build_pattern_model(p, sheet(n));
    for (const Vec3& e : strains) {
      EXPECT_NEAR(strained_energy(m, e) / plane_stress_energy(area, e), 1, 1e-9)
          << name << " strain " << e.transpose();
    }
  }
}

// A strip 0.4 x 0.05 m clamped at x < 0 and pulled at its end by F spread over the last
// column's cells: in its middle, e_xx = F / (E t W) and e_yy = -nu e_xx (uniaxial stress).
TEST(MembraneCells, StripInTensionContractsByPoissonsRatio) {
  const double L = 0.4, W = 0.05, F = 50;  // e_xx = 1e-3
  PatternSheetSpec spec = sheet(1);
  spec.segment_size = W / 4;
  spec.fixed_faces = {0};
  Model m = build_pattern_model(row_of_rectangles({-0.02, 0, L}, W), spec);
  std::vector<int> end;
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    if (m.bodies[b].p0_W.x() > L - W / 4) end.push_back(static_cast<int>(b));
  }
  ASSERT_EQ(end.size(), 4u);
  for (int b : end) {
    LoadDef l;
    l.body = b;
    l.force = Vec3(F / 4, 0, 0);
    m.loads.push_back(l);
  }
  State s = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  const SolverStats st = run_solver(m, s, set, nullptr);
  ASSERT_EQ(st.status, "ok") << st.message;
  // Strains from cell centroids around the middle (cells h = W / 4 square): x from two
  // columns 5 cells apart, y from the outer rows of one column.
  const double h = W / 4;
  const auto near = [&](double x, double y) {
    int best = 0;
    for (std::size_t b = 0; b < m.bodies.size(); ++b) {
      if ((m.bodies[b].p0_W.head<2>() - Vec2(x, y)).norm() <
          (m.bodies[best].p0_W.head<2>() - Vec2(x, y)).norm()) {
        best = static_cast<int>(b);
      }
    }
    return best;
  };
  const int a = near(0.5 * L - 2.5 * h, 1.5 * h), b = near(0.5 * L + 2.5 * h, 1.5 * h);
  const int lo = near(0.5 * L + 0.5 * h, 0.5 * h), hi = near(0.5 * L + 0.5 * h, W - 0.5 * h);
  const double exx = (s.p_W[b] - s.p_W[a]).x() / (m.bodies[b].p0_W - m.bodies[a].p0_W).x() - 1;
  const double eyy = (s.p_W[hi] - s.p_W[lo]).y() / (m.bodies[hi].p0_W - m.bodies[lo].p0_W).y() - 1;
  const double expected = F / (kE * kT * W);
  EXPECT_NEAR(exx / expected, 1, 0.01);
  EXPECT_NEAR(eyy / exx, -kNu, 0.01 * kNu);
  ::testing::Test::RecordProperty("exx_over_closed_form", fmt::format("{:.6f}", exx / expected));
  ::testing::Test::RecordProperty("eyy_over_exx", fmt::format("{:.6f}", eyy / exx));
}

// The membrane cells' Jacobian, with the geometric terms of their turning frames and levers,
// against central differences of the forces: a folded Miura sheet, every segment moved and
// turned so that the membrane forces are large (strains of order 1e-2).
TEST(MembraneCells, JacobianMatchesCentralDifferencesWhenStrained) {
  MiuraSpec ms;
  ms.rows = 2;
  ms.columns = 2;
  ms.fold_angle = 0.6;
  PatternSheetSpec spec = sheet(2);
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(1e-3, 0.0);
  spec.valley_law = spec.mountain_law;
  const Model m = build_pattern_model(miura_crease_pattern(ms), spec);
  ASSERT_FALSE(m.membrane_cells.empty());
  State s = initial_state(m);
  Eigen::VectorXd dq(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) dq[i] = (i % 6 < 3 ? 2e-4 : 0.02) * std::sin(1.7 * i + 0.3);
  apply_pose_increment(m, s, dq);
  const Eigen::MatrixXd J = test::pose_jacobian(m, s), fd = test::fd_pose_jacobian(m, s, 1e-7);
  const double scale = J.cwiseAbs().maxCoeff();
  EXPECT_LT((J - fd).cwiseAbs().maxCoeff(), 1e-6 * scale) << "largest entry " << scale;
}

// Every cell's correction is positive semi-definite, so that joints plus corrections never
// lose convexity: on a folded stack whose fold strips are cells 50 times longer than wide
// next to square ones (each joint's energy shared between its cells by their part of the
// centroid-to-centroid strip), on a Miura sheet and on a fan of triangles.
TEST(MembraneCells, EveryCorrectionIsPositiveSemiDefinite) {
  MiuraSpec ms;
  ms.rows = 2;
  ms.columns = 3;
  PatternSheetSpec spec = sheet(3);
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(1e-3, 0.0);
  spec.valley_law = spec.mountain_law;
  for (const auto& [name, p] : {std::pair{"stack", folded_stack_pattern(3, 3, 5e-3, kT / 10)},
                                {"miura", miura_crease_pattern(ms)},
                                {"fan", square_fan()}}) {
    const Model m = build_pattern_model(p, spec);
    ASSERT_FALSE(m.membrane_cells.empty()) << name;
    for (const MembraneCellDef& c : m.membrane_cells) {
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(c.Q);
      EXPECT_GE(es.eigenvalues().minCoeff(), -1e-9 * es.eigenvalues().cwiseAbs().maxCoeff())
          << name << " cell " << c.body;
      EXPECT_GT(es.eigenvalues().maxCoeff(), 0) << name << " cell " << c.body;
    }
  }
}

}  // namespace validation_membrane_test
}  // namespace finseg
