// Cell boundaries along a line cut into n cells, uniform or graded towards its ends
// (towards creases): shared by the strip generator and the crease-pattern subdivision.
#pragma once

#include <vector>

namespace finseg {

/// Relative lengths of n cells (sum n): uniform when `refinement` is 1 or no end is chosen,
/// else a geometric grading in which the cells at a chosen end are 1/refinement of the
/// middle (largest) cell.
std::vector<double> graded_cell_weights(int n, double refinement, bool toward_start,
                                        bool toward_end);

/// The n + 1 cell boundaries in [0, 1] (0 and 1 exact) of graded_cell_weights.
std::vector<double> graded_fractions(int n, double refinement, bool toward_start, bool toward_end);

/// Fractions of the given relative cell lengths (any positive scale), 0 and 1 exact.
std::vector<double> fractions_of_weights(const std::vector<double>& weights);

}  // namespace finseg
