// Crease data files (docs/crease-data.md): measured moment against opening angle, one curve
// per crease pressing time and opening count. Reading validates every line and averages
// repeats of one condition; writing produces a file that read_crease_data accepts.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace finseg {

/// One measured moment-angle curve (after averaging repeats).
struct CreaseCurve {
  double pressing_time = 0;       ///< s the crease was pressed
  int opening = 1;                ///< 1 = first opening of the crease, 2 = second, ...
  std::vector<double> angle_deg;  ///< opening angle theta, strictly increasing, deg
  std::vector<double> moment;     ///< moment holding the crease open at that angle, N m, >= 0
  int repeats = 1;                ///< measurements averaged into this curve
  int first_line = 0;             ///< line of its first row, for messages
};

/// All curves of one file, sorted by pressing time, then opening.
struct CreaseData {
  std::string source;  ///< file name for messages
  std::vector<CreaseCurve> curves;
  std::vector<double> pressing_times() const;  ///< distinct, ascending
  /// Curves of one pressing time (exact match), ascending opening 1..n.
  std::vector<const CreaseCurve*> curves_at(double pressing_time) const;
};

/// Reads and validates a crease data file; throws InputError("file", "line N: column", ...).
/// `default_lever` (m) is used for force_N columns when the file has no lever_m column.
CreaseData read_crease_data(const std::string& path,
                            std::optional<double> default_lever = std::nullopt);
CreaseData parse_crease_data(std::istream& in, const std::string& source,
                             std::optional<double> default_lever = std::nullopt);

/// Writes curves as angle_deg, moment_Nm, pressing_time_s, opening (17 significant digits).
/// `comment` lines are written first, each prefixed with "# ".
void write_crease_data(const std::string& path, const CreaseData& data,
                       const std::vector<std::string>& comment = {});
void write_crease_data(std::ostream& out, const CreaseData& data,
                       const std::vector<std::string>& comment = {});

}  // namespace finseg
