// Small text and value checks shared by the readers (crease data, test data, measured curves).
#pragma once

#include <istream>
#include <string>
#include <vector>

namespace finseg {

/// `text` with a leading UTF-8 byte-order mark removed and CRLF / lone CR line ends turned
/// into LF: every reader (scene YAML, crease, cantilever and measured-curve CSVs) goes
/// through this, so files saved by Windows tools read the same as any other.
std::string normalize_text(std::string text);

/// Whole stream, normalised (normalize_text).
std::string read_text(std::istream& in);

/// Whole file, normalised; InputError(path, "file", "cannot be read: ...") otherwise.
std::string read_text_file(const std::string& path);

/// `s` quoted for a message, cut to its first `max_chars` characters + "..." when longer.
std::string quoted(const std::string& s, std::size_t max_chars = 40);

/// Throws InputError(file, field, ...) when `v` is subnormal (0 < |v| < 2.2e-308): such
/// numbers are never a physical input and stall the sparse factorisation.
void refuse_subnormal(double v, const std::string& file, const std::string& field);

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
