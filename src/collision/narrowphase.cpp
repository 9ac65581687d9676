// Sample grids and direction shares of the rounded-plate narrow phase.
#include "collision/narrowphase.hpp"

#include <algorithm>

namespace finseg {

std::vector<PlateSample> plate_samples(const PlateShape& s, int n) {
  n = std::max(n, 2);
  std::vector<PlateSample> out;
  out.reserve(static_cast<std::size_t>(n) * n);
  auto weight_1d = [n](int i) { return (i == 0 || i == n - 1) ? 0.5 / (n - 1) : 1.0 / (n - 1); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -s.hx + 2 * s.hx * i / (n - 1), y = -s.hy + 2 * s.hy * j / (n - 1);
      out.push_back({Vec3(x, y, 0), weight_1d(i) * weight_1d(j)});
    }
  return out;
}

DirectionShares direction_shares(const PlateShape& a, const PlateShape& b) {
  const double area_a = a.hx * a.hy, area_b = b.hx * b.hy;
  if (std::abs(area_a - area_b) <= 1e-6 * std::max(area_a, area_b)) return {0.5, 0.5};
  return area_a < area_b ? DirectionShares{1, 0} : DirectionShares{0, 1};
}

}  // namespace finseg
