// A pressurised straight tube against membrane theory (issue 13 item 6). A rectangle rolled
// into a tube of N flat facets (closed by a seam), its ends closed by fixed end plates,
// prescribed pressure p, static.
//
// Set-up. The end plates are fixed world polygons: they take the pressure on the ends, so
// the tube carries no axial stress (an open-ended tube, sigma_x = 0). Rigid motion is held
// by clamping the first and the last row of cells; the measuring station is the middle of
// a tube 4 diameters long, where the clamps' bending boundary layer (decay length
// sqrt(R t) / (3 (1 - nu^2))^(1/4) = 7.6 mm here) has died out: a long tube. nu = 0: the
// joints' membrane springs have no Poisson coupling (docs/stiffness.md), and with nu = 0
// every end condition gives the same closed form.
//
// Closed form of the N-gon (derived by hand for this test): facet width a, s = sin(pi / N),
// c = cos(pi / N), phi = 2 pi / N. By symmetry every facet (one cell across) moves out along
// its normal by delta and turns by psi about its own axis line (the crease elements carry
// their frame on one side, so nothing forbids the turn). At a corner the right facet's end
// moves (delta + psi a/2) n_R, the left's (delta - psi a/2) n_L: in the left facet's side
// frame (x across, z normal) the gap is (A sin phi, 0, A cos phi - B), A = delta + psi a/2,
// B = delta - psi a/2, against the stretch spring E t L / a and the out-of-plane shear spring
// kappa G t L / a (docs/stiffness.md, h = a); no relative rotation. Minimising the energy
// less the pressure's work N p a L delta over A and B:
//
//     delta = p rho^2 / (E t) + p a^2 / (4 kappa G t),   rho = a c / (2 s) the apothem:
//
// membrane theory for the polygon (hoop force p rho, every facet stretched by p rho / (E t))
// plus the corner joints' transverse shear. With R = a / (2 s) the corner radius,
// delta / (p R^2 / (E t)) = c^2 + E / (kappa G) s^2 = 1 + (E / (kappa G) - 1) (pi / N)^2 + ...:
// it tends to the round tube's membrane growth p R^2 / (E t) (hoop stress p R / t) as N^-2,
// 1.4 (pi / N)^2 with nu = 0: 1.35 % at N = 32, below 1 % from N = 40.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "elements/chamber_gas.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "patterns/pattern_checks.hpp"
#include "patterns/tube_pattern.hpp"
#include "pressure_test_util.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace gas_tube_test {

constexpr double kR = 0.1, kT = 1e-3, kE = 1e9, kP = 1e3;  // m, m, Pa, Pa
constexpr double kLength = 0.8;                            // 4 diameters, m
constexpr int kRows = 16;
constexpr double kKappaG = 5.0 / 6.0 * kE / 2;  // nu = 0, Pa

struct TubeResult {
  double delta = 0;   // mean radial growth of the middle row's facet centres, m
  double spread = 0;  // largest departure of one facet from the mean, m
  double closed_form = 0;
};

// The tube of n facets under kP, solved statically: closed by fixed end plates with both
// end rows clamped, or (capped) by caps of its own end corners with the first row clamped.
struct SolvedTube {
  Model model;
  State state;
};

SolvedTube solved_tube(int n, bool capped) {
  CreasePattern p = tube_crease_pattern(n, kRows, kR, kLength);
  validate_pattern(p, "<tube>");
  PatternSheetSpec spec;
  spec.thickness = kT;
  spec.youngs_modulus = kE;
  spec.poisson_ratio = 0;
  spec.subdivisions = 1;
  // The creases as stiff as the plate (they do not move: the facets do not turn).
  const double D = kE * kT * kT * kT / 12;
  const double a = 2 * kR * std::sin(kPi / n);
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(D / a, 2 * kPi / n);
  for (int j = 0; j < n; ++j) {
    spec.fixed_faces.push_back(j);
    if (!capped) spec.fixed_faces.push_back((kRows - 1) * n + j);
  }
  Model m = build_pattern_model(p, spec, "<tube>");
  ChamberDef c = test::whole_model_chamber(m, "tube");
  c.prescribed.pressure = kP;
  if (capped) {
    c.cap_open_ends = true;
  } else {
    std::vector<Vec3> start, end;  // y = 0 seen from -y: corners clockwise in theta
    for (int j = 0; j < n; ++j) {
      const double th = 2 * kPi * j / n;
      end.emplace_back(kR * std::cos(th), kLength, -kR * std::sin(th));
      start.insert(start.begin(), Vec3(kR * std::cos(th), 0, -kR * std::sin(th)));
    }
    c.end_plates = {start, end};
  }
  m.chambers.push_back(c);
  validate(m);
  prepare_chambers(m);
  State s = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  const SolverStats st = run_solver(m, s, set, nullptr);
  EXPECT_EQ(st.status, "ok") << st.message;
  return {std::move(m), std::move(s)};
}

