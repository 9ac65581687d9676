// A strip cut into rows across (a plate, Poisson ratio 0) bends as the beam; the one-row strip's
// twist and in-plane loads match beam theory in the small-load limit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "elastica_reference.hpp"
#include "generators/sheet.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace validation_width_twist_test {

constexpr double kShearCorrection = 5.0 / 6.0;  // rectangular section

// Four rows across are a plate (the pattern path's joints and cell corrections); with nu = 0
// and free long sides it bends as the beam: the elastica under a large tip load, and the
// Euler-Bernoulli cantilever's first two frequencies (beta L = 1.8751041, 4.6940911), both
// converging at second order (the hinges on the cells' sides: the trapezoid rule,
// docs/stiffness.md). Until 2026-12-03 a strip cut into rows was the one-row strip's joints
// repeated, and this test compared it with one row to 1e-6.
TEST(WidthDiscretisation, FourRowsBendAsTheBeamAtSecondOrder) {
  const reference::ElasticaTip ref = reference::elastica_tip_load(2);
  double tip_error[2], f_error[2][2];
  for (int k = 0; k < 2; ++k) {
    CantileverSpec four = validation::slender_strip(16 << k);
    four.poisson_ratio = 0;
    four.segments_across = 4;
    four.tip_force = Vec3(0, 0, -2 * bending_rigidity(four) / (four.length * four.length));
    const Vec3 d = validation::static_tip_displacement(four);
    tip_error[k] = -d.z() / four.length - ref.vertical;
    std::printf("%d segments: tip / L (%.6f, %.6f), elastica (%.6f, %.6f)\n", four.segments,
                -d.x() / four.length, -d.z() / four.length, ref.horizontal, ref.vertical);
    four.tip_force = Vec3::Zero();
    const Model m = build_cantilever_model(four);
    const std::vector<double> f = natural_frequencies(m, initial_state(m), 2);
    const double rho_A = four.density * four.width * four.thickness;
    const double scale = std::sqrt(bending_rigidity(four) / rho_A) /
                         (2 * std::numbers::pi * four.length * four.length);
    const double beta_L[2] = {1.8751041, 4.6940911};
    for (int n = 0; n < 2; ++n) {
      const double beam = beta_L[n] * beta_L[n] * scale;
      f_error[k][n] = f[n] / beam - 1;
      std::printf("  mode %d: %.6f Hz, Euler-Bernoulli %.6f Hz\n", n + 1, f[n], beam);
    }
  }
  EXPECT_LT(std::abs(tip_error[0]), 5e-3 * ref.vertical);
  EXPECT_GT(std::abs(tip_error[0] / tip_error[1]), 3.0);  // 4 at second order
  for (int n = 0; n < 2; ++n) {
    SCOPED_TRACE(n + 1);
    EXPECT_LT(std::abs(f_error[0][n]), 1e-2);
    EXPECT_GT(std::abs(f_error[0][n] / f_error[1][n]), 3.0);
  }
}

// Slope of the tip body about the world x axis (twist angle), rad.
double tip_twist(const Model& model, const State& state) {
  const int b = model.probes.front().body;
  const Mat3& R = state.R_WB[b];
  return std::atan2(R(2, 1), R(1, 1));
}

// The strip of `finseg gen cantilever --segments-across R` (nu = 0, 32 segments, end torque for
// 1 mrad) twists at Saint-Venant's rate T / (G W t^3 / 3) away from its ends (between 0.3 L and
// 0.7 L, 1.5 W and more from either end), for 2 to 16 rows: the 27 % (2 rows) and
// 9.2 % (4 rows) of the rows of beam joints are gone. The tip's twist is less by the clamp's
// restraint of the section's warping (docs/stiffness.md, "Sheets cut into rows").
TEST(WidthDiscretisation, RowsTwistAtSaintVenantsRate) {
  for (int rows : {2, 4, 8, 16}) {
    SCOPED_TRACE(rows);
    CantileverSpec s = validation::slender_strip(32);
    s.poisson_ratio = 0;
    s.segments_across = rows;
    const double GJ = s.youngs_modulus / 2 * s.width * std::pow(s.thickness, 3) / 3;
    const double T = 1e-3 * GJ / s.length;
    s.tip_moment = Vec3(T, 0, 0);
    const Model model = build_cantilever_model(s);
    const State state = validation::solve_static(model);
    // Twist of the body on the centre line at x (about the world x axis) and that body's x.
    auto twist = [&](double x) {
      const int b = locate_material_point(model, x, 0.5 * s.width).body;
      const Mat3& R = state.R_WB[b];
      return std::pair{std::atan2(R(2, 1), R(1, 1)), model.bodies[b].centroid_M->x()};
    };
    const auto [phi_a, x_a] = twist(0.3 * s.length);
    const auto [phi_b, x_b] = twist(0.7 * s.length);
    EXPECT_NEAR((phi_b - phi_a) / (x_b - x_a) / (T / GJ), 1.0, 1e-3);
  }
}

TEST(SmallLoadBeamTheory, EndTorqueTwistsByTLOverGJ) {
  CantileverSpec s = validation::slender_strip(16);
  const double G = s.youngs_modulus / (2 * (1 + s.poisson_ratio));
  const double GJ = G * s.width * std::pow(s.thickness, 3) / 3;  // thin strip, St Venant
  const double T = 1e-3 * GJ / s.length;                         // 1 mrad at the tip
  s.tip_moment = Vec3(T, 0, 0);
  const Model model = build_cantilever_model(s);
  const State state = validation::solve_static(model);
  const double phi = tip_twist(model, state);
  std::printf("twist: %.6e rad, T L / GJ = %.6e rad\n", phi, T * s.length / GJ);
  EXPECT_NEAR(phi / (T * s.length / GJ), 1.0, 1e-3);
}

TEST(SmallLoadBeamTheory, InPlaneTipLoadBendsAndShears) {
  CantileverSpec s = validation::slender_strip(32);
  const double E = s.youngs_modulus, G = E / (2 * (1 + s.poisson_ratio));
  const double A = s.width * s.thickness, Iz = s.thickness * std::pow(s.width, 3) / 12;
  const double bending = std::pow(s.length, 3) / (3 * E * Iz);
  const double shear = s.length / (kShearCorrection * G * A);
  const double F = 1e-4 * s.length / bending;  // deflection 1e-4 L
  s.tip_force = Vec3(0, F, 0);
  const double d = validation::static_tip_displacement(s).y();
  std::printf("in-plane: %.6e m, beam %.6e m (shear part %.2f %%)\n", d, F * (bending + shear),
              100 * shear / (bending + shear));
  // Midpoint-rule error of the bending part: -1 / (4 n^2) = -2.4e-4 at 32 segments.
  EXPECT_NEAR(d / (F * (bending + shear)), 1.0, 1e-3);
  // Without the shear term the 3 % difference would show.
  EXPECT_GT(std::abs(d / (F * bending) - 1), 0.02);
}

TEST(SmallLoadBeamTheory, AxialTipLoadStretchesByFLOverEA) {
  CantileverSpec s = validation::slender_strip(16);
  const double EA = s.youngs_modulus * s.width * s.thickness;
  const double F = 1e-6 * EA;  // strain 1e-6
  s.tip_force = Vec3(F, 0, 0);
  const double d = validation::static_tip_displacement(s).x();
  EXPECT_NEAR(d / (F * s.length / EA), 1.0, 1e-4);
}

}  // namespace validation_width_twist_test
}  // namespace finseg
