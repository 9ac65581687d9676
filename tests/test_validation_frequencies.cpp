// Natural frequencies of the cantilever strip against Euler-Bernoulli beam theory:
// f_n = (beta_n L)^2 / (2 pi L^2) sqrt(E I / (rho A)), 1 + cos(beta L) cosh(beta L) = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "elastica_reference.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace validation_frequencies_test {

TEST(CantileverEigenvalues, RootsMatchClassicalValues) {
  EXPECT_NEAR(reference::cantilever_beta_l(1), 1.87510, 5e-6);
  EXPECT_NEAR(reference::cantilever_beta_l(2), 4.69409, 5e-6);
  EXPECT_NEAR(reference::cantilever_beta_l(3), 7.85476, 5e-6);
}

TEST(CantileverFrequencies, FirstTwoWithinOnePercentAt64Segments) {
  const CantileverSpec s = validation::slender_strip(64);
  const Model model = build_cantilever_model(s);
  const std::vector<double> hz = natural_frequencies(model, initial_state(model), 2);
  ASSERT_EQ(hz.size(), 2u);
  const double rho_a = s.density * s.width * s.thickness;
  for (int n = 1; n <= 2; ++n) {
    const double f = reference::cantilever_omega(n, s.length, bending_rigidity(s), rho_a) /
                     (2 * std::numbers::pi);
    std::printf("mode %d: %.6f Hz, beam theory %.6f Hz\n", n, hz[n - 1], f);
    EXPECT_NEAR(hz[n - 1] / f, 1.0, 1e-2) << "mode " << n;
  }
}

}  // namespace validation_frequencies_test
}  // namespace finseg
