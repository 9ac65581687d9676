#include "probes/deployment_peak.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace finseg {

DeploymentPeak find_deployment_peak(const std::vector<double>& x, const std::vector<double>& force,
                                    double window_lo, double window_hi, double drop) {
  if (x.size() != force.size()) throw std::invalid_argument("deployment peak: x and force sizes");
  const auto lo = static_cast<int>(std::lower_bound(x.begin(), x.end(), window_lo) - x.begin());
  const auto hi = static_cast<int>(std::upper_bound(x.begin(), x.end(), window_hi) - x.begin());
  DeploymentPeak best;
  if (hi - lo < 3) return best;
  const auto [fmin, fmax] = std::minmax_element(force.begin() + lo, force.begin() + hi);
  const double needed = drop * (*fmax - *fmin);
  if (!(needed > 0)) return best;
  // Right to left, a stack of "next higher" candidates; each entry carries the smallest
  // force from it up to (not including) the entry below it. Popping every entry not above
  // sample i gives the smallest force between i and the next sample above it: O(n).
  struct Entry {
    int index;
    double low;
  };
  std::vector<Entry> stack;
  for (int i = hi - 1; i >= lo; --i) {
    double low = INFINITY;
    while (!stack.empty() && force[stack.back().index] <= force[i]) {
      low = std::min(low, stack.back().low);
      stack.pop_back();
    }
    const bool rose_to_it = i > lo && force[i] >= force[i - 1];
    if (rose_to_it && force[i] - low >= needed && (!best.found || force[i] >= best.force)) {
      best = {true, force[i], x[i], i};
    }
    stack.push_back({i, std::min(force[i], low)});
  }
  return best;
}

int max_force_index(const std::vector<double>& x, const std::vector<double>& force,
                    double window_lo, double window_hi) {
  int best = -1;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] < window_lo || x[i] > window_hi) continue;
    if (best < 0 || force[i] > force[best]) best = static_cast<int>(i);
  }
  return best;
}

}  // namespace finseg
