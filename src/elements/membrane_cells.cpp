#include "elements/membrane_cells.hpp"

#include <algorithm>
#include <vector>

#include "core/so3.hpp"
#include "elements/assembler.hpp"

namespace finseg {
namespace {

// An element's two attachment points: world position and lever from the body's centroid.
struct Attachment {
  Vec3 x_W, r_W;
};

Attachment attachment(const State& s, int body, const Vec3& c_B) {
  const Vec3 r = s.R_WB[body] * c_B;
  return {s.p_W[body] + r, r};
}

// d(x of an attachment point)/d(pose of its body): [I, -[r]x].
Eigen::Matrix<double, 3, 6> point_motion(const Vec3& r) {
  Eigen::Matrix<double, 3, 6> J;
  J.leftCols<3>() = Mat3::Identity();
  J.rightCols<3>() = -hat<double>(r);
  return J;
}

}  // namespace

void add_membrane_cells(const Model& model, const State& state, Assembler& as) {
  std::vector<int> bodies;
  for (const MembraneCellDef& cell : model.membrane_cells) {
    const int n = static_cast<int>(cell.sides.size());
    const Mat3& R_WB = state.R_WB[cell.body];
    std::vector<Attachment> inner(n), outer(n);
    Eigen::VectorXd delta(2 * n);
    for (int k = 0; k < n; ++k) {
      const ElementDef& e = model.elements[cell.sides[k].element];
      inner[k] = attachment(state, e.inner, e.c_inner_B);
      outer[k] = attachment(state, e.outer, e.c_outer_B);
      const Vec3 u_W = inner[k].x_W - outer[k].x_W;
      delta.segment<2>(2 * k) = cell.sides[k].sign * (R_WB.transpose() * u_W).head<2>();
    }
    const Eigen::VectorXd m = cell.Q * delta;
    as.add_energy(0.5 * delta.dot(m));
    // dE/du_W of side k: f_k = sign R_WB (m_k, 0). The inner point takes -f_k, the outer +f_k,
    // and the cell, whose frame reads u, the couple u x f_k.
    for (int k = 0; k < n; ++k) {
      const ElementDef& e = model.elements[cell.sides[k].element];
      const Vec3 f = cell.sides[k].sign * (R_WB * Vec3(m[2 * k], m[2 * k + 1], 0));
      as.add(e.inner, {Vec3(-f), inner[k].r_W.cross(-f)});
      as.add(e.outer, {f, outer[k].r_W.cross(f)});
      const Vec3 u_W = inner[k].x_W - outer[k].x_W;
      as.add(cell.body, {Vec3::Zero(), u_W.cross(f)});
    }
    if (!as.want_jacobian()) continue;
    // d force / d pose = -T^T Q T, d delta = T d pose over the bodies the sides join.
    bodies.clear();
    auto local = [&bodies](int b) {
      const auto it = std::find(bodies.begin(), bodies.end(), b);
      if (it != bodies.end()) return static_cast<int>(it - bodies.begin());
      bodies.push_back(b);
      return static_cast<int>(bodies.size()) - 1;
    };
    for (const PlateCellSide& side : cell.sides) {
      local(model.elements[side.element].inner);
      local(model.elements[side.element].outer);
    }
    const int nb = static_cast<int>(bodies.size());
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(2 * n, 6 * nb);
    for (int k = 0; k < n; ++k) {
      const ElementDef& e = model.elements[cell.sides[k].element];
      const Eigen::Matrix<double, 2, 3> read = cell.sides[k].sign * R_WB.transpose().topRows<2>();
      T.block<2, 6>(2 * k, 6 * local(e.inner)) += read * point_motion(inner[k].r_W);
      T.block<2, 6>(2 * k, 6 * local(e.outer)) -= read * point_motion(outer[k].r_W);
    }
    const Eigen::MatrixXd K = -T.transpose() * cell.Q * T;
    for (int a = 0; a < nb; ++a) {
      for (int b = 0; b < nb; ++b)
        as.add_pose_block(bodies[a], bodies[b], K.block<6, 6>(6 * a, 6 * b));
    }
  }
}

}  // namespace finseg
