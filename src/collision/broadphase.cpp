// Sweep-and-prune broad phase.
#include "collision/broadphase.hpp"

#include <algorithm>

namespace finseg {

Aabb plate_aabb(const Vec3& p_W, const Mat3& R_WB, const Vec3& size, double margin) {
  // Extent of a box along world axis k: sum over body axes of |R(k, j)| * half size j.
  const Vec3 half = 0.5 * size;
  const Vec3 ext = R_WB.cwiseAbs() * half + Vec3::Constant(margin);
  return {p_W - ext, p_W + ext};
}

std::vector<std::pair<int, int>> SweepAndPrune::find_pairs(const std::vector<Aabb>& boxes) {
  std::vector<std::pair<int, int>> pairs;
  const int n = static_cast<int>(boxes.size());
  if (n < 2) return pairs;
  // Sweep along the axis where the box centres spread most.
  Vec3 mean = Vec3::Zero(), sq = Vec3::Zero();
  for (const Aabb& b : boxes) {
    const Vec3 c = 0.5 * (b.lo + b.hi);
    mean += c;
    sq += c.cwiseProduct(c);
  }
  mean /= n;
  const Vec3 var = sq / n - mean.cwiseProduct(mean);
  int axis = 0;
  if (var[1] > var[axis]) axis = 1;
  if (var[2] > var[axis]) axis = 2;
  const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;

  order_.resize(n);
  for (int i = 0; i < n; ++i) order_[i] = {boxes[i].lo[axis], i};
  std::sort(order_.begin(), order_.end());
  active_.clear();
  for (const auto& [lo, i] : order_) {
    const Aabb& bi = boxes[i];
    std::size_t keep = 0;
    for (std::size_t k = 0; k < active_.size(); ++k) {
      const int j = active_[k];
      const Aabb& bj = boxes[j];
      if (bj.hi[axis] < lo) continue;  // ended before this one starts: drop it
      active_[keep++] = j;
      if (bi.lo[a1] <= bj.hi[a1] && bj.lo[a1] <= bi.hi[a1] && bi.lo[a2] <= bj.hi[a2] &&
          bj.lo[a2] <= bi.hi[a2])
        pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
    active_.resize(keep);
    active_.push_back(i);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace finseg
