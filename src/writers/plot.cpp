// Plots through gnuplot: the data (.dat) and script (.gp) are written beside the figure so
// a user can restyle it by hand; the figure itself appears atomically.
#include "writers/plot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "writers/atomic_write.hpp"

extern char** environ;

namespace finseg {
namespace {

/// A gnuplot single-quoted string: no escapes inside, a quote is written twice.
std::string gp_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'')
      out += "''";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out + "'";
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string data_file(const PlotSpec& spec) {
  std::string out =
      "# finseg plot data: one block per band, then per series (gnuplot 'index' 0, 1, ...)\n";
  out += fmt::format("# x: {}\n# y: {}\n", spec.x_label, spec.y_label);
  std::size_t block = 0;
  for (const PlotBand& b : spec.bands) {
    if (block++ > 0) out += "\n\n";
    out += fmt::format("# band {}: {} (x lower upper)\n", block - 1, b.title);
    for (std::size_t i = 0; i < b.x.size(); ++i) {
      out += fmt::format("{:.10g} {:.10g} {:.10g}\n", b.x[i], b.lower[i], b.upper[i]);
    }
  }
  for (std::size_t s = 0; s < spec.series.size(); ++s) {
    const PlotSeries& ser = spec.series[s];
    if (block++ > 0) out += "\n\n";
    out += fmt::format("# series {}: {}\n", block - 1, ser.title);
    for (std::size_t i = 0; i < ser.x.size(); ++i) {
      out += fmt::format("{:.10g} {:.10g}\n", ser.x[i], ser.y[i]);
    }
  }
  if (spec.segments.empty()) return out;
  // Two blocks: the segments with a value (x y dx dy value), then the grey ones.
  for (const bool valued : {true, false}) {
    if (block++ > 0) out += "\n\n";
    out += fmt::format("# segments {}: {} (x y dx dy value)\n", block - 1,
                       valued ? spec.segment_label : spec.grey_label);
    for (const PlotSegment& g : spec.segments) {
      if (std::isfinite(g.value) != valued) continue;
      out += fmt::format("{:.10g} {:.10g} {:.10g} {:.10g} {:.10g}\n", g.x0, g.y0, g.x1 - g.x0,
                         g.y1 - g.y0, valued ? g.value : 0.0);
    }
    // gnuplot refuses an empty block; a zero-length piece draws nothing.
    const PlotSegment& g0 = spec.segments.front();
    out += fmt::format("{:.10g} {:.10g} 0 0 NaN\n", g0.x0, g0.y0);
  }
  return out;
}

// The plot commands of a map's segments (after the bands' and series' blocks).
std::string segment_commands(const PlotSpec& spec, const std::string& dat_path,
                             std::size_t first_block) {
  return fmt::format(
      "  {} index {} using 1:2:3:4:5 with vectors nohead lw 2.5 lc palette title {}, \\\n"
      "  {} index {} using 1:2:3:4 with vectors nohead lw 1.5 lc rgb '#b0b0b0' title {}\n",
      gp_quote(dat_path), first_block, gp_quote(spec.segment_label), gp_quote(dat_path),
      first_block + 1, gp_quote(spec.grey_label));
}

std::string script(const PlotSpec& spec, bool png, const std::string& out_path,
                   const std::string& dat_path) {
  static const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
                                   "#e377c2", "#17becf", "#7f7f7f", "#bcbd22", "#393b79", "#e6550d",
                                   "#31a354", "#de2d8f", "#6b6ecf", "#000000"};
  std::string g = "# finseg plot script; to redraw, run in this folder: gnuplot <this file>\n";
  if (png) {
    g += "set terminal pngcairo size 1200,750 enhanced font 'DejaVu Sans,12' "
         "background rgb 'white' noenhanced\n";
  } else {
    g += "set terminal svg size 1200,750 dynamic font 'DejaVu Sans,12' "
         "background rgb 'white' noenhanced\n";
  }
  g += "set output " + gp_quote(out_path) + "\n";
  g += "set title " + gp_quote(spec.title) + " font ',15'\n";
  if (!spec.warning.empty()) {
    g += "set tmargin 5\n";
    g += "set label 1000 " + gp_quote(spec.warning) +
         " at screen 0.5, screen 0.975 center front font ',15' tc rgb '#c00000'\n";
  }
  g += "set xlabel " + gp_quote(spec.x_label) + "\n";
  g += "set ylabel " + gp_quote(spec.y_label) + "\n";
  g += "set border 3 lw 1.2 lc rgb '#333333'\n";
  g += "set tics nomirror out\n";
  g += "set mxtics 2\nset mytics 2\n";
  g += "set grid xtics ytics mxtics mytics back lt 1 dt solid lw 1 lc rgb '#dedede', lt 1 dt solid "
       "lw 0.6 lc rgb '#f0f0f0'\n";
  g += "set key outside below center horizontal noreverse samplen 3 spacing 1.2 width 2\n";
  g += "set style textbox opaque noborder margins 1, 1\n";
  g += "set autoscale xfix\nset autoscale yfix\n";
  g += "set offsets graph 0.0, graph 0.0, graph 0.06, graph 0.04\n";
  for (std::size_t i = 0; i < std::size(kColours); ++i) {
    g += fmt::format("set linetype {} lc rgb '{}' lw 2.2 pt 7 ps 0.7\n", i + 1, kColours[i]);
  }
  for (std::size_t m = 0; m < spec.markers.size(); ++m) {
    const PlotMarker& mk = spec.markers[m];
    g += fmt::format(
        "set arrow {} from {:.10g}, graph 0 to {:.10g}, graph 1 nohead front dt 2 lw 1.2 "
        "lc rgb '#555555'\n",
        m + 1, mk.x, mk.x);
    g += fmt::format(
        "set label {} {} at {:.10g}, graph 0.98 right rotate by 90 offset char -0.9, 0 "
        "front boxed font ',10' tc rgb '#333333'\n",
        m + 1, gp_quote(mk.label), mk.x);
  }
  double x_lo = INFINITY, x_hi = -INFINITY;
  for (const PlotSeries& ser : spec.series) {
    for (double x : ser.x) x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
  }
  for (std::size_t p = 0; p < spec.points.size(); ++p) {
    const PlotPoint& pt = spec.points[p];
    // Text on the side facing the middle, so that it stays inside the frame.
    const bool right_half = pt.x > 0.5 * (x_lo + x_hi);
    g += fmt::format(
        "set label {} {} at {:.10g}, {:.10g} {} point pt 7 ps 1.6 lc rgb '#000000' offset char "
        "{}, {} front boxed font ',10' tc rgb '#000000'\n",
        spec.markers.size() + p + 1, gp_quote(pt.label), pt.x, pt.y, right_half ? "right" : "left",
        right_half ? -1 : 1, pt.above ? 1 : -1);
  }
  if (!spec.segments.empty()) {
    g += "set size ratio -1\nset autoscale xfix\nset autoscale yfix\n";
    g += "set offsets graph 0.03, graph 0.03, graph 0.03, graph 0.03\n";
    g += "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')\n";
    g += "set cblabel " + gp_quote(spec.segment_label) + "\n";
  }
  g += "plot \\\n";
  const std::size_t bands = spec.bands.size();
  for (std::size_t b = 0; b < bands; ++b) {
    g += fmt::format(
        "  {} index {} using 1:2:3 with filledcurves lc rgb '#9ecae1' fs transparent solid 0.45 "
        "noborder title {}, \\\n",
        gp_quote(dat_path), b, gp_quote(spec.bands[b].title));
  }
  for (std::size_t s = 0; s < spec.series.size(); ++s) {
    const PlotSeries& ser = spec.series[s];
    g += fmt::format(
        "  {} index {} using 1:2 with {} lt {} title {}{}\n", gp_quote(dat_path), bands + s,
        ser.style,
        (ser.colour >= 0 ? static_cast<std::size_t>(ser.colour) : s) % std::size(kColours) + 1,
        gp_quote(ser.title), s + 1 < spec.series.size() || !spec.segments.empty() ? ", \\" : "");
  }
  if (!spec.segments.empty()) g += segment_commands(spec, dat_path, bands + spec.series.size());
  g += "unset output\n";
  return g;
}

