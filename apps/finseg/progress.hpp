// Progress of a long command on stderr: percent, where the run is (simulated time or pull
// displacement), wall time and ETA. On a terminal one line is redrawn in place; otherwise
// (a log file, a batch job) a plain line is printed every few seconds.
#pragma once

#include <chrono>
#include <functional>
#include <string>

namespace finseg::cli {

enum class ProgressMode { Off, Terminal, Lines };

class ProgressLine {
 public:
  /// `where` returns the current position as text (e.g. "t = 0.42 s"); in Lines mode a line
  /// is printed at most every `every_s` seconds (and at the end).
  ProgressLine(ProgressMode mode, std::function<std::string()> where, double every_s = 5.0);
  void update(double fraction);  ///< terminal: redraws at most 10 times a second
  void finish();                 ///< ends the line (no-op if nothing was drawn)

 private:
  ProgressMode mode_;
  bool drawn_ = false;
  std::function<std::string()> where_;
  std::chrono::duration<double> every_;
  std::chrono::steady_clock::time_point start_, last_;
};

/// True when stderr is a terminal.
bool stderr_is_terminal();

/// Off when `quiet`, else Terminal or Lines depending on stderr.
ProgressMode progress_mode(bool quiet);

}  // namespace finseg::cli
