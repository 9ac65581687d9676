// The consistent cell Hessian bending (generators/plate_hessian.hpp, docs/stiffness.md,
// "Triangular cells") against its two defining properties, on irregular triangulations:
// for every quadratic deflection w = 1/2 x^T K x (each cell tilted as the plane through its
// side midpoints, the Crouzeix-Raviart interpolant, computed here independently) a cell away
// from the boundary stores exactly Kirchhoff's energy 1/2 A kappa^T C kappa, and the cells'
// energies together are stationary in the rotation of every cell away from the boundary (the
// patch test: a quadratic field is an equilibrium). Also: no zero-energy modes but the two
// uniform tilts.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <deque>

#include "generators/pattern_sheet.hpp"
#include "patterns/crease_pattern.hpp"
#include "patterns/segment_mesh.hpp"

namespace finseg {
namespace validation_plate_hessian_test {

constexpr double kE = 1e9, kT = 1e-3, kNu = 0.3;
constexpr double kD = kE * kT * kT * kT / (12 * (1 - kNu * kNu));

using Mat2 = Eigen::Matrix2d;

Mat2 sym2(double xx, double yy, double xy) {
  Mat2 K;
  K << xx, xy, xy, yy;
  return K;
}

// An n x n grid on [0, 1]^2 with its interior vertices moved by up to 15 % of a square
// (a fixed pseudo-random pattern), each square split by a diagonal or into a fan of four.
CreasePattern jittered_triangulation(int n, bool fan) {
  CreasePattern p;
  const double h = 1.0 / n;
  auto jitter = [](int i, int j, int k) { return 0.15 * std::sin(12.9898 * i + 78.233 * j + k); };
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const bool inner = i > 0 && i < n && j > 0 && j < n;
      p.vertices_flat_m.push_back(
          {h * (i + (inner ? jitter(i, j, 0) : 0)), h * (j + (inner ? jitter(i, j, 7) : 0))});
    }
  }
  auto v = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (fan) {
        const int c = static_cast<int>(p.vertices_flat_m.size());
        p.vertices_flat_m.push_back(
            0.25 * (p.vertices_flat_m[v(i, j)] + p.vertices_flat_m[v(i + 1, j)] +
                    p.vertices_flat_m[v(i + 1, j + 1)] + p.vertices_flat_m[v(i, j + 1)]));
        p.faces.push_back({v(i, j), v(i + 1, j), c});
        p.faces.push_back({v(i + 1, j), v(i + 1, j + 1), c});
        p.faces.push_back({v(i + 1, j + 1), v(i, j + 1), c});
        p.faces.push_back({v(i, j + 1), v(i, j), c});
      } else {
        p.faces.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
        p.faces.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
  }
  p.edges = edges_from_faces(p.faces);
  derive_edge_faces(p, "<jittered>");
  return p;
}

struct Built {
  Model model;
  SegmentMesh mesh;
  std::vector<int> depth;  // cells from the boundary: 0 on it
};

Built build(bool fan, int n) {
  const CreasePattern p = jittered_triangulation(n, fan);
  PatternSheetSpec spec;
  spec.thickness = kT;
  spec.youngs_modulus = kE;
  spec.poisson_ratio = kNu;
  spec.hessian_bending = true;
  Built b{build_pattern_model(p, spec), subdivide_pattern(p, 1), {}};
  const int cells = static_cast<int>(b.mesh.cells.size());
  std::vector<std::vector<int>> nb(cells);
  for (const CellLink& l : b.mesh.links) {
    nb[l.left].push_back(l.right);
    nb[l.right].push_back(l.left);
  }
  b.depth.assign(cells, -1);
  std::deque<int> queue;
  for (int c = 0; c < cells; ++c) {
    if (nb[c].size() < b.mesh.cells[c].size()) b.depth[c] = 0, queue.push_back(c);
  }
  while (!queue.empty()) {
    const int c = queue.front();
    queue.pop_front();
    for (int o : nb[c]) {
      if (b.depth[o] < 0) b.depth[o] = b.depth[c] + 1, queue.push_back(o);
    }
  }
  return b;
}

// Slope of the plane through w = 1/2 x^T K x at the cell's side midpoints (a triangle).
Vec2 cr_slope(const Built& b, int c, const Mat2& K) {
  const std::vector<int>& loop = b.mesh.cells[c];
  Mat3 A;
  Vec3 w;
  for (int i = 0; i < 3; ++i) {
    const Vec2 m = 0.5 * (b.mesh.flat_m[loop[i]] + b.mesh.flat_m[loop[(i + 1) % 3]]);
    A.row(i) << 1, m.x(), m.y();
    w[i] = 0.5 * m.dot(K * m);
  }
  return A.partialPivLu().solve(w).tail<2>();
}

