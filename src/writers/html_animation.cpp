// Self-contained HTML animation: the page template with three.js, OrbitControls and
// Chart.js inlined from Debian's packages and the model and frames embedded as JSON.
#include "writers/html_animation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "writers/atomic_write.hpp"
#include "writers/frame_check.hpp"
#include "writers/html/page_template.hpp"

namespace finseg {
namespace {

/// Replaces every occurrence of `from` with `to`.
void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (std::size_t pos = s.find(from); pos != std::string::npos;
       pos = s.find(from, pos + to.size())) {
    s.replace(pos, from.size(), to);
  }
}

/// Text that is safe inside an HTML <script> element: the sequences that would end the
/// element or switch the HTML parser's script state are broken with a backslash, which is
/// harmless where they can occur in JavaScript and JSON (inside string literals).
std::string script_safe(std::string s) {
  replace_all(s, "</script", "<\\/script");
  replace_all(s, "</SCRIPT", "<\\/SCRIPT");
  replace_all(s, "<!--", "<\\!--");
  return s;
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string read_library(const char* path, const char* package) {
  try {
    return read_whole_file(path);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("HTML animation: needs ") + path +
                             " from Debian's package " + package +
                             " (install it with scripts/setup.sh): " + e.what());
  }
}

/// A number with at most `decimals` digits after the point, trailing zeros dropped.
void put_fixed(std::string& out, double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  out += s;
}

/// A number with `digits` significant digits (shortest form).
void put_general(std::string& out, double v, int digits) {
  out += fmt::format("{:.{}g}", v, digits);
}

std::string json_string(const std::string& s) {
  return nlohmann::json(s).dump();
}

// `"xLabel":..,"yLabel":..,"x":[..],"y":[..]` of a curve (7 significant digits).
void put_curve(std::string& j, const Curve& curve) {
  j += "\"xLabel\":";
  j += json_string(curve.x_label);
  j += ",\"yLabel\":";
  j += json_string(curve.y_label);
  j += ",\"x\":[";
  for (std::size_t i = 0; i < curve.x.size(); ++i) {
    if (i) j += ',';
    put_general(j, curve.x[i], 7);
  }
  j += "],\"y\":[";
  for (std::size_t i = 0; i < curve.y.size(); ++i) {
    if (i) j += ',';
    put_general(j, curve.y[i], 7);
  }
  j += ']';
}

std::string data_json(const std::string& title, const FrameAxis& axis, const Model& model,
                      const std::vector<Frame>& frames, const Curve& curve,
                      const HtmlAnnotations& notes) {
  const std::vector<ChartMark>& marks = notes.marks;
  const std::size_t n = model.bodies.size();
  // Positions are rounded to 1e-5 of the scene's extent (1e-6 m at the least).
  double extent = 0;
  for (const BodyDef& b : model.bodies) {
    extent = std::max(extent, std::hypot(2 * outline_radius(b.outline_B), b.thickness));
  }
  if (n > 0) {
    Vec3 lo = frames[0].p_W[0], hi = lo;
    for (const Frame& f : frames) {
      for (const Vec3& p : f.p_W) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
    extent = std::max(extent, (hi - lo).norm());
  }
  const int pos_decimals =
      extent > 0 ? std::clamp(static_cast<int>(std::ceil(-std::log10(extent * 1e-5))), 0, 6) : 6;

  std::string j = "{\"title\":";
  j += json_string(title);
  j += ",\"timeLabel\":";
  j += json_string(axis.label);
  j += ",\"lengthUnit\":\"m\",\"bodies\":{\"outline\":[";
  for (std::size_t b = 0; b < n; ++b) {
    j += b ? ",[" : "[";
    const Outline& o = model.bodies[b].outline_B;
    for (std::size_t k = 0; k < o.size(); ++k) {
      if (k) j += ',';
      put_general(j, o[k].x(), 6);
      j += ',';
      put_general(j, o[k].y(), 6);
    }
    j += ']';
  }
  j += "],\"thickness\":[";
  for (std::size_t b = 0; b < n; ++b) {
    if (b) j += ',';
    put_general(j, model.bodies[b].thickness, 6);
  }
  j += "],\"panel\":[";
  for (std::size_t b = 0; b < n; ++b) {
    if (b) j += ',';
    j += std::to_string(model.bodies[b].panel);
  }
  j += "],\"fixed\":[";
  for (std::size_t b = 0; b < n; ++b) {
    if (b) j += ',';
    j += model.bodies[b].fixed ? '1' : '0';
  }
  j += "],\"name\":[";
  for (std::size_t b = 0; b < n; ++b) {
    if (b) j += ',';
    j += json_string(model.bodies[b].name);
  }
  j += "]},\"frames\":{\"t\":[";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    if (f) j += ',';
    put_general(j, axis.scale * frames[f].t, 9);
  }
  j += "],\"p\":[";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    j += f ? ",[" : "[";
    for (std::size_t b = 0; b < n; ++b) {
      for (int k = 0; k < 3; ++k) {
        if (b || k) j += ',';
        put_fixed(j, frames[f].p_W[b][k], pos_decimals);
      }
    }
    j += ']';
  }
  j += "],\"q\":[";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    j += f ? ",[" : "[";
    for (std::size_t b = 0; b < n; ++b) {
      // Nearest rotation first, so a slightly non-orthogonal R still gives a unit quaternion.
      Eigen::Quaterniond q(frames[f].R_WB[b]);
      q.normalize();
      const double xyzw[4] = {q.x(), q.y(), q.z(), q.w()};
      for (int k = 0; k < 4; ++k) {
        if (b || k) j += ',';
        put_fixed(j, xyzw[k], 5);
      }
    }
    j += ']';
  }
  j += "],\"c\":[";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    j += f ? ",[" : "[";
    const auto& cps = frames[f].contact_points_W;
    for (std::size_t c = 0; c < cps.size(); ++c) {
      for (int k = 0; k < 3; ++k) {
        if (c || k) j += ',';
        put_fixed(j, cps[c][k], pos_decimals);
      }
    }
    j += ']';
  }
  j += "]},\"curve\":{";
  put_curve(j, curve);
  j += ",\"marks\":[";
  for (std::size_t i = 0; i < marks.size(); ++i) {
    j += i ? ",{\"x\":" : "{\"x\":";
    put_general(j, marks[i].x, 7);
    j += ",\"y\":";
    put_general(j, marks[i].y, 7);
    j += ",\"label\":" + json_string(marks[i].label) + "}";
  }
  j += "]},\"curves\":[";
  for (std::size_t i = 0; i < notes.curves.size(); ++i) {
    j += i ? ",{" : "{";
    put_curve(j, notes.curves[i]);
    j += '}';
  }
  j += "]}";
  return j;
}

