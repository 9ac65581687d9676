// Small text and value checks shared by the readers (crease data, test data, measured curves).
#pragma once

#include <string>
#include <vector>

namespace finseg {

/// `s` without leading and trailing blanks (space, tab, carriage return).
std::string trim(const std::string& s);

/// Comma-separated cells of one line, each trimmed; a trailing comma gives an empty cell.
std::vector<std::string> split_csv_line(const std::string& line);

/// The whole of `text` as a finite number; otherwise InputError(file, field, ...).
double parse_number(const std::string& text, const std::string& file, const std::string& field);

/// Throws InputError(file, field, "<v> <unit>; must be finite and > 0") unless 0 < v < inf.
void require_positive(double v, const std::string& file, const std::string& field,
                      const char* unit);

}  // namespace finseg
