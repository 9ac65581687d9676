#include "probes/unfolding.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "elements/bushing.hpp"
#include "model/segment_shape.hpp"

namespace finseg {
namespace {

// Mean fold angle of a line's crease elements for the bodies' orientations R_WB, each nearest
// to its element's last accepted angle in `history` (none: the principal angle, for a shape).
double mean_fold_angle(const Model& model, const UnfoldingLine& line, const std::vector<Mat3>& R_WB,
                       const std::vector<ElementHistory>* history) {
  double sum = 0;
  for (int k : line.elements) {
    const ElementDef& e = model.elements[k];
    sum += fold_angle<double>(R_WB[e.inner] * e.R_inner_E, R_WB[e.outer] * e.R_outer_F,
                              history ? (*history)[k].fold_angle : 0.0);
  }
  return sum / static_cast<double>(line.elements.size());
}

// Where element e's side lies on the flat sheet: the side of its outer body's outline that
// carries the element's point (none when the body has no flat placement).
bool flat_side(const BodyDef& outer, const ElementDef& e, std::array<Vec2, 2>& side_M) {
  if (!outer.centroid_M || outer.outline_B.size() < 3) return false;
  const Vec2 P = e.c_outer_B.head<2>();
  double nearest = std::numeric_limits<double>::infinity();
  const std::size_t n = outer.outline_B.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = outer.outline_B[i], &b = outer.outline_B[(i + 1) % n];
    const double d = point_segment_distance(P, a, b);
    if (d >= nearest) continue;
    nearest = d;
    side_M = {*outer.centroid_M + a, *outer.centroid_M + b};
  }
  return true;
}

// Lines in reading order: by their name's letters, then its number ("edge2" before "edge10").
bool reads_before(const std::string& a, const std::string& b) {
  const auto split = [](const std::string& s) {
    const std::size_t digits = s.find_first_of("0123456789");
    const std::string word = s.substr(0, digits);
    return std::make_pair(word, digits == std::string::npos ? -1L : std::stol(s.substr(digits)));
  };
  return split(a) < split(b);
}

}  // namespace

std::vector<UnfoldingLine> unfolding_lines(const Model& model, int shape) {
  std::vector<UnfoldingLine> lines;
  std::map<std::string, std::size_t> by_name;
  for (std::size_t k = 0; k < model.elements.size(); ++k) {
    const ElementDef& e = model.elements[k];
    if (e.crease < 0) continue;
    const std::string& line = model.creases[e.crease].line;
    const std::string name = line.empty() ? fmt::format("crease{}", e.crease + 1) : line;
    const auto [it, added] = by_name.emplace(name, lines.size());
    if (added) lines.push_back({name, {}, 0, {}});
    UnfoldingLine& l = lines[it->second];
    l.elements.push_back(static_cast<int>(k));
    std::array<Vec2, 2> side;
    if (flat_side(model.bodies[e.outer], e, side)) l.sides_M.push_back(side);
  }
  std::stable_sort(lines.begin(), lines.end(), [](const UnfoldingLine& a, const UnfoldingLine& b) {
    return reads_before(a.name, b.name);
  });
  if (shape < 0) return lines;  // towards flat: targets 0
  for (UnfoldingLine& l : lines)
    l.target = mean_fold_angle(model, l, model.shapes[shape].R_WB, nullptr);
  return lines;
}

std::vector<double> line_fold_angles(const Model& model, const State& state,
                                     const std::vector<UnfoldingLine>& lines) {
  std::vector<double> out;
  out.reserve(lines.size());
  for (const UnfoldingLine& l : lines) {
    out.push_back(mean_fold_angle(model, l, state.R_WB, &state.history));
  }
  return out;
}

double opening_fraction(double angle, double start, double target) {
  return (angle - start) / (target - start);
}

std::vector<std::string> unfolding_columns(const std::string& x,
                                           const std::vector<UnfoldingLine>& lines) {
  std::vector<std::string> c{x, "lines_half_open", "mean_opening"};
  for (const UnfoldingLine& l : lines) c.push_back(l.name + "_deg");
  return c;
}

std::vector<double> unfolding_row(double x, const std::vector<double>& angles_rad,
                                  const std::vector<double>& start_deg,
                                  const std::vector<UnfoldingLine>& lines) {
  std::vector<double> row{x, 0, 0};
  for (double a : angles_rad) row.push_back(a / kDegToRad);
  const double* start = start_deg.empty() ? &row[kFirstLineColumn] : start_deg.data();
  int folded = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const double target = lines[i].target / kDegToRad;
    if (std::abs(target - start[i]) < kLeastFoldToOpen / kDegToRad) continue;
    const double f = opening_fraction(row[kFirstLineColumn + i], start[i], target);
    ++folded;
    row[1] += f >= 0.5 ? 1 : 0;
    row[2] += f;
  }
  row[2] = folded > 0 ? row[2] / folded : NAN;
  return row;
}

namespace {

// First abscissa where a line's opening reaches `level`, interpolated between the rows.
double first_reaching(const std::vector<std::vector<double>>& rows, std::size_t column,
                      double start, double target, double level) {
  double f_before = 0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const double f = opening_fraction(rows[r][column], start, target);
    if (f >= level) {
      if (r == 0) return rows[0][0];
      const double u = (level - f_before) / (f - f_before);
      return rows[r - 1][0] + u * (rows[r][0] - rows[r - 1][0]);
    }
    f_before = f;
  }
  return NAN;
}

}  // namespace

std::vector<LineOpening> unfolding_order(const std::vector<std::vector<double>>& rows,
                                         const std::vector<UnfoldingLine>& lines) {
  std::vector<LineOpening> out;
  if (rows.empty()) return out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::size_t c = kFirstLineColumn + i;
    LineOpening o;
    o.name = lines[i].name;
    o.start_deg = rows.front()[c];
    o.target_deg = lines[i].target / kDegToRad;
    if (std::abs(o.target_deg - o.start_deg) < kLeastFoldToOpen / kDegToRad) continue;
    o.final_deg = rows.back()[c];
    o.final_opening = opening_fraction(o.final_deg, o.start_deg, o.target_deg);
    o.half_open_at = first_reaching(rows, c, o.start_deg, o.target_deg, 0.5);
    o.open_at = first_reaching(rows, c, o.start_deg, o.target_deg, 0.9);
    if (!lines[i].sides_M.empty()) {
      Vec2 sum = Vec2::Zero();
      for (const auto& s : lines[i].sides_M) sum += 0.5 * (s[0] + s[1]);
      o.mid_M = sum / static_cast<double>(lines[i].sides_M.size());
    }
    out.push_back(o);
  }
  std::stable_sort(out.begin(), out.end(), [](const LineOpening& a, const LineOpening& b) {
    const bool ha = std::isfinite(a.half_open_at), hb = std::isfinite(b.half_open_at);
    if (ha != hb) return ha;
    if (ha) return a.half_open_at < b.half_open_at;
    return a.final_opening > b.final_opening;
  });
  return out;
}

}  // namespace finseg
