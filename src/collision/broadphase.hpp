// Broad phase: axis-aligned boxes of the segments and sweep-and-prune along the axis of
// largest spread. O(n log n + k) for n boxes and k overlapping pairs.
#pragma once

#include <utility>
#include <vector>

#include "core/types.hpp"

namespace finseg {

struct Aabb {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
};

/// Box of a thin plate (mid-surface rectangle of half sizes hx, hy, thickness radius r)
/// with centroid p_W and orientation R_WB, grown by `margin`.
Aabb plate_aabb(const Vec3& p_W, const Mat3& R_WB, const Vec3& size, double margin);

/// All pairs (i < j) of overlapping boxes, sorted. `scratch` keeps its capacity between
/// calls so that repeated detection does not allocate.
struct SweepAndPrune {
  std::vector<std::pair<int, int>> find_pairs(const std::vector<Aabb>& boxes);

 private:
  std::vector<std::pair<double, int>> order_;
  std::vector<int> active_;
};

}  // namespace finseg
