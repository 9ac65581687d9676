#include "core/grading.hpp"

#include <algorithm>
#include <cmath>

namespace finseg {

std::vector<double> graded_cell_weights(int n, double refinement, bool toward_start,
                                        bool toward_end) {
  std::vector<double> w(std::max(n, 0), 1.0);
  if (refinement == 1.0 || n < 2 || !(toward_start || toward_end)) return w;
  for (int j = 0; j < n; ++j) {
    // Distance in cells from the nearest chosen end, relative to half the line.
    const double da = toward_start ? j : n;
    const double db = toward_end ? n - 1 - j : n;
    const double d = std::min(da, db) / std::max(1.0, (n - 1) / 2.0);
    w[j] = std::pow(refinement, std::min(1.0, d)) / refinement;
  }
  return w;
}

std::vector<double> fractions_of_weights(const std::vector<double>& weights) {
  double total = 0;
  for (double x : weights) total += x;
  std::vector<double> f{0.0};
  for (double x : weights) f.push_back(f.back() + x / total);
  f.back() = 1.0;
  return f;
}

std::vector<double> graded_fractions(int n, double refinement, bool toward_start, bool toward_end) {
  if (refinement == 1.0 || !(toward_start || toward_end)) {
    std::vector<double> f;  // exactly k / n
    for (int k = 0; k <= n; ++k) f.push_back(static_cast<double>(k) / n);
    return f;
  }
  return fractions_of_weights(graded_cell_weights(n, refinement, toward_start, toward_end));
}

}  // namespace finseg