// The closed form of the header: the N-gon's radial growth, m.
double polygon_growth(int n) {
  const double sn = std::sin(kPi / n), cn = std::cos(kPi / n), a = 2 * kR * sn;
  const double rho = a * cn / (2 * sn);
  return kP * rho * rho / (kE * kT) + kP * a * a / (4 * kKappaG * kT);
}

TubeResult pressurised_tube(int n) {
  const SolvedTube t = solved_tube(n, false);
  const Model& m = t.model;
  const State& s = t.state;
  TubeResult r;
  std::vector<double> d;
  for (int j = 0; j < n; ++j) {
    const int b = (kRows / 2) * n + j;
    const auto radius = [](const Vec3& x) { return std::hypot(x.x(), x.z()); };
    d.push_back(radius(s.p_W[b]) - radius(m.bodies[b].p0_W));
    r.delta += d.back() / n;
  }
  for (double x : d) r.spread = std::max(r.spread, std::abs(x - r.delta));
  r.closed_form = polygon_growth(n);
  return r;
}

void check_tube(const std::vector<int>& facets) {
  const double membrane = kP * kR * kR / (kE * kT);
  double last = 1;
  for (int n : facets) {
    const TubeResult r = pressurised_tube(n);
    const double polygon_err = r.delta / r.closed_form - 1, round_err = r.delta / membrane - 1;
    EXPECT_LT(std::abs(polygon_err), 5e-4) << n;  // geometric nonlinearity: delta / R = 1e-4
    EXPECT_LT(r.spread, 1e-6 * r.delta) << n;
    EXPECT_LT(std::abs(round_err), 0.6 * last) << n;  // shrinks as N^-2
    if (n >= 48) {
      EXPECT_LT(std::abs(round_err), 0.01) << n;
    }
    last = std::abs(round_err);
    ::testing::Test::RecordProperty(fmt::format("N{}_polygon_rel_error", n),
                                    fmt::format("{:.3e}", polygon_err));
    ::testing::Test::RecordProperty(fmt::format("N{}_round_tube_rel_error", n),
                                    fmt::format("{:.3e}", round_err));
    std::printf(
        "N = %d: delta %.6e m, polygon closed form %.6e (%+.2e), p R^2/(E t) %.6e (%+.2e)\n", n,
        r.delta, r.closed_form, polygon_err, membrane, round_err);
  }
}

TEST(GasTube, PressurisedTubeGrowsAsMembraneTheorySays) {
  check_tube({8, 16, 32, 48, 64});
}

// Ends closed by caps of the tube's own end corners (ChamberDef::cap_open_ends) instead of
// fixed plates: the enclosed volume is the N-gon's area times the length (to round-off), and
// the caps' load p A goes into the wall, an axial stress p rho / (2 t) (rho the apothem; the
// closed-ended tube's p R / (2 t)): rows in the middle move apart by the strain
// p rho / (2 E t) (nu = 0), while the radial growth stays the open tube's.
TEST(GasTube, CappedTubeCarriesItsEndLoadAxially) {
  const int n = 16;
  const SolvedTube t = solved_tube(n, true);
  const double sn = std::sin(kPi / n), cn = std::cos(kPi / n), a = 2 * kR * sn;
  const double rho = a * cn / (2 * sn), area = n * a * rho / 2;
  EXPECT_NEAR(t.model.chambers[0].initial_volume / (area * kLength), 1, 1e-12);
  const auto row_y = [&](const auto& pos, int r) {
    double y = 0;
    for (int j = 0; j < n; ++j) y += pos(r * n + j).y() / n;
    return y;
  };
  const auto now = [&](int b) { return t.state.p_W[b]; };
  const auto then = [&](int b) { return t.model.bodies[b].p0_W; };
  const int r1 = kRows / 4, r2 = 3 * kRows / 4;
  const double strain = (row_y(now, r2) - row_y(now, r1)) / (row_y(then, r2) - row_y(then, r1)) - 1;
  EXPECT_NEAR(strain / (kP * rho / (2 * kE * kT)), 1, 1e-4);
  double delta = 0;
  for (int j = 0; j < n; ++j) {
    const auto radius = [](const Vec3& x) { return std::hypot(x.x(), x.z()); };
    const int b = (kRows / 2) * n + j;
    delta += (radius(now(b)) - radius(then(b))) / n;
  }
  EXPECT_NEAR(delta / polygon_growth(n), 1, 5e-4);
  std::printf(
      "capped N = %d: volume %.12e m^3 (A L %.12e), axial strain %+.3e of p rho/(2 E t), "
      "radial growth %+.3e of the closed form\n",
      n, t.model.chambers[0].initial_volume, area * kLength,
      strain / (kP * rho / (2 * kE * kT)) - 1, delta / polygon_growth(n) - 1);
}

// The sanitizer build runs this one instead (scripts/test.sh).
TEST(GasTube, PressurisedTubeSmall) {
  check_tube({8, 16});
}

}  // namespace gas_tube_test
}  // namespace finseg
