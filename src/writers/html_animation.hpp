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
/// (empty: none) and labelled points on the chart.
struct HtmlAnnotations {
  std::string warning;
  std::vector<ChartMark> marks;
};

/// Writes one HTML file (atomically) that needs no network and no other file. `curve` may
/// be empty (no chart); otherwise it has one point per frame. `time_label` names what
/// Frame::t is, with its unit in brackets: "time [s]", or e.g. "drive displacement [m]" for
/// quasi-static runs. Throws InputError if frames or curve do not fit the model, and
/// std::runtime_error naming the file and the Debian package if a JavaScript library is
/// missing.
void write_html_animation(const std::string& path, const std::string& title, const Model& model,
                          const std::vector<Frame>& frames, const Curve& curve,
                          const std::string& time_label = "time [s]",
                          const HtmlAnnotations& notes = {});

/// Where the inlined libraries are read from (Debian's libjs-three and libjs-chart.js).
inline constexpr const char* kThreeJsPath = "/usr/share/javascript/three/three.min.js";
inline constexpr const char* kOrbitControlsJsPath =
    "/usr/share/javascript/three/examples/js/controls/OrbitControls.js";
inline constexpr const char* kChartJsPath = "/usr/share/javascript/chart.js/chart.min.js";

}  // namespace finseg
