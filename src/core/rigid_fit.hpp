// The rigid motion that takes one set of points nearest to another (Kabsch): where a face of a
// pattern sits in two placements of it.
#pragma once

#include <vector>

#include "core/types.hpp"

namespace finseg {

/// x -> to_centroid + R (x - from_centroid): a proper rotation R (no reflection).
struct RigidFit {
  Mat3 R = Mat3::Identity();
  Vec3 from_centroid = Vec3::Zero(), to_centroid = Vec3::Zero();
  Vec3 apply(const Vec3& x) const { return to_centroid + R * (x - from_centroid); }
};

/// The rigid motion minimising sum |apply(from[k]) - to[k]|^2 (Kabsch); the point lists have
/// the same, non-zero length.
RigidFit best_rigid_fit(const std::vector<Vec3>& from, const std::vector<Vec3>& to);

}  // namespace finseg
