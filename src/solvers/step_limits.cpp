#include "solvers/step_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace finseg {

namespace {

double step_count(double span, double h) {
  return std::ceil(span / h - 1e-9);
}

}  // namespace

long checked_step_count(double span, double h, double limit, const std::string& file,
                        const std::string& field) {
  const double n = step_count(span, h);
  if (!(n <= limit)) {
    throw InputError(file, field,
                     fmt::format("{:g} over {:g} gives {:.3g} steps; at most {:.0e} allowed "
                                 "(docs/scene.md, step limits)",
                                 h, span, n, limit));
  }
  return static_cast<long>(std::max(n, 0.0));
}

long solver_step_count(double span, double h, const std::string& solver) {
  const double n = step_count(span, h);
  if (!(n <= kMaxSteps)) {
    throw DivergenceError(
        fmt::format("{}: steps of {:.3g} over {:.3g} would be {:.3g} steps, "
                    "more than the {:.0e} allowed",
                    solver, h, span, n, kMaxSteps));
  }
  return static_cast<long>(std::max(n, 0.0));
}

void require_step_advances(double t, double h, const std::string& solver) {
  if (t + h == t || !std::isfinite(t + h)) {
    throw DivergenceError(
        fmt::format("{}: a step of {:.3g} does not advance t = {:.17g} (below its floating-point "
                    "resolution); the run cannot go on",
                    solver, h, t));
  }
}

}  // namespace finseg
