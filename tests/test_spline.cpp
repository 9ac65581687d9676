// Cubic spline: exact reproduction of polynomials, interpolation, end conditions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/cubic_spline.hpp"

using finseg::CubicSpline;
using finseg::SplineEnds;
using finseg::SplineExtrapolation;

namespace spline_test {

// p(x) = 2 - 3x + 0.5x^2 + 0.7x^3 and its derivatives / antiderivative.
double p(double x) {
  return 2 - 3 * x + 0.5 * x * x + 0.7 * x * x * x;
}
double dp(double x) {
  return -3 + x + 2.1 * x * x;
}
double d2p(double x) {
  return 1 + 4.2 * x;
}
double ip(double x) {
  return 2 * x - 1.5 * x * x + x * x * x / 6 + 0.175 * x * x * x * x;
}

const std::vector<double> kKnots = {-1.3, -0.9, -0.1, 0.25, 0.3, 1.1, 2.0};

std::vector<double> values_of(double (*f)(double), const std::vector<double>& x) {
  std::vector<double> y;
  for (double xi : x) y.push_back(f(xi));
  return y;
}

TEST(Spline, NotAKnotReproducesCubicExactly) {
  const CubicSpline s(kKnots, values_of(p, kKnots), SplineEnds::NotAKnot,
                      SplineExtrapolation::Polynomial);
  for (double x = -1.3; x <= 2.0; x += 0.01) {
    EXPECT_NEAR(s.value(x), p(x), 1e-12) << x;
    EXPECT_NEAR(s.derivative(x), dp(x), 1e-11) << x;
    EXPECT_NEAR(s.second_derivative(x), d2p(x), 1e-10) << x;
    EXPECT_NEAR(s.integral(x), ip(x) - ip(-1.3), 1e-12) << x;
  }
  // Polynomial extrapolation continues the same cubic.
  EXPECT_NEAR(s.value(2.5), p(2.5), 1e-10);
  EXPECT_NEAR(s.value(-2.0), p(-2.0), 1e-10);
}

TEST(Spline, NotAKnotFourKnotsIsTheInterpolatingCubic) {
  const std::vector<double> x = {0.0, 0.3, 1.7, 2.0};
  const CubicSpline s(x, values_of(p, x), SplineEnds::NotAKnot);
  for (double t = 0; t <= 2.0; t += 0.05) EXPECT_NEAR(s.value(t), p(t), 1e-12);
}

TEST(Spline, ThreeKnotsNotAKnotIsTheParabola) {
  const std::vector<double> x = {0.0, 0.4, 1.5}, y = {1.0, 3.0, -2.0};
  const CubicSpline s(x, y, SplineEnds::NotAKnot);
  // Newton form of the parabola through the three points.
  const double d01 = (3.0 - 1.0) / 0.4, d12 = (-2.0 - 3.0) / 1.1, d012 = (d12 - d01) / 1.5;
  for (double t = 0; t <= 1.5; t += 0.05) {
    EXPECT_NEAR(s.value(t), 1.0 + d01 * t + d012 * t * (t - 0.4), 1e-12);
  }
}

TEST(Spline, TwoKnotsIsTheLine) {
  const CubicSpline s({1.0, 3.0}, {2.0, 6.0}, SplineEnds::Natural);
  EXPECT_DOUBLE_EQ(s.value(2.0), 4.0);
  EXPECT_DOUBLE_EQ(s.derivative(1.7), 2.0);
  EXPECT_DOUBLE_EQ(s.second_derivative(1.7), 0.0);
}

TEST(Spline, PassesThroughEveryDataPointAndIsC2) {
  const std::vector<double> y = {0.3, -1.0, 2.5, 2.4, 0.0, 7.0, -3.0};
  for (SplineEnds ends : {SplineEnds::Natural, SplineEnds::NotAKnot}) {
    const CubicSpline s(kKnots, y, ends);
    for (size_t i = 0; i < kKnots.size(); ++i) {
      EXPECT_NEAR(s.value(kKnots[i]), y[i], 1e-13 * (1 + std::abs(y[i])));
    }
    // Continuity at the knots: across x +- e a continuous quantity can change by at most
    // 2 e times the largest size of its derivative (mean value theorem); a jump cannot.
    double s3 = 0;  // largest |S'''| = |m_{i+1} - m_i| / h_i
    const auto& m = s.knot_curvatures();
    for (size_t i = 0; i + 1 < kKnots.size(); ++i) {
      s3 = std::max(s3, std::abs(m[i + 1] - m[i]) / (kKnots[i + 1] - kKnots[i]));
    }
    for (size_t i = 1; i + 1 < kKnots.size(); ++i) {
      const double e = 1e-9, x = kKnots[i];
      const double bound2 = 2 * e * s3 + 1e-12 * (1 + s3);
      EXPECT_NEAR(s.second_derivative(x - e), s.second_derivative(x + e), bound2);
      const double s2 = std::max(std::abs(m[i - 1]), std::max(std::abs(m[i]), std::abs(m[i + 1])));
      EXPECT_NEAR(s.derivative(x - e), s.derivative(x + e), 2 * e * (s2 + e * s3) + 1e-12 * s2);
      const double s1 = std::abs(s.derivative(x)) + e * s2;
      EXPECT_NEAR(s.value(x - e), s.value(x + e), 2 * e * s1 + 1e-13);
    }
    // Slope against central differences of the value, curvature against those of the slope.
    for (double x = -1.25; x < 1.95; x += 0.137) {
      const double e = 1e-6;
      EXPECT_NEAR(s.derivative(x), (s.value(x + e) - s.value(x - e)) / (2 * e), 1e-6);
      EXPECT_NEAR(s.second_derivative(x), (s.derivative(x + e) - s.derivative(x - e)) / (2 * e),
                  1e-5);
    }
  }
}

TEST(Spline, NaturalEndsHaveZeroCurvature) {
  const std::vector<double> y = {0.3, -1.0, 2.5, 2.4, 0.0, 7.0, -3.0};
  const CubicSpline s(kKnots, y, SplineEnds::Natural);
  EXPECT_NEAR(s.second_derivative(kKnots.front()), 0.0, 1e-12);
  EXPECT_NEAR(s.second_derivative(kKnots.back()), 0.0, 1e-12);
}

TEST(Spline, NaturalThreeKnotsClosedForm) {
  // Natural ends, knots 0, h0, h0+h1: m_1 = 3 (d1 - d0) / (h0 + h1), m_0 = m_2 = 0.
  const double h0 = 0.5, h1 = 1.5;
  const std::vector<double> x = {0.0, h0, h0 + h1}, y = {1.0, 2.0, 0.5};
  const CubicSpline s(x, y, SplineEnds::Natural);
  const double d0 = (2.0 - 1.0) / h0, d1 = (0.5 - 2.0) / h1;
  EXPECT_NEAR(s.second_derivative(h0), 3 * (d1 - d0) / (h0 + h1), 1e-13);
}

TEST(Spline, LinearExtrapolationUsesEndSlope) {
  const CubicSpline s(kKnots, values_of(p, kKnots), SplineEnds::NotAKnot,
                      SplineExtrapolation::Linear);
  const double b = 2.0, a = -1.3;
  EXPECT_NEAR(s.value(b + 0.5), p(b) + 0.5 * dp(b), 1e-11);
  EXPECT_NEAR(s.derivative(b + 0.5), dp(b), 1e-11);
  EXPECT_EQ(s.second_derivative(b + 0.5), 0.0);
  EXPECT_NEAR(s.value(a - 0.2), p(a) - 0.2 * dp(a), 1e-11);
  // Integral continues consistently: derivative of the integral is the value.
  const double e = 1e-6;
  EXPECT_NEAR((s.integral(b + 0.3 + e) - s.integral(b + 0.3 - e)) / (2 * e), s.value(b + 0.3),
              1e-6);
  EXPECT_NEAR((s.integral(a - 0.3 + e) - s.integral(a - 0.3 - e)) / (2 * e), s.value(a - 0.3),
              1e-6);
}

TEST(Spline, RejectsBadKnots) {
  EXPECT_THROW(CubicSpline({0.0}, {1.0}, SplineEnds::Natural), std::invalid_argument);
  EXPECT_THROW(CubicSpline({0.0, 1.0, 1.0}, {1.0, 2.0, 3.0}, SplineEnds::Natural),
               std::invalid_argument);
  EXPECT_THROW(CubicSpline({0.0, 2.0, 1.0}, {1.0, 2.0, 3.0}, SplineEnds::Natural),
               std::invalid_argument);
  EXPECT_THROW(CubicSpline({0.0, NAN}, {1.0, 2.0}, SplineEnds::Natural), std::invalid_argument);
}

}  // namespace spline_test
