#include "core/text.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace finseg {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

double parse_number(const std::string& text, const std::string& file, const std::string& field) {
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size()) {
    throw InputError(file, field, fmt::format("'{}' is not a number", text));
  }
  if (!std::isfinite(v)) throw InputError(file, field, "must be finite (NaN/inf given)");
  return v;
}

void require_positive(double v, const std::string& file, const std::string& field,
                      const char* unit) {
  if (!(v > 0) || !std::isfinite(v)) {
    throw InputError(file, field, fmt::format("{} {}; must be finite and > 0", v, unit));
  }
}

}  // namespace finseg
