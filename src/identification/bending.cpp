#include "identification/bending.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.hpp"
#include "core/text.hpp"

namespace finseg {

CantileverData parse_cantilever_data(std::istream& raw_in, const std::string& file) {
  std::istringstream in(read_text(raw_in));
  CantileverData d;
  d.source = file;
  std::string raw;
  int line = 0;
  std::vector<std::string> header;
  int col_f = -1, col_x = -1;
  double x_scale = 1;
  while (std::getline(in, raw)) {
    ++line;
    const std::string t = trim(raw);
    if (t.empty()) continue;
    if (t[0] == '#') {
      const auto colon = t.find(':');
      if (colon == std::string::npos) continue;
      const std::string key = trim(t.substr(1, colon - 1));
      const std::string value = trim(t.substr(colon + 1));
      std::optional<double>* slot = key == "length_m"      ? &d.length
                                    : key == "width_m"     ? &d.width
                                    : key == "thickness_m" ? &d.thickness
                                                           : nullptr;
      if (slot) {
        const double v = parse_number(value, file, fmt::format("line {}: {}", line, key));
        if (!(v > 0)) {
          throw InputError(file, fmt::format("line {}: {}", line, key),
                           fmt::format("{} must be > 0 m", v));
        }
        *slot = v;
      }
      continue;
    }
    const std::vector<std::string> cells = split_csv_line(t);
    if (header.empty()) {
      header = cells;
      for (size_t i = 0; i < cells.size(); ++i) {
        if (cells[i] == "force_N") {
          col_f = static_cast<int>(i);
        } else if (cells[i] == "tip_displacement_m") {
          col_x = static_cast<int>(i);
        } else if (cells[i] == "tip_displacement_mm") {
          col_x = static_cast<int>(i);
          x_scale = 1e-3;
        } else {
          throw InputError(file, fmt::format("line {}: column {}", line, quoted(cells[i])),
                           "unknown column; allowed: force_N, tip_displacement_m | "
                           "tip_displacement_mm");
        }
      }
      if (col_f < 0 || col_x < 0) {
        throw InputError(file, fmt::format("line {}: header", line),
                         "needs columns force_N and tip_displacement_m (or _mm)");
      }
      continue;
    }
    if (cells.size() != header.size()) {
      throw InputError(
          file, fmt::format("line {}", line),
          fmt::format("has {} values, the header has {} columns", cells.size(), header.size()));
    }
    const double F = parse_number(cells[static_cast<size_t>(col_f)], file,
                                  fmt::format("line {}: force_N", line));
    const double x = x_scale * parse_number(cells[static_cast<size_t>(col_x)], file,
                                            fmt::format("line {}: {}", line, header[col_x]));
    if (F < 0 || x < 0) {
      throw InputError(file, fmt::format("line {}", line),
                       "force and displacement must be >= 0 (measured along the load)");
    }
    d.force.push_back(F);
    d.deflection.push_back(x);
    d.line.push_back(line);
  }
  if (header.empty()) {
    throw InputError(file, "header", "no header; expected force_N, tip_displacement_m");
  }
  return d;
}

CantileverData read_cantilever_data(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "file", "cannot open cantilever data file");
  return parse_cantilever_data(in, path);
}

namespace {

// "line 7: force_N, tip_displacement" for a point read from a file, "row 3: ..." otherwise.
std::string point_field(const CantileverData& d, std::size_t i) {
  return i < d.line.size() ? fmt::format("line {}: force_N, tip displacement", d.line[i])
                           : fmt::format("row {}: force, deflection", i + 1);
}

}  // namespace

double chain_compliance_factor(int segments) {
  const double n = segments;
  return 1.0 - 1.0 / (4.0 * n * n);
}

BendingIdentification identify_bending(const CantileverData& data, double length, int segments,
                                       std::optional<double> width,
                                       std::optional<double> thickness) {
  const std::string& f = data.source;
  if (!(length > 0) || !std::isfinite(length)) {
    throw InputError(f, "length",
                     fmt::format("{} m; must be > 0 (free length clamp to load)", length));
  }
  if (segments < 1 || segments > 1000000) {
    throw InputError(f, "segments", fmt::format("{}; must be 1..1000000", segments));
  }
  double sff = 0, sfx = 0;
  int loaded = 0;
  for (size_t i = 0; i < data.force.size(); ++i) {
    sff += data.force[i] * data.force[i];
    sfx += data.force[i] * data.deflection[i];
    loaded += data.force[i] > 0;
    if (!std::isfinite(sff) || !std::isfinite(sfx)) {
      throw InputError(f, point_field(data, i),
                       fmt::format("force {:g} N, tip displacement {:g} m: the least-squares "
                                   "sums overflow; give the values in N and m",
                                   data.force[i], data.deflection[i]));
    }
  }
  if (loaded < 1 || !(sfx > 0)) {
    throw InputError(f, "data", "need at least one point with force > 0 and deflection > 0");
  }
  BendingIdentification r;
  r.compliance = sfx / sff;
  double ss = 0;
  for (size_t i = 0; i < data.force.size(); ++i) {
    const double e = data.deflection[i] - r.compliance * data.force[i];
    ss += e * e;
    r.max_slope = std::max(r.max_slope, data.deflection[i] / length);
  }
  r.rms_residual = std::sqrt(ss / static_cast<double>(data.force.size()));
  r.length = length;
  r.EI_continuum = length * length * length / (3 * r.compliance);
  r.segments = segments;
  r.cell_length = length / segments;
  r.EI_chain = r.EI_continuum * chain_compliance_factor(segments);
  r.joint_stiffness = r.EI_chain / r.cell_length;
  if (width && thickness) {
    r.youngs_modulus = 12 * r.EI_continuum / (*width * std::pow(*thickness, 3));
    if (!std::isfinite(*r.youngs_modulus) || !(*r.youngs_modulus > 0)) {
      throw InputError(f, "width, thickness",
                       fmt::format("{:g} m, {:g} m give a Young's modulus of {:g} Pa; not a "
                                   "finite positive number",
                                   *width, *thickness, *r.youngs_modulus));
    }
  }
  for (const double v :
       {r.compliance, r.rms_residual, r.max_slope, r.EI_continuum, r.EI_chain, r.joint_stiffness}) {
    if (!std::isfinite(v) || !(r.compliance > 0)) {
      throw InputError(f, "data",
                       fmt::format("the fit gives compliance {:g} m/N, EI {:g} N m^2: not finite; "
                                   "check the units and magnitudes of force_N, tip displacement "
                                   "and the length {:g} m",
                                   r.compliance, r.EI_continuum, length));
    }
  }
  return r;
}

}  // namespace finseg
