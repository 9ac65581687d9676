#include "core/cubic_spline.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace finseg {

bool parse_spline_ends(const std::string& text, SplineEnds& ends) {
  if (text == "natural") {
    ends = SplineEnds::Natural;
    return true;
  }
  if (text == "not-a-knot") {
    ends = SplineEnds::NotAKnot;
    return true;
  }
  return false;
}

std::string to_string(SplineEnds ends) {
  return ends == SplineEnds::Natural ? "natural" : "not-a-knot";
}

CubicSpline::CubicSpline(std::vector<double> x, std::vector<double> y, SplineEnds ends,
                         SplineExtrapolation extrapolation)
    : x_(std::move(x)), y_(std::move(y)), ends_(ends), extrapolation_(extrapolation) {
  const size_t n = x_.size();
  if (n < 2 || y_.size() != n) {
    throw std::invalid_argument("cubic spline: needs at least 2 knots and one value per knot");
  }
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i])) {
      throw std::invalid_argument("cubic spline: knots and values must be finite");
    }
    if (i > 0 && !(x_[i] > x_[i - 1])) {
      throw std::invalid_argument("cubic spline: knots must be strictly increasing");
    }
  }
  m_.assign(n, 0.0);
  if (n >= 3) {
    // Unknowns: second derivatives m_i at the knots. Interior rows are the C^2 conditions
    // h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1} = 6 (d_i - d_{i-1}).
    std::vector<Eigen::Triplet<double>> t;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
    auto h = [&](size_t i) { return x_[i + 1] - x_[i]; };
    auto d = [&](size_t i) { return (y_[i + 1] - y_[i]) / h(i); };
    for (size_t i = 1; i + 1 < n; ++i) {
      const int r = static_cast<int>(i);
      t.emplace_back(r, r - 1, h(i - 1));
      t.emplace_back(r, r, 2 * (h(i - 1) + h(i)));
      t.emplace_back(r, r + 1, h(i));
      rhs[r] = 6 * (d(i) - d(i - 1));
    }
    const int last = static_cast<int>(n) - 1;
    if (ends_ == SplineEnds::Natural) {
      t.emplace_back(0, 0, 1.0);
      t.emplace_back(last, last, 1.0);
    } else if (n == 3) {
      // Both not-a-knot conditions say "one cubic over all three knots"; with three points
      // that cubic is the interpolating parabola: m_0 = m_1 = m_2.
      t.emplace_back(0, 0, 1.0);
      t.emplace_back(0, 1, -1.0);
      t.emplace_back(2, 2, 1.0);
      t.emplace_back(2, 1, -1.0);
    } else {
      // Jump of S''' at x_1 and x_{n-2} is zero: (m_1 - m_0)/h_0 = (m_2 - m_1)/h_1.
      t.emplace_back(0, 0, h(1));
      t.emplace_back(0, 1, -(h(0) + h(1)));
      t.emplace_back(0, 2, h(0));
      t.emplace_back(last, last - 2, h(n - 2));
      t.emplace_back(last, last - 1, -(h(n - 3) + h(n - 2)));
      t.emplace_back(last, last, h(n - 3));
    }
    Eigen::SparseMatrix<double> A(last + 1, last + 1);
    A.setFromTriplets(t.begin(), t.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(A);
    if (lu.info() != Eigen::Success) {
      throw std::invalid_argument("cubic spline: singular end-condition system");
    }
    const Eigen::VectorXd m = lu.solve(rhs);
    for (size_t i = 0; i < n; ++i) m_[i] = m[static_cast<Eigen::Index>(i)];
  }
  cumulative_.assign(n, 0.0);
  for (size_t i = 0; i + 1 < n; ++i) {
    cumulative_[i + 1] = cumulative_[i] + piece_integral(i, x_[i + 1] - x_[i]);
  }
}

size_t CubicSpline::interval(double x) const {
  // Piece i covers [x_i, x_{i+1}); the last piece also takes x_{n-1} and beyond.
  const auto it = std::upper_bound(x_.begin() + 1, x_.end() - 1, x);
  return static_cast<size_t>(it - x_.begin()) - 1;
}

// On piece i with h = x_{i+1} - x_i, u = x - x_i, w = h - u:
// S = m_i w^3/(6h) + m_{i+1} u^3/(6h) + (y_i/h - m_i h/6) w + (y_{i+1}/h - m_{i+1} h/6) u.
CubicSpline::Sample CubicSpline::sample(double x) const {
  const size_t n = x_.size();
  if (extrapolation_ == SplineExtrapolation::Linear && (x < x_[0] || x > x_[n - 1])) {
    const bool left = x < x_[0];
    const size_t e = left ? 0 : n - 1;
    const Sample end = sample(x_[e]);
    return {end.value + end.slope * (x - x_[e]), end.slope, 0.0};
  }
  const size_t i = interval(x);
  const double h = x_[i + 1] - x_[i], u = x - x_[i], w = h - u;
  const double a = y_[i] / h - m_[i] * h / 6, b = y_[i + 1] / h - m_[i + 1] * h / 6;
  Sample s;
  s.value = (m_[i] * w * w * w + m_[i + 1] * u * u * u) / (6 * h) + a * w + b * u;
  s.slope = (-m_[i] * w * w + m_[i + 1] * u * u) / (2 * h) - a + b;
  s.curvature = (m_[i] * w + m_[i + 1] * u) / h;
  return s;
}

double CubicSpline::value(double x) const {
  return sample(x).value;
}
double CubicSpline::derivative(double x) const {
  return sample(x).slope;
}
double CubicSpline::second_derivative(double x) const {
  return sample(x).curvature;
}

double CubicSpline::piece_integral(size_t i, double u) const {
  const double h = x_[i + 1] - x_[i], w = h - u;
  const double a = y_[i] / h - m_[i] * h / 6, b = y_[i + 1] / h - m_[i + 1] * h / 6;
  return m_[i] * (h * h * h * h - w * w * w * w) / (24 * h) + m_[i + 1] * u * u * u * u / (24 * h) +
         a * (h * h - w * w) / 2 + b * u * u / 2;
}

double CubicSpline::integral(double x) const {
  const size_t n = x_.size();
  if (extrapolation_ == SplineExtrapolation::Linear && (x < x_[0] || x > x_[n - 1])) {
    const size_t e = x < x_[0] ? 0 : n - 1;
    const Sample end = sample(x_[e]);
    const double u = x - x_[e];
    return cumulative_[e] + end.value * u + end.slope * u * u / 2;
  }
  const size_t i = interval(x);
  return cumulative_[i] + piece_integral(i, x - x_[i]);
}

}  // namespace finseg
