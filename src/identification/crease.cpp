#include "identification/crease.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/types.hpp"
#include "elements/crease_laws/measured.hpp"

namespace finseg {

CreaseIdentification identify_crease(const CreaseData& flap, SplineEnds ends) {
  CreaseIdentification id;
  id.data = flap;
  for (const CreaseCurve& c : flap.curves) {
    CreaseData one;
    one.source = flap.source;
    one.curves = {c};
    one.curves[0].pressing_time = 0;
    one.curves[0].opening = 1;
    MeasuredLawOptions o;
    o.ends = ends;
    const MeasuredCreaseLaw law(one, o);
    CreaseCurveSummary s;
    s.pressing_time = c.pressing_time;
    s.opening = c.opening;
    s.points = static_cast<int>(c.angle_deg.size());
    s.repeats = c.repeats;
    s.theta_min_deg = c.angle_deg.front();
    s.theta_max_deg = c.angle_deg.back();
    const double rest_phi = law.rest_angle(ElementHistory{}, 0);
    s.rest_deg = (kPi - rest_phi) / kDegToRad;
    const double th0 = s.theta_min_deg * kDegToRad, th1 = s.theta_max_deg * kDegToRad;
    s.secant_stiffness = std::isfinite(rest_phi) ? c.moment.back() / (th1 - (kPi - rest_phi))
                                                 : std::numeric_limits<double>::quiet_NaN();
    s.tangent_start = law.opening_moment(th0, 1).slope;
    s.tangent_end = law.opening_moment(th1, 1).slope;
    if (!std::isfinite(s.tangent_start) || !std::isfinite(s.tangent_end)) {
      throw InputError(
          flap.source,
          fmt::format("curve pressing_time_s {:g}, opening {}", c.pressing_time, c.opening),
          fmt::format("the spline through the moments (up to {:g} N m) is not "
                      "finite; give moments in N m and angles in degrees",
                      *std::max_element(c.moment.begin(), c.moment.end())));
    }
    id.curves.push_back(s);
  }
  return id;
}

PlotSpec crease_plot(const CreaseIdentification& id, SplineEnds ends) {
  PlotSpec p;
  p.title = "Crease stiffness characteristic (flap test, M = F L)";
  p.x_label = "opening angle (deg)";
  p.y_label = "moment (N m)";
  for (const CreaseCurve& c : id.data.curves) {
    const MomentCurve curve(c, ends);
    PlotSeries line, points;
    line.title = fmt::format("pressed {} s, opening {}", c.pressing_time, c.opening);
    line.style = "lines";
    const int n = 200;
    for (int i = 0; i <= n; ++i) {
      const double deg = c.angle_deg.front() + (c.angle_deg.back() - c.angle_deg.front()) * i / n;
      line.x.push_back(deg);
      line.y.push_back(curve.at(deg * kDegToRad).value);
    }
    points.title = "";
    points.style = "points";
    points.x = c.angle_deg;
    points.y = c.moment;
    // One colour per curve, its fitted line and its measured points alike.
    line.colour = points.colour = static_cast<int>(p.series.size() / 2);
    p.series.push_back(std::move(line));
    p.series.push_back(std::move(points));
  }
  return p;
}

}  // namespace finseg
