// Cutting the strip across its width (Poisson ratio 0) leaves its bending answers
// unchanged; twist and in-plane loads match beam theory in the small-load limit.
#include <gtest/gtest.h>

#include <cmath>

#include "elastica_reference.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace validation_width_twist_test {

constexpr double kShearCorrection = 5.0 / 6.0;  // rectangular section

TEST(WidthDiscretisation, FourRowsBendLikeOne) {
  CantileverSpec one = validation::slender_strip(16);
  one.poisson_ratio = 0;
  one.tip_force = Vec3(0, 0, -2 * bending_rigidity(one) / (one.length * one.length));
  CantileverSpec four = one;
  four.segments_across = 4;
  const Vec3 d1 = validation::static_tip_displacement(one);
  const Vec3 d4 = validation::static_tip_displacement(four);
  const reference::ElasticaTip ref = reference::elastica_tip_load(2);
  std::printf("tip / L: 1 row (%.6f, %.6f), 4 rows (%.6f, %.6f), elastica (%.6f, %.6f)\n",
              -d1.x() / one.length, -d1.z() / one.length, -d4.x() / one.length,
              -d4.z() / one.length, ref.horizontal, ref.vertical);
  EXPECT_LT((d4 - d1).norm(), 1e-6 * one.length);
  EXPECT_NEAR(-d4.z() / one.length / ref.vertical, 1.0, 5e-3);

  one.tip_force = four.tip_force = Vec3::Zero();
  const Model m1 = build_cantilever_model(one), m4 = build_cantilever_model(four);
  const std::vector<double> f1 = natural_frequencies(m1, initial_state(m1), 2);
  const std::vector<double> f4 = natural_frequencies(m4, initial_state(m4), 2);
  for (int n = 0; n < 2; ++n) {
    std::printf("mode %d: 1 row %.6f Hz, 4 rows %.6f Hz\n", n + 1, f1[n], f4[n]);
    EXPECT_NEAR(f4[n] / f1[n], 1.0, 1e-6) << "mode " << n + 1;
  }
}

// Slope of the tip body about the world x axis (twist angle), rad.
double tip_twist(const Model& model, const State& state) {
  const int b = model.probes.front().body;
  const Mat3& R = state.R_WB[b];
  return std::atan2(R(2, 1), R(1, 1));
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
