// Broad phase: axis-aligned boxes of the segments and a uniform grid hashed by cell. Boxes
// go into every cell they cover (cell edge = median box extent); the entries are sorted by
// cell, pairs are tested inside each cell and reported only from the cell that holds the
// lower corner of their overlap, so each pair comes once. O(n log n) for n boxes of similar
// size; boxes covering more than 64 cells (a large clamped plate) are tested against all.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "model/model.hpp"

namespace finseg {

struct Aabb {
  Vec3 lo = Vec3::Zero();
  Vec3 hi = Vec3::Zero();
};

/// True when the boxes overlap (touching faces count).
inline bool boxes_overlap(const Aabb& a, const Aabb& b) {
  return a.lo.x() <= b.hi.x() && b.lo.x() <= a.hi.x() && a.lo.y() <= b.hi.y() &&
         b.lo.y() <= a.hi.y() && a.lo.z() <= b.hi.z() && b.lo.z() <= a.hi.z();
}

/// Box of the segment `body` at centroid p_W and orientation R_WB: its mid-surface polygon
/// grown by the half thickness in every direction (the reach of the narrow phase), then by
/// `margin` (m).
Aabb plate_aabb(const Vec3& p_W, const Mat3& R_WB, const BodyDef& body, double margin);

/// Finds all pairs (i < j) of overlapping boxes, sorted. Keeps its buffers between calls so
/// that repeated detection does not allocate.
class BroadPhase {
 public:
  std::vector<std::pair<int, int>> find_pairs(const std::vector<Aabb>& boxes);

 private:
  std::vector<std::pair<std::uint64_t, int>> entries_;
  std::vector<int> large_;
  std::vector<double> extents_;
};

}  // namespace finseg
