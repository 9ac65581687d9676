#include "core/rigid_fit.hpp"

#include <Eigen/SVD>
#include <cassert>

namespace finseg {

RigidFit best_rigid_fit(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  assert(from.size() == to.size() && !from.empty());
  RigidFit fit;
  for (std::size_t k = 0; k < from.size(); ++k) {
    fit.from_centroid += from[k];
    fit.to_centroid += to[k];
  }
  fit.from_centroid /= static_cast<double>(from.size());
  fit.to_centroid /= static_cast<double>(from.size());
  Mat3 H = Mat3::Zero();
  for (std::size_t k = 0; k < from.size(); ++k) {
    H += (from[k] - fit.from_centroid) * (to[k] - fit.to_centroid).transpose();
  }
  const Eigen::JacobiSVD<Mat3> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 D = Mat3::Identity();
  D(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1 : 1;
  fit.R = svd.matrixV() * D * svd.matrixU().transpose();
  return fit;
}

}  // namespace finseg
