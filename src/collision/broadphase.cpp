// Hashed uniform-grid broad phase.
#include "collision/broadphase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace finseg {

Aabb plate_aabb(const Vec3& p_W, const Mat3& R_WB, const BodyDef& body, double margin) {
  // The mid-surface polygon's box, grown by the half thickness in every direction. The
  // narrow phase takes two plates as touching where their mid-surfaces come closer than the
  // sum of the half thicknesses (at any angle), so the box is the polygon swept by a ball of
  // radius r, not the plate's own box: a tilted corner would otherwise enter with a finite
  // depth.
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec2& v : body.outline_B) {
    const Vec3 c = R_WB.col(0) * v.x() + R_WB.col(1) * v.y();
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  const Vec3 r = Vec3::Constant(0.5 * body.thickness + margin);
  return {p_W + lo - r, p_W + hi + r};
}

namespace {

// 21 bits per axis, offset so that negative cells stay positive.
std::uint64_t cell_key(std::int64_t ix, std::int64_t iy, std::int64_t iz) {
  constexpr std::int64_t off = 1 << 20, mask = (1 << 21) - 1;
  return (static_cast<std::uint64_t>((ix + off) & mask) << 42) |
         (static_cast<std::uint64_t>((iy + off) & mask) << 21) |
         static_cast<std::uint64_t>((iz + off) & mask);
}

}  // namespace

std::vector<std::pair<int, int>> BroadPhase::find_pairs(const std::vector<Aabb>& boxes) {
  std::vector<std::pair<int, int>> pairs;
  const int n = static_cast<int>(boxes.size());
  if (n < 2) return pairs;
  // Cell edge: median of the boxes' largest extents.
  extents_.resize(n);
  Vec3 lo_all = boxes[0].lo;
  for (int i = 0; i < n; ++i) {
    extents_[i] = (boxes[i].hi - boxes[i].lo).maxCoeff();
    lo_all = lo_all.cwiseMin(boxes[i].lo);
  }
  std::nth_element(extents_.begin(), extents_.begin() + n / 2, extents_.end());
  double cell = extents_[n / 2];
  if (!(cell > 0)) cell = 1e-9;
  auto index = [&](double x, double x0) {
    return static_cast<std::int64_t>(std::floor((x - x0) / cell));
  };
  entries_.clear();
  large_.clear();
  for (int i = 0; i < n; ++i) {
    const Aabb& b = boxes[i];
    std::int64_t lo[3], hi[3], count = 1;
    for (int k = 0; k < 3; ++k) {
      lo[k] = index(b.lo[k], lo_all[k]);
      hi[k] = index(b.hi[k], lo_all[k]);
      count *= hi[k] - lo[k] + 1;
    }
    if (count > 64 || hi[0] - lo[0] >= (1 << 20) || hi[1] - lo[1] >= (1 << 20)) {
      large_.push_back(i);
      continue;
    }
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) entries_.emplace_back(cell_key(x, y, z), i);
  }
  std::sort(entries_.begin(), entries_.end());
  for (std::size_t s = 0; s < entries_.size();) {
    std::size_t e = s + 1;
    while (e < entries_.size() && entries_[e].first == entries_[s].first) ++e;
    for (std::size_t p = s; p < e; ++p)
      for (std::size_t q = p + 1; q < e; ++q) {
        const int i = entries_[p].second, j = entries_[q].second;
        const Aabb& a = boxes[i];
        const Aabb& b = boxes[j];
        if (!boxes_overlap(a, b)) continue;
        // Report only from the cell holding the overlap's lower corner.
        const Vec3 c = a.lo.cwiseMax(b.lo);
        if (cell_key(index(c.x(), lo_all.x()), index(c.y(), lo_all.y()),
                     index(c.z(), lo_all.z())) != entries_[s].first)
          continue;
        pairs.emplace_back(std::min(i, j), std::max(i, j));
      }
    s = e;
  }
  // Large boxes against everything (each large-large pair once).
  std::vector<char> is_large(large_.empty() ? 0 : n, 0);
  for (int i : large_) is_large[i] = 1;
  for (int i : large_)
    for (int j = 0; j < n; ++j) {
      if (j == i || (is_large[j] && j < i)) continue;
      if (boxes_overlap(boxes[i], boxes[j])) pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace finseg
