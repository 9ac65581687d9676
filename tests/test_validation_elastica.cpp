// Large-deflection cantilever under a vertical dead tip load against the elastica
// (elliptic integrals, tests/elastica_reference.hpp), and its order of convergence.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "elastica_reference.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace validation_elastica_test {

using reference::elastica_tip_load;
using validation::slender_strip;
using validation::static_tip_displacement;

struct TableRow {
  double alpha, horizontal, vertical;
};
// Bisshopp & Drucker (1945) / Mattiasson (1981), tip displacements / L.
constexpr TableRow kTable[] = {
    {1, 0.05643, 0.30172}, {2, 0.16064, 0.49346}, {5, 0.38763, 0.71379}, {10, 0.55500, 0.81061}};

TEST(ElasticaReference, MatchesClassicalTable) {
  for (const TableRow& row : kTable) {
    const reference::ElasticaTip tip = elastica_tip_load(row.alpha);
    // The table is rounded to 5 decimals.
    EXPECT_NEAR(tip.horizontal, row.horizontal, 6e-6) << "alpha " << row.alpha;
    EXPECT_NEAR(tip.vertical, row.vertical, 6e-6) << "alpha " << row.alpha;
  }
}

TEST(ElasticaReference, SmallLoadIsLinearBeam) {
  const double alpha = 1e-4;
  const reference::ElasticaTip tip = elastica_tip_load(alpha);
  EXPECT_NEAR(tip.vertical / (alpha / 3), 1.0, 1e-4);             // P L^3 / (3 EI)
  EXPECT_NEAR(tip.tip_angle / (alpha / 2), 1.0, 1e-4);            // P L^2 / (2 EI)
  EXPECT_NEAR(tip.horizontal / (alpha * alpha / 15), 1.0, 1e-3);  // int (w')^2 / 2
}

// Tip displacement of the model at load parameter alpha, / L: (horizontal, vertical).
// Memoised: the 64-segment solves are shared by the two tests below.
std::pair<double, double> model_tip(double alpha, int segments) {
  static std::map<std::pair<double, int>, std::pair<double, double>> cache;
  const auto key = std::make_pair(alpha, segments);
  if (const auto it = cache.find(key); it != cache.end()) return it->second;
  CantileverSpec s = slender_strip(segments);
  const double P = alpha * bending_rigidity(s) / (s.length * s.length);
  s.tip_force = Vec3(0, 0, -P);
  const Vec3 d = static_tip_displacement(s);
  return cache[key] = {-d.x() / s.length, -d.z() / s.length};
}

TEST(ElasticaCantilever, TipWithinHalfPercentAt64Segments) {
  for (const TableRow& row : kTable) {
    const reference::ElasticaTip ref = elastica_tip_load(row.alpha);
    const auto [h, v] = model_tip(row.alpha, 64);
    EXPECT_NEAR(h / ref.horizontal, 1.0, 5e-3) << "alpha " << row.alpha;
    EXPECT_NEAR(v / ref.vertical, 1.0, 5e-3) << "alpha " << row.alpha;
    std::printf("alpha %g: horizontal %.6f (elastica %.6f), vertical %.6f (elastica %.6f)\n",
                row.alpha, h, ref.horizontal, v, ref.vertical);
  }
}

TEST(ElasticaCantilever, ConvergesAtSecondOrder) {
  for (double alpha : {2.0, 10.0}) {
    const reference::ElasticaTip ref = elastica_tip_load(alpha);
    double err_h[3], err_v[3];
    const int n[3] = {16, 32, 64};
    for (int i = 0; i < 3; ++i) {
      const auto [h, v] = model_tip(alpha, n[i]);
      err_h[i] = std::abs(h - ref.horizontal);
      err_v[i] = std::abs(v - ref.vertical);
      std::printf("alpha %g, %d segments: error horizontal %.3e L, vertical %.3e L\n", alpha, n[i],
                  err_h[i], err_v[i]);
    }
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(std::log2(err_h[i] / err_h[i + 1]), 2.0, 0.2) << "alpha " << alpha << " h";
      EXPECT_NEAR(std::log2(err_v[i] / err_v[i + 1]), 2.0, 0.2) << "alpha " << alpha << " v";
    }
  }
}

}  // namespace validation_elastica_test
}  // namespace finseg
