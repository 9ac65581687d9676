#include "elements/crease_laws/crease_data.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/cubic_spline.hpp"
#include "core/error.hpp"
#include "core/text.hpp"

namespace finseg {

namespace {

const char* kAllowedColumns =
    "angle_deg, moment_Nm | force_N (+ lever_m), pressing_time_s, "
    "opening, repeat";

struct Row {
  int line;
  double angle, moment;
};

// Key of one measured curve: pressing time, opening, repeat.
using Key = std::tuple<double, int, int>;

CreaseCurve average_repeats(const std::map<int, std::vector<Row>>& repeats, double pressing,
                            int opening, const std::string& file) {
  CreaseCurve c;
  c.pressing_time = pressing;
  c.opening = opening;
  c.repeats = static_cast<int>(repeats.size());
  c.first_line = repeats.begin()->second.front().line;
  for (const auto& [r, rows] : repeats) c.first_line = std::min(c.first_line, rows.front().line);
  const std::vector<Row>& first = repeats.begin()->second;
  bool same_angles = true;
  for (const auto& [r, rows] : repeats) {
    if (rows.size() != first.size()) {
      same_angles = false;
      break;
    }
    for (size_t i = 0; i < rows.size(); ++i) same_angles &= rows[i].angle == first[i].angle;
  }
  if (same_angles) {
    for (size_t i = 0; i < first.size(); ++i) {
      double sum = 0;
      for (const auto& [r, rows] : repeats) sum += rows[i].moment;
      c.angle_deg.push_back(first[i].angle);
      c.moment.push_back(sum / static_cast<double>(repeats.size()));
    }
    return c;
  }
  // Different angles: every repeat's not-a-knot spline on the union of the angles that lie
  // inside all repeats' ranges.
  double lo = -1e300, hi = 1e300;
  std::vector<CubicSpline> splines;
  std::vector<double> all;
  for (const auto& [r, rows] : repeats) {
    std::vector<double> x, y;
    for (const Row& row : rows) {
      x.push_back(row.angle);
      y.push_back(row.moment);
      all.push_back(row.angle);
    }
    lo = std::max(lo, x.front());
    hi = std::min(hi, x.back());
    splines.emplace_back(x, y, SplineEnds::NotAKnot);
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  for (double a : all) {
    if (a < lo || a > hi) continue;
    double sum = 0;
    for (const CubicSpline& s : splines) sum += s.value(a);
    c.angle_deg.push_back(a);
    c.moment.push_back(std::max(0.0, sum / static_cast<double>(splines.size())));
  }
  if (c.angle_deg.size() < 3) {
    throw InputError(file, fmt::format("line {}: angle_deg", c.first_line),
                     fmt::format("repeats of pressing_time_s {} opening {} overlap in fewer "
                                 "than 3 angles ({}..{} deg); need >= 3 common points",
                                 pressing, opening, lo, hi));
  }
  return c;
}

}  // namespace

std::vector<double> CreaseData::pressing_times() const {
  std::vector<double> p;
  for (const CreaseCurve& c : curves) {
    if (p.empty() || p.back() != c.pressing_time) p.push_back(c.pressing_time);
  }
  return p;
}

std::vector<const CreaseCurve*> CreaseData::curves_at(double pressing_time) const {
  std::vector<const CreaseCurve*> out;
  for (const CreaseCurve& c : curves) {
    if (c.pressing_time == pressing_time) out.push_back(&c);
  }
  return out;
}

CreaseData parse_crease_data(std::istream& raw_in, const std::string& file,
                             std::optional<double> default_lever) {
  std::istringstream in(read_text(raw_in));
  std::string raw;
  int line_no = 0;
  std::vector<std::string> header;
  int header_line = 0;
  while (header.empty() && std::getline(in, raw)) {
    ++line_no;
    const std::string t = trim(raw);
    if (t.empty() || t[0] == '#') continue;
    header = split_csv_line(t);
    header_line = line_no;
  }
  if (header.empty()) {
    throw InputError(file, "header",
                     fmt::format("no header line; expected columns {}", kAllowedColumns));
  }
  std::map<std::string, int> col;
  for (size_t i = 0; i < header.size(); ++i) {
    static const char* known[] = {"angle_deg",       "moment_Nm", "force_N", "lever_m",
                                  "pressing_time_s", "opening",   "repeat"};
    if (std::find(std::begin(known), std::end(known), header[i]) == std::end(known)) {
      throw InputError(file, fmt::format("line {}: column {}", header_line, quoted(header[i])),
                       fmt::format("unknown column; allowed: {}", kAllowedColumns));
    }
    if (col.count(header[i])) {
      throw InputError(file, fmt::format("line {}: column {}", header_line, quoted(header[i])),
                       "appears twice");
    }
    col[header[i]] = static_cast<int>(i);
  }
  const std::string hfield = fmt::format("line {}: header", header_line);
  if (!col.count("angle_deg")) {
    throw InputError(file, hfield,
                     fmt::format("missing column angle_deg; columns: {}", kAllowedColumns));
  }
  const bool by_moment = col.count("moment_Nm") > 0, by_force = col.count("force_N") > 0;
  if (by_moment == by_force) {
    throw InputError(file, hfield, "need exactly one of moment_Nm or force_N (with lever_m)");
  }
  if (by_moment && col.count("lever_m")) {
    throw InputError(file, hfield, "lever_m goes with force_N, not with moment_Nm");
  }
  if (by_force && !col.count("lever_m") && !default_lever) {
    throw InputError(file, hfield, "force_N needs a lever_m column (M = F L, paper eq. 20)");
  }
  if (default_lever && !(*default_lever > 0 && std::isfinite(*default_lever))) {
    throw InputError(file, "lever", "must be > 0 m");
  }

  std::map<Key, std::vector<Row>> rows;
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string t = trim(raw);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> cells = split_csv_line(t);
    if (cells.size() != header.size()) {
      throw InputError(
          file, fmt::format("line {}", line_no),
          fmt::format("has {} values, the header has {} columns", cells.size(), header.size()));
    }
    auto get = [&](const char* name) {
      return parse_number(cells[static_cast<size_t>(col.at(name))], file,
                          fmt::format("line {}: {}", line_no, name));
    };
    auto get_index = [&](const char* name) {
      const double v = get(name);
      if (v != std::floor(v) || v < 1 || v > 1e6) {
        throw InputError(file, fmt::format("line {}: {}", line_no, name),
                         fmt::format("{} is not a valid index; must be an integer 1, 2, ...", v));
      }
      return static_cast<int>(v);
    };
    const double angle = get("angle_deg");
    if (angle < 0 || angle > 360) {
      throw InputError(
          file, fmt::format("line {}: angle_deg", line_no),
          fmt::format("{} outside 0..360 deg (opening angle from folded shut)", angle));
    }
    double moment;
    if (by_moment) {
      moment = get("moment_Nm");
      if (moment < 0) {
        throw InputError(file, fmt::format("line {}: moment_Nm", line_no),
                         fmt::format("{} is negative; must be >= 0 N m (the moment that holds "
                                     "the crease open)",
                                     moment));
      }
    } else {
      const double force = get("force_N");
      if (force < 0) {
        throw InputError(file, fmt::format("line {}: force_N", line_no),
                         fmt::format("{} is negative; must be >= 0 N (the pull that opens the "
                                     "flap)",
                                     force));
      }
      const double lever = col.count("lever_m") ? get("lever_m") : *default_lever;
      if (!(lever > 0)) {
        throw InputError(file, fmt::format("line {}: lever_m", line_no),
                         fmt::format("{} must be > 0 m", lever));
      }
      moment = force * lever;
    }
    double pressing = 0;
    if (col.count("pressing_time_s")) {
      pressing = get("pressing_time_s");
      if (pressing < 0) {
        throw InputError(file, fmt::format("line {}: pressing_time_s", line_no),
                         fmt::format("{} must be >= 0 s", pressing));
      }
    }
    const int opening = col.count("opening") ? get_index("opening") : 1;
    const int repeat = col.count("repeat") ? get_index("repeat") : 1;
    std::vector<Row>& curve = rows[{pressing, opening, repeat}];
    if (!curve.empty() && !(angle > curve.back().angle)) {
      throw InputError(
          file, fmt::format("line {}: angle_deg", line_no),
          fmt::format("{} is not greater than {} on line {}: the angles of one curve "
                      "(pressing_time_s {}, opening {}, repeat {}) must increase strictly; "
                      "repeated measurements need a repeat column",
                      angle, curve.back().angle, curve.back().line, pressing, opening, repeat));
    }
    curve.push_back({line_no, angle, moment});
  }
  if (rows.empty()) throw InputError(file, "data", "no data rows after the header");

