// Plates with free edges, where Poisson coupling and the twisting rigidity show (cell curvature
// correction, docs/stiffness.md): a strip clamped at one end, loaded at the other by a pure
// bending moment (Kirchhoff: M = D (1 - nu^2) k_xx W, anticlastic k_yy = -nu k_xx) or a
// torque (Kirchhoff / Saint-Venant thin strip: T = G W t^3 / 3 twist rate), with 1..16 cells
// across, curvatures measured far from the clamp.
#include <gtest/gtest.h>

#include <cmath>

#include "core/so3.hpp"
#include "generators/pattern_sheet.hpp"
#include "patterns/grid_pattern.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace validation_plate_free_test {

constexpr double kW = 0.02, kT = 1e-4, kE = 3e9, kNu = 0.3;

struct StripResult {
  double k_xx = 0, k_yy = 0, twist = 0;  // 1/m, in the middle of the strip
  std::string status;
};

// A strip 12 W long of square cells (W / rows), column 0 clamped, end moment `m_W` (N m,
// world) shared by the last column.
StripResult strip(int rows, const Vec3& m_W, double nu) {
  const int kAlong = 12 * rows;
  const double h = kW / rows;
  PatternSheetSpec spec;
  spec.thickness = kT;
  spec.youngs_modulus = kE;
  spec.poisson_ratio = nu;
  spec.density = 800;
  for (int r = 0; r < rows; ++r) spec.fixed_faces.push_back(r * kAlong);
  CreasePattern p = grid_crease_pattern(kAlong, rows, h, h);
  derive_edge_faces(p, "<strip>");
  Model m = build_pattern_model(p, spec);
  for (int r = 0; r < rows; ++r) {
    LoadDef l;
    l.body = r * kAlong + kAlong - 1;  // one cell per face, faces row by row
    l.moment = m_W / rows;
    m.loads.push_back(l);
  }
  State s = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  StripResult res;
  res.status = run_solver(m, s, set, nullptr).status;
  // Rotation vectors (small): phi = (w_y, -w_x, .); k_xx = -d phi_y / dx, k_yy = d phi_x / dy,
  // twist = d phi_x / dx. Columns a, b a width apart around the middle, 5.5 widths from the
  // clamp and from the end.
  const int a = kAlong / 2 - rows / 2, b = a + rows;
  for (int r = 0; r < rows; ++r) {
    const Vec3 pa = so3_log<double>(s.R_WB[r * kAlong + a]),
               pb = so3_log<double>(s.R_WB[r * kAlong + b]);
    res.k_xx += -(pb.y() - pa.y()) / ((b - a) * h) / rows;
    res.twist += (pb.x() - pa.x()) / ((b - a) * h) / rows;
  }
  if (rows > 1) {
    const int c = kAlong / 2;
    const Vec3 p0 = so3_log<double>(s.R_WB[c]),
               p1 = so3_log<double>(s.R_WB[(rows - 1) * kAlong + c]);
    res.k_yy = (p1.x() - p0.x()) / ((rows - 1) * h);
  }
  return res;
}

TEST(PlateFreeEdges, PureBendingGivesTheBeamCurvatureAndAnticlasticCurvature) {
  const double D = kE * kT * kT * kT / (12 * (1 - kNu * kNu));
  // Small: W^2 k_xx / t = 0.008, far below the Searle parameter where the anticlastic
  // curvature of a large deflection flattens (measured at 1e-5 N m: k_yy = -0.17 k_xx).
  const double M = 1e-8;  // N m
  for (int rows : {2, 4, 8}) {
    const StripResult r = strip(rows, Vec3(0, -M, 0), kNu);
    ASSERT_EQ(r.status, "ok") << rows;
    const double k_beam = M / (D * (1 - kNu * kNu) * kW);  // = 12 M / (E t^3 W)
    EXPECT_NEAR(r.k_xx / k_beam, 1, 0.01) << rows << " rows";
    EXPECT_NEAR(r.k_yy / r.k_xx, -kNu, 0.01 * kNu) << rows << " rows";
  }
}

TEST(PlateFreeEdges, TorsionOfAStripMatchesSaintVenantFromFourRows) {
  const double G = kE / (2 * (1 + kNu));
  const double T = 1e-9;                        // N m: twist rate 1.3e-4 rad/m, linear
  const double GJ = G * kW * kT * kT * kT / 3;  // thin strip: W / t = 200
  for (int rows : {2, 4, 8, 16}) {
    const StripResult r = strip(rows, Vec3(T, 0, 0), kNu);
    ASSERT_EQ(r.status, "ok") << rows;
    const double error = r.twist / (T / GJ) - 1;
    ::testing::Test::RecordProperty("rows_" + std::to_string(rows), std::to_string(error));
    if (rows >= 4) {
      EXPECT_NEAR(error, 0, 0.01) << rows << " rows";
    }
  }
}

}  // namespace validation_plate_free_test
}  // namespace finseg
