// C^2 cubic interpolating spline on non-uniform knots, with natural or not-a-knot ends.
// Value, first and second derivative and the exact integral; a chosen rule outside the knots.
#pragma once

#include <string>
#include <vector>

namespace finseg {

/// End conditions of an interpolating cubic spline.
enum class SplineEnds {
  Natural,   ///< S'' = 0 at both ends
  NotAKnot,  ///< S''' continuous at the second and the second-to-last knot
};

/// What the spline returns outside [x.front(), x.back()].
enum class SplineExtrapolation {
  Linear,      ///< straight line with the end value and end slope (S'' = 0 outside)
  Polynomial,  ///< the end piece's cubic continued
};

/// Parses "natural" / "not-a-knot"; returns false for anything else.
bool parse_spline_ends(const std::string& text, SplineEnds& ends);
std::string to_string(SplineEnds ends);

/// Interpolating cubic spline S with S(x_i) = y_i, C^2 on [x_0, x_{n-1}].
/// Needs n >= 2 strictly increasing finite knots. With n = 2 it is the straight line; with
/// n = 3 and not-a-knot ends the parabola through the three points (both conditions then
/// say the same thing). Throws std::invalid_argument on bad knots.
class CubicSpline {
 public:
  CubicSpline() = default;
  CubicSpline(std::vector<double> x, std::vector<double> y, SplineEnds ends,
              SplineExtrapolation extrapolation = SplineExtrapolation::Linear);

  double value(double x) const;
  double derivative(double x) const;
  double second_derivative(double x) const;
  /// Exact integral of S from x.front() to x (negative for x < x.front()).
  double integral(double x) const;

  /// Value, slope and curvature at once (one interval search).
  struct Sample {
    double value = 0, slope = 0, curvature = 0;
  };
  Sample sample(double x) const;

  const std::vector<double>& knots() const { return x_; }
  const std::vector<double>& values() const { return y_; }
  /// Second derivatives at the knots (the spline's "moments").
  const std::vector<double>& knot_curvatures() const { return m_; }
  double x_min() const { return x_.front(); }
  double x_max() const { return x_.back(); }
  bool empty() const { return x_.empty(); }
  SplineEnds ends() const { return ends_; }

 private:
  size_t interval(double x) const;
  double piece_integral(size_t i, double u) const;  ///< from x_i to x_i + u

  std::vector<double> x_, y_, m_;
  std::vector<double> cumulative_;  ///< integral from x_0 to x_i
  SplineEnds ends_ = SplineEnds::Natural;
  SplineExtrapolation extrapolation_ = SplineExtrapolation::Linear;
};

}  // namespace finseg