// Rotation vector (w_y, -w_x) of a slope.
Vec2 rot(const Vec2& g) {
  return Vec2(g.y(), -g.x());
}

// Theta of every element for the cells' slopes g.
Eigen::VectorXd cell_thetas(const Built& b, const PlateCellDef& cell, const std::vector<Vec2>& g) {
  Eigen::VectorXd th(2 * cell.sides.size());
  for (std::size_t k = 0; k < cell.sides.size(); ++k) {
    const ElementDef& e = b.model.elements[cell.sides[k].element];
    th.segment<2>(2 * k) = rot(g[e.inner] - g[e.outer]);
  }
  return th;
}

class PlateHessian : public ::testing::TestWithParam<bool> {};

TEST_P(PlateHessian, QuadraticDeflectionIsExactAndInEquilibriumAwayFromTheBoundary) {
  const Built b = build(GetParam(), 8);
  Mat3 C;
  C << 1, kNu, 0, kNu, 1, 0, 0, 0, 2 * (1 - kNu);
  for (const Mat2& K : {sym2(1, 0, 0), sym2(0, 1, 0), sym2(0, 0, 1), sym2(0.7, 1.3, -0.4)}) {
    std::vector<Vec2> g(b.mesh.cells.size());
    for (std::size_t c = 0; c < g.size(); ++c) g[c] = cr_slope(b, static_cast<int>(c), K);
    const Vec3 kappa(K(0, 0), K(1, 1), K(0, 1));
    std::vector<Vec2> grad(g.size(), Vec2::Zero());  // dE / dg of each cell
    int exact = 0;
    for (const PlateCellDef& cell : b.model.plate_cells) {
      const Eigen::VectorXd th = cell_thetas(b, cell, g);
      const Eigen::VectorXd m = cell.Q * th;
      if (b.depth[cell.body] >= 2) {
        const double area = segment_area(b.model.bodies[cell.body]);
        const double kirchhoff = 0.5 * area * kD * kappa.dot(C * kappa);
        EXPECT_NEAR(0.5 * th.dot(m), kirchhoff, 1e-9 * kirchhoff) << "cell " << cell.body;
        ++exact;
      }
      for (std::size_t k = 0; k < cell.sides.size(); ++k) {
        const ElementDef& e = b.model.elements[cell.sides[k].element];
        const Vec2 dg = -rot(m.segment<2>(2 * k));  // R^T m: d(Theta . m) / d(g_inner)
        grad[e.inner] += dg;
        grad[e.outer] -= dg;
      }
    }
    EXPECT_GT(exact, 10);
    // Scale: a cell's moment D |K| times its size.
    const double scale = kD * K.norm() * std::sqrt(segment_area(b.model.bodies[0]));
    int inner = 0;
    for (std::size_t c = 0; c < g.size(); ++c) {
      if (b.depth[c] < 4) continue;
      EXPECT_LT(grad[c].norm(), 1e-9 * scale) << "cell " << c;
      ++inner;
    }
    EXPECT_GT(inner, 3);
  }
}

TEST_P(PlateHessian, OnlyUniformTiltsAreFreeOfEnergy) {
  const Built b = build(GetParam(), 5);
  const int n = static_cast<int>(b.mesh.cells.size());
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(2 * n, 2 * n);  // energy in the cells' slopes
  for (const PlateCellDef& cell : b.model.plate_cells) {
    const int s = static_cast<int>(cell.sides.size());
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(2 * s, 2 * n);  // Theta = T g
    Mat2 R;
    R << 0, 1, -1, 0;
    for (int k = 0; k < s; ++k) {
      const ElementDef& e = b.model.elements[cell.sides[k].element];
      T.block<2, 2>(2 * k, 2 * e.inner) += R;
      T.block<2, 2>(2 * k, 2 * e.outer) -= R;
    }
    H += T.transpose() * cell.Q * T;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(H);
  const Eigen::VectorXd l = eig.eigenvalues();
  EXPECT_LT(std::abs(l[0]), 1e-10 * l[2 * n - 1]);
  EXPECT_LT(std::abs(l[1]), 1e-10 * l[2 * n - 1]);
  EXPECT_GT(l[2], 1e-6 * l[2 * n - 1]) << "a zero-energy mode besides the uniform tilts";
}

INSTANTIATE_TEST_SUITE_P(Triangulations, PlateHessian, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Fans" : "Diagonals"; });

}  // namespace validation_plate_hessian_test
}  // namespace finseg
