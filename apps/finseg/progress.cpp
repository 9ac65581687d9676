#include "apps/finseg/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace finseg::cli {

bool stderr_is_terminal() {
  return isatty(fileno(stderr)) != 0;
}

ProgressMode progress_mode(bool quiet) {
  if (quiet) return ProgressMode::Off;
  return stderr_is_terminal() ? ProgressMode::Terminal : ProgressMode::Lines;
}

ProgressLine::ProgressLine(ProgressMode mode, std::function<std::string()> where, double every_s)
    : mode_(mode),
      where_(std::move(where)),
      every_(every_s),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void ProgressLine::update(double fraction) {
  if (mode_ == ProgressMode::Off) return;
  const auto now = std::chrono::steady_clock::now();
  const bool done = fraction >= 1;
  if (mode_ == ProgressMode::Terminal && drawn_ && now - last_ < std::chrono::milliseconds(100) &&
      !done) {
    return;
  }
  if (mode_ == ProgressMode::Lines && now - last_ < every_ && !done) return;
  last_ = now;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const std::string eta =
      fraction > 1e-6 ? fmt::format("{:.1f} s", wall * std::max(0.0, 1 - fraction) / fraction)
                      : "?";
  const std::string text =
      fmt::format("[{:5.1f}%] {}  wall {:.1f} s  ETA {}", 100 * fraction, where_(), wall, eta);
  if (mode_ == ProgressMode::Terminal) {
    fmt::print(stderr, "\r{}\033[K", text);
    drawn_ = true;
  } else {
    fmt::print(stderr, "finseg: {}\n", text);
  }
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (drawn_) fmt::print(stderr, "\n");
  drawn_ = false;
}

}  // namespace finseg::cli