void check_curve(const Model& model, const std::vector<Frame>& frames, const Curve& curve) {
  if (curve.x.size() != curve.y.size()) {
    throw InputError(model.source, "curve",
                     fmt::format("has {} x and {} y values", curve.x.size(), curve.y.size()));
  }
  if (!curve.x.empty() && curve.x.size() != frames.size()) {
    throw InputError(model.source, "curve",
                     fmt::format("has {} points but there are {} frames (one point per frame)",
                                 curve.x.size(), frames.size()));
  }
  for (std::size_t i = 0; i < curve.x.size(); ++i) {
    if (!std::isfinite(curve.x[i]) || !std::isfinite(curve.y[i])) {
      throw InputError(model.source, fmt::format("curve point {}", i), "must be finite");
    }
  }
}

}  // namespace

void write_html_animation(const std::string& path, const std::string& title, const Model& model,
                          const std::vector<Frame>& frames, const Curve& curve,
                          const FrameAxis& axis, const HtmlAnnotations& notes) {
  if (frames.empty()) throw InputError(model.source, "frames", "at least one frame is needed");
  check_frames(model, frames);
  check_curve(model, frames, curve);
  for (const Curve& c : notes.curves) {
    if (c.x.empty()) throw InputError(model.source, "curve " + c.y_label, "has no points");
    check_curve(model, frames, c);
  }

  std::string libs;
  const struct {
    const char* path;
    const char* package;
    const char* what;
  } kLibs[] = {{kThreeJsPath, "libjs-three", "three.js r111"},
               {kOrbitControlsJsPath, "libjs-three", "three.js OrbitControls"},
               {kChartJsPath, "libjs-chart.js", "Chart.js"}};
  for (const auto& lib : kLibs) {
    libs += fmt::format("<script>/* {} inlined from {} (Debian package {}) */\n", lib.what,
                        lib.path, lib.package);
    libs += script_safe(read_library(lib.path, lib.package));
    libs += "\n</script>\n";
  }

  const std::string tmpl = html::kPageTemplate;
  for (const ChartMark& m : notes.marks) {
    if (!std::isfinite(m.x) || !std::isfinite(m.y)) {
      throw InputError(model.source, "chart mark '" + m.label + "'", "must be finite");
    }
  }
  const std::string data = script_safe(data_json(title, axis, model, frames, curve, notes));
  std::string page;
  page.reserve(tmpl.size() + libs.size() + data.size() + title.size());
  // Each placeholder is looked up in the template only, never in what was inserted.
  std::size_t pos = 0;
  const std::string escaped_title = html_escape(title),
                    escaped_warning = html_escape(notes.warning);
  const std::pair<const char*, const std::string*> parts[] = {{"@@TITLE@@", &escaped_title},
                                                              {"@@WARNING@@", &escaped_warning},
                                                              {"@@LIBS@@", &libs},
                                                              {"@@DATA@@", &data}};
  for (const auto& [key, value] : parts) {
    const std::size_t at = tmpl.find(key, pos);
    if (at == std::string::npos) throw std::logic_error(std::string("page template lacks ") + key);
    page.append(tmpl, pos, at - pos);
    page += *value;
    pos = at + std::string(key).size();
  }
  page.append(tmpl, pos, std::string::npos);
  write_file_atomically(path, page);
}

}  // namespace finseg
