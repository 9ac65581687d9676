// Plots through gnuplot (Debian's gnuplot-nox): PNG via the pngcairo terminal and SVG.
#pragma once

#include <string>
#include <vector>

namespace finseg {

/// One line of a plot.
struct PlotSeries {
  std::string title;
  std::vector<double> x, y;
  std::string style = "lines";  ///< gnuplot style: "lines", "points", "linespoints"
  int colour = -1;  ///< palette index (16 distinct colours, then repeated); -1: the position
};

/// A vertical marker line with a label (e.g. a deployment-phase boundary).
struct PlotMarker {
  double x = 0;
  std::string label;
};

/// A marked point with a label beside it (e.g. the deployment peak).
struct PlotPoint {
  double x = 0, y = 0;
  std::string label;
  bool above = true;  ///< label above the point, else below (two marks close together)
};

/// A shaded band between two curves over the same abscissae (e.g. a measured spread).
struct PlotBand {
  std::string title;
  std::vector<double> x, lower, upper;
};

/// A straight piece drawn in the colour of its value on the colour bar (e.g. a crease on the
/// flat sheet coloured by when it opened); a value that is not finite is drawn grey.
struct PlotSegment {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double value = 0;
};

struct PlotSpec {
  std::string title, x_label, y_label;  ///< labels carry units
  std::vector<PlotSeries> series;
  std::vector<PlotMarker> markers;
  std::vector<PlotPoint> points;
  std::vector<PlotBand> bands;  ///< drawn beneath the series
  /// Drawn after the series, in the colours of a colour bar titled `segment_label`; a plot
  /// with segments keeps x and y at the same scale (a map).
  std::vector<PlotSegment> segments;
  std::string segment_label;
  std::string grey_label = "never";  ///< legend of the segments whose value is not finite
  /// Shown in red across the top when not empty, e.g. "RUN DIVERGED: ...": a plot of a run
  /// that did not finish must not look like a finished one.
  std::string warning;
};

/// One run of an overlay: its force curve and how it ended.
struct OverlayRun {
  std::string label;                  ///< legend entry, e.g. the run's title
  std::string status = "ok";          ///< summary.json's status; other than "ok": marked
  std::vector<double> x_mm, force_N;  ///< pull displacement, mm; force, N
  double peak_x_mm = 0, peak_N = 0;   ///< deployment peak
  bool has_peak = false;
};

/// The force curves of several runs in one figure (`finseg overlay`): one line per run, its
/// deployment peak marked, a run that did not finish named so in its legend entry and in a
/// red banner.
PlotSpec overlay_spec(const std::string& title, const std::vector<OverlayRun>& runs);

/// Writes `path` (.png or .svg, chosen by extension); the data and the gnuplot script are
/// kept beside it as path + ".dat"/".gp". Throws std::runtime_error if gnuplot fails.
void write_plot(const std::string& path, const PlotSpec& spec);

}  // namespace finseg
