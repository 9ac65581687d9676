// Self-contained HTML page: 3-D view of the unfolding (play, pause, scrub, rotate) with the
// force curve beside it and a marker that follows the current frame. three.js and Chart.js
// are inlined from Debian's libjs-three and libjs-chart.js.
#pragma once

#include <string>
#include <vector>

#include "model/model.hpp"
#include "writers/frames.hpp"

namespace finseg {

/// Writes one HTML file (atomically) that needs no network and no other file.
void write_html_animation(const std::string& path, const std::string& title,
                          const Model& model, const std::vector<Frame>& frames,
                          const Curve& curve);

}  // namespace finseg
