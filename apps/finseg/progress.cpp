#include "apps/finseg/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace finseg::cli {

bool stderr_is_terminal() {
  return isatty(fileno(stderr)) != 0;
}

ProgressLine::ProgressLine(bool enabled, std::function<std::string()> where)
    : enabled_(enabled),
      where_(std::move(where)),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void ProgressLine::update(double fraction) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_ < std::chrono::milliseconds(100) && fraction < 1) return;
  last_ = now;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const std::string eta =
      fraction > 1e-6 ? fmt::format("{:.1f} s", wall * (1 - fraction) / fraction) : "?";
  fmt::print(stderr, "\r[{:5.1f}%] {}  wall {:.1f} s  ETA {}\033[K", 100 * fraction, where_(), wall,
             eta);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressLine::finish() {
  if (drawn_) fmt::print(stderr, "\n");
  drawn_ = false;
}

}  // namespace finseg::cli
