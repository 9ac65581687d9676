#include "core/text.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.hpp"

namespace finseg {

std::string normalize_text(std::string text) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\r') {
      out += text[i];
    } else if (i + 1 == text.size() || text[i + 1] != '\n') {
      out += '\n';  // a lone CR (old Mac) ends a line; the CR of CRLF is dropped
    }
  }
  return out;
}

std::string read_text(std::istream& in) {
  std::ostringstream ss;
  ss << in.rdbuf();
  return normalize_text(ss.str());
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "file", std::string("cannot be read: ") + std::strerror(errno));
  std::string text = read_text(in);
  if (in.bad()) throw InputError(path, "file", "read error");
  return text;
}

std::string quoted(const std::string& s, std::size_t max_chars) {
  if (s.size() <= max_chars) return "'" + s + "'";
  std::size_t cut = max_chars;
  while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;  // whole UTF-8
  return fmt::format("'{}...' ({} characters)", s.substr(0, cut), s.size());
}

void refuse_subnormal(double v, const std::string& file, const std::string& field) {
  if (v != 0 && std::abs(v) < std::numeric_limits<double>::min()) {
    throw InputError(file, field,
                     fmt::format("{:g} is below the smallest normal number ({:g}); give 0 or a "
                                 "value of sensible magnitude",
                                 v, std::numeric_limits<double>::min()));
  }
}

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
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double v = text.empty() || std::isspace(static_cast<unsigned char>(text[0]))
                       ? 0
                       : std::strtod(begin, &end);
  if (end == nullptr || end == begin || static_cast<std::size_t>(end - begin) != text.size()) {
    throw InputError(file, field, quoted(text) + " is not a number");
  }
  if (!std::isfinite(v) || (errno == ERANGE && std::abs(v) > 1)) {
    throw InputError(file, field,
                     quoted(text) + ": must be finite (NaN, inf or beyond +-1.8e308 given)");
  }
  refuse_subnormal(v, file, field);
  if (errno == ERANGE && v == 0) {
    throw InputError(file, field, quoted(text) + " is below the smallest normal number; give 0");
  }
  return v;
}

void require_positive(double v, const std::string& file, const std::string& field,
                      const char* unit) {
  if (!(v > 0) || !std::isfinite(v)) {
    throw InputError(file, field, fmt::format("{} {}; must be finite and > 0", v, unit));
  }
}

}  // namespace finseg
