// A one-row strip through the pattern path, clamped at one end and loaded by a small tip force,
// against the beam's F L^3 / (3 EI) (docs/stiffness.md, "Hinges on cell sides"). The pattern
// path's cells are its rigid bodies and its hinges sit on the cells' sides, each standing for
// the sheet between two centroids (the clamp's for the free cell's half): with nu = 0 the tip
// moves by the sum of (moment x lever x compliance) over the sides,
//   F h^3 / EI [N^2 / 2 + sum_{m=2}^{N-1} m^2 + 2/3] = F L^3 / (3 EI) (1 + 1/(2 N^2) - 1/N^3),
// the trapezoid rule of the curvature integral (the last side stiffened by half by the free
// end cell's correction, which charges the cell's whole length to its one side). The strip
// generator's hinges sit at the cell centres: the midpoint rule, 1 - 1/(4 N^2)
// (docs/crease-data.md), half the error and of the other sign. With nu = 0.3 the cells'
// corrections couple neighbouring sides; their curvature fit must weigh each side by the
// cell's share of it, or the clamp cell's fit leaves a first-order error (tip error ratios
// 3.3 / 3.0 / 2.7 from 32 to 256 cells, falling towards 2).
#include <gtest/gtest.h>

#include <cmath>

#include "generators/pattern_sheet.hpp"
#include "patterns/grid_pattern.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace validation_pattern_cantilever_test {

constexpr double kL = 0.1, kW = 0.02, kT = 1e-4, kE = 3e9, kKappa = 5.0 / 6.0;

// Tip deflection of a one-row strip of n free cells of length L / n, clamped by one more fixed
// cell, under the transverse tip force `force` (N), over the beam's F L^3 / (3 EI) less the
// shear's F (L - h/2) / (kappa G W t) (the joints' out-of-plane shear springs in series).
double deflection_over_beam(int n, double nu) {
  const double h = kL / n, EI = kE * kW * kT * kT * kT / 12;  // D (1 - nu^2) W: free edges
  const double force = 1e-4 * 3 * EI / (kL * kL);             // deflection 1e-4 L: linear
  PatternSheetSpec spec;
  spec.thickness = kT;
  spec.youngs_modulus = kE;
  spec.poisson_ratio = nu;
  spec.density = 800;
  spec.fixed_faces = {0};
  CreasePattern p = grid_crease_pattern(n + 1, 1, h, kW);
  derive_edge_faces(p, "<strip>");
  Model m = build_pattern_model(p, spec);
  const int tip = n;  // one cell per face
  State s = initial_state(m);
  const Vec3 tip_W0((n + 1) * h, 0.5 * kW, 0);
  const Vec3 tip_B = s.R_WB[tip].transpose() * (tip_W0 - s.p_W[tip]);
  LoadDef load;
  load.body = tip;
  load.point_B = tip_B;
  load.force = Vec3(0, 0, force);
  m.loads.push_back(load);
  SolverSettings set;
  set.kind = SolverKind::Static;
  const SolverStats stats = run_solver(m, s, set, nullptr);
  EXPECT_EQ(stats.status, "ok") << stats.message;
  const double x = (s.p_W[tip] + s.R_WB[tip] * tip_B - tip_W0).z();
  const double G = kE / (2 * (1 + nu));
  const double shear = force * (kL - 0.5 * h) / (kKappa * G * kW * kT);
  return (x - shear) / (force * kL * kL * kL / (3 * EI));
}

TEST(PatternCantilever, WithoutPoissonTheTipMovesByTheTrapezoidRule) {
  for (int n : {2, 4, 8, 16, 32}) {
    SCOPED_TRACE(n);
    const double N = n;
    // The rotations (1e-4) leave 1e-8 of geometric nonlinearity.
    EXPECT_NEAR(deflection_over_beam(n, 0.0), 1 + 1 / (2 * N * N) - 1 / (N * N * N), 5e-8);
  }
}

TEST(PatternCantilever, WithPoissonTheTipConvergesAtSecondOrder) {
  double previous = 0;
  for (int n : {32, 64, 128, 256}) {
    SCOPED_TRACE(n);
    const double error = deflection_over_beam(n, 0.3) - 1;
    EXPECT_GT(error, 0);                  // the soft side, as the trapezoid rule
    EXPECT_LT(error, 1 / (2.0 * n * n));  // within the trapezoid rule's error
    if (previous > 0) {
      EXPECT_GT(previous / error, 3.7);  // 4 at second order, 2 at first
    }
    previous = error;
  }
}

}  // namespace validation_pattern_cantilever_test
}  // namespace finseg
