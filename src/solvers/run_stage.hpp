// A solve made before a run on another model (the fold on a coarser cut of the pattern), kept
// for the run's summary.
#pragma once

#include <cstddef>
#include <string>

#include "solvers/solver.hpp"

namespace finseg {

/// What an earlier solve was, on how many segments, its statistics and wall time (s).
struct RunStage {
  std::string what;  ///< e.g. "fold on the coarse cut (pattern.subdivisions 2)"
  std::size_t segments = 0;
  SolverStats stats;
  double wall_seconds = 0;
};

}  // namespace finseg