/// Runs `gnuplot script_path`; returns its exit status and what it printed on stderr.
int run_gnuplot(const std::string& script_path, std::string& stderr_text) {
  int pipe_fd[2];
  if (pipe(pipe_fd) != 0) throw std::runtime_error("plot: pipe() failed");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fd[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fd[0]);
  posix_spawn_file_actions_addclose(&actions, pipe_fd[1]);
  std::string prog = "gnuplot";
  std::string arg = script_path;
  char* argv[] = {prog.data(), arg.data(), nullptr};
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fd[1]);
  if (rc != 0) {
    close(pipe_fd[0]);
    throw std::runtime_error(std::string("plot: cannot start gnuplot (") + std::strerror(rc) +
                             "); install Debian's gnuplot-nox (scripts/setup.sh)");
  }
  char buf[4096];
  ssize_t got;
  while ((got = read(pipe_fd[0], buf, sizeof buf)) > 0 || (got < 0 && errno == EINTR)) {
    if (got > 0) stderr_text.append(buf, static_cast<std::size_t>(got));
  }
  close(pipe_fd[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("plot: waitpid() failed");
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace

PlotSpec overlay_spec(const std::string& title, const std::vector<OverlayRun>& runs) {
  PlotSpec spec;
  spec.title = title;
  spec.x_label = "pull displacement [mm]";
  spec.y_label = "gauge force [N]";
  std::string unfinished;
  for (const OverlayRun& r : runs) {
    const bool ok = r.status == "ok";
    spec.series.push_back({ok ? r.label : r.label + " [" + r.status + "]", r.x_mm, r.force_N});
    if (!ok) unfinished += (unfinished.empty() ? "" : ", ") + r.label + " (" + r.status + ")";
    if (r.has_peak) {
      spec.points.push_back({r.peak_x_mm, r.peak_N, fmt::format("{:.3g} N", r.peak_N)});
    }
  }
  if (!unfinished.empty()) spec.warning = "NOT FINISHED: " + unfinished;
  return spec;
}

void write_plot(const std::string& path, const PlotSpec& spec) {
  const bool png = ends_with(path, ".png");
  if (!png && !ends_with(path, ".svg")) {
    throw std::invalid_argument("plot '" + path + "': the file name must end in .png or .svg");
  }
  if (spec.series.empty() && spec.segments.empty()) {
    throw std::invalid_argument("plot '" + path + "': no series");
  }
  for (const PlotBand& b : spec.bands) {
    if (b.x.size() != b.lower.size() || b.x.size() != b.upper.size()) {
      throw std::invalid_argument(
          fmt::format("plot '{}': band '{}' has {} x, {} lower and {} "
                      "upper values",
                      path, b.title, b.x.size(), b.lower.size(), b.upper.size()));
    }
  }
  for (const PlotSeries& s : spec.series) {
    if (s.x.size() != s.y.size()) {
      throw std::invalid_argument(fmt::format("plot '{}': series '{}' has {} x and {} y values",
                                              path, s.title, s.x.size(), s.y.size()));
    }
    if (s.style != "lines" && s.style != "points" && s.style != "linespoints") {
      throw std::invalid_argument("plot '" + path + "': series '" + s.title + "' style '" +
                                  s.style + "' is not lines, points or linespoints");
    }
  }
  const std::string dat = path + ".dat", gp = path + ".gp", partial = path + ".partial";
  write_file_atomically(dat, data_file(spec));
  // The script kept beside the figure names files relative to its own folder; the copy we
  // run names them as given and writes .partial, renamed once gnuplot has succeeded.
  const auto name_of = [](const std::string& p) {
    return std::filesystem::path(p).filename().string();
  };
  write_file_atomically(gp, script(spec, png, name_of(path), name_of(dat)));
  const std::string run_script = path + ".run.gp";
  write_file_atomically(run_script, script(spec, png, partial, dat));
  std::string err;
  int rc = 0;
  try {
    rc = run_gnuplot(run_script, err);
  } catch (...) {
    std::remove(run_script.c_str());
    throw;
  }
  std::remove(run_script.c_str());
  std::error_code ec;
  const bool made = std::filesystem::file_size(partial, ec) > 0 && !ec;
  if (rc != 0 || !made) {
    std::remove(partial.c_str());
    throw std::runtime_error(fmt::format("plot '{}': gnuplot failed (exit status {}): {}", path, rc,
                                         err.empty() ? "no message" : err));
  }
  if (std::rename(partial.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(partial.c_str());
    throw std::runtime_error("plot: cannot rename '" + partial + "' to '" + path + "': " + why);
  }
}

}  // namespace finseg
