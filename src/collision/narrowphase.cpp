// Sample grids and direction shares of the rounded-plate narrow phase.
#include "collision/narrowphase.hpp"

#include <algorithm>

namespace finseg {
namespace {

// n x n grid of the parallelogram q0 + a (q1 - q0) + b (q3 - q0), trapezoidal weights (sum 1).
void parallelogram_samples(const Vec2& q0, const Vec2& q1, const Vec2& q3, int n,
                           std::vector<PlateSample>& out) {
  auto weight_1d = [n](int i) { return (i == 0 || i == n - 1) ? 0.5 / (n - 1) : 1.0 / (n - 1); };
  const Vec2 ea = q1 - q0, eb = q3 - q0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2 x = q0 + ea * i / (n - 1) + eb * j / (n - 1);
      out.push_back({Vec3(x.x(), x.y(), 0), weight_1d(i) * weight_1d(j)});
    }
}

// Lattice of triangle (a, b, c) with n points per side; each point carries a third of the
// area of the lattice triangles around it (the integral of the linear interpolant: exact
// for linear functions). Weights in m^2.
void triangle_samples(const Vec2& a, const Vec2& b, const Vec2& c, int n,
                      std::vector<PlateSample>& out) {
  const int m = n - 1;  // lattice triangles per side
  const double third = 0.5 * std::abs(cross2d(b - a, c - a)) / (m * m) / 3;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i + j <= m; ++i) {
      // Lattice triangles touching point (i, j): up to 6 inside, fewer on the sides.
      int touching = 0;
      if (i + j < m) touching += 1;            // up triangle with (i, j) as its corner 0
      if (i > 0) touching += 1 + (i + j < m);  // up with corner 1, down with corner 0
      if (j > 0) touching += 1 + (i + j < m);  // up with corner 2, down with corner 2
      if (i > 0 && j > 0) touching += 1;       // down with corner 1
      const Vec2 x = a + (b - a) * i / m + (c - a) * j / m;
      out.push_back({Vec3(x.x(), x.y(), 0), touching * third});
    }
}

}  // namespace

std::vector<PlateSample> plate_samples(const PlateShape& s, int n) {
  n = std::max(n, 2);
  const Outline& v = *s.outline;
  std::vector<PlateSample> out;
  if (v.size() == 4 && (v[2] - v[3] - v[1] + v[0]).isZero(0)) {
    parallelogram_samples(v[0], v[1], v[3], n, out);
    return out;
  }
  for (std::size_t k = 1; k + 1 < v.size(); ++k) triangle_samples(v[0], v[k], v[k + 1], n, out);
  double total = 0;
  for (const PlateSample& p : out) total += p.weight;
  for (PlateSample& p : out) p.weight /= total;
  return out;
}

DirectionShares direction_shares(const PlateShape& a, const PlateShape& b) {
  if (std::abs(a.area - b.area) <= 1e-6 * std::max(a.area, b.area)) return {0.5, 0.5};
  return a.area < b.area ? DirectionShares{1, 0} : DirectionShares{0, 1};
}

}  // namespace finseg
