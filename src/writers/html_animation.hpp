// Self-contained HTML page: 3-D view of the unfolding (play, pause, scrub, rotate) with the
// force curve beside it and a marker that follows the current frame. three.js and Chart.js
// are inlined from Debian's libjs-three and libjs-chart.js.
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"
#include "writers/frames.hpp"

namespace finseg {

/// A labelled point on the force chart (e.g. the deployment peak), in the curve's units.
struct ChartMark {
  double x = 0, y = 0;
  std::string label;
};

/// What the page says besides the motion: a red banner for a run that did not finish
/// (empty: none), labelled points on the chart, and further curves charted below it (a
/// chamber's pressure), each with one point per frame.
struct HtmlAnnotations {
  std::string warning;
  std::vector<ChartMark> marks;
  std::vector<Curve> curves;
};

/// How the page shows Frame::t (the slider's abscissa): `label` with its unit in brackets and
/// the factor from Frame::t to that unit, e.g. {"pull displacement [mm]", 1e3} for a
/// quasi-static pull whose Frame::t is in m.
struct FrameAxis {
  std::string label = "time [s]";
  double scale = 1;
};

/// Writes one HTML file (atomically) that needs no network and no other file. `curve` may
/// be empty (no chart); otherwise it has one point per frame. Throws InputError if frames or curve
/// do not fit the model, and std::runtime_error naming the file and the Debian package if a
/// JavaScript library is missing.
void write_html_animation(const std::string& path, const std::string& title, const Model& model,
                          const std::vector<Frame>& frames, const Curve& curve,
                          const FrameAxis& axis = {}, const HtmlAnnotations& notes = {});

/// Where the inlined libraries are read from (Debian's libjs-three and libjs-chart.js).
inline constexpr const char* kThreeJsPath = "/usr/share/javascript/three/three.min.js";
inline constexpr const char* kOrbitControlsJsPath =
    "/usr/share/javascript/three/examples/js/controls/OrbitControls.js";
inline constexpr const char* kChartJsPath = "/usr/share/javascript/chart.js/chart.min.js";

}  // namespace finseg