  CreaseData data;
  data.source = file;
  std::map<std::pair<double, int>, std::map<int, std::vector<Row>>> conditions;
  for (const auto& [key, curve] : rows) {
    const auto [pressing, opening, repeat] = key;
    if (curve.size() < 3) {
      throw InputError(file, fmt::format("line {}: angle_deg", curve.front().line),
                       fmt::format("curve pressing_time_s {} opening {} repeat {} has {} "
                                   "point(s); need >= 3",
                                   pressing, opening, repeat, curve.size()));
    }
    conditions[{pressing, opening}][repeat] = curve;
  }
  for (const auto& [cond, repeats] : conditions) {
    data.curves.push_back(average_repeats(repeats, cond.first, cond.second, file));
  }
  // Openings of each pressing time must be 1, 2, ..., n.
  for (double p : data.pressing_times()) {
    int expect = 1;
    for (const CreaseCurve* c : data.curves_at(p)) {
      if (c->opening != expect) {
        throw InputError(file, fmt::format("line {}: opening", c->first_line),
                         fmt::format("curve index {} for pressing_time_s {} but opening {} is "
                                     "missing; openings must run 1, 2, ..., n",
                                     c->opening, p, expect));
      }
      ++expect;
    }
  }
  return data;
}

CreaseData read_crease_data(const std::string& path, std::optional<double> default_lever) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "file", "cannot open crease data file");
  return parse_crease_data(in, path, default_lever);
}

void write_crease_data(std::ostream& out, const CreaseData& data,
                       const std::vector<std::string>& comment) {
  for (const std::string& c : comment) out << "# " << c << '\n';
  out << "angle_deg,moment_Nm,pressing_time_s,opening\n";
  for (const CreaseCurve& c : data.curves) {
    for (size_t i = 0; i < c.angle_deg.size(); ++i) {
      out << fmt::format("{:.17g},{:.17g},{:.17g},{}\n", c.angle_deg[i], c.moment[i],
                         c.pressing_time, c.opening);
    }
  }
}

void write_crease_data(const std::string& path, const CreaseData& data,
                       const std::vector<std::string>& comment) {
  std::ofstream out(path);
  if (!out) throw InputError(path, "file", "cannot write crease data file");
  write_crease_data(out, data, comment);
  if (!out) throw InputError(path, "file", "write failed");
}

}  // namespace finseg
