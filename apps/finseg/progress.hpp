// One-line progress display on a terminal: percent, where the run is (simulated time or
// pull displacement), wall time and ETA. Silent when stderr is not a terminal.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace finseg::cli {

class ProgressLine {
 public:
  /// `where` returns the current position as text (e.g. "t = 0.42 s").
  ProgressLine(bool enabled, std::function<std::string()> where);
  void update(double fraction);  ///< redraws at most 10 times a second
  void finish();                 ///< ends the line (no-op if nothing was drawn)

 private:
  bool enabled_, drawn_ = false;
  std::function<std::string()> where_;
  std::chrono::steady_clock::time_point start_, last_;
};

/// True when stderr is a terminal.
bool stderr_is_terminal();

}  // namespace finseg::cli
