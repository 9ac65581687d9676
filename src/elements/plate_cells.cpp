#include "elements/plate_cells.hpp"

#include <algorithm>
#include <vector>

#include "core/so3.hpp"
#include "elements/assembler.hpp"

namespace finseg {
namespace {

// World orientation of an element's frame F (on its outer body) and its rotation vector
// theta = log(R_FE), F components.
struct SideRotation {
  Mat3 R_WF;
  Vec3 theta_F;
};

SideRotation side_rotation(const ElementDef& e, const State& s) {
  const Mat3 R_WE = s.R_WB[e.inner] * e.R_inner_E;
  const Mat3 R_WF = s.R_WB[e.outer] * e.R_outer_F;
  return {R_WF, so3_log<double>(R_WF.transpose() * R_WE)};
}

}  // namespace

void add_plate_cells(const Model& model, const State& state, Assembler& as) {
  std::vector<SideRotation> rot;
  std::vector<int> bodies;  // the cell's bodies, in first-seen order
  for (const PlateCellDef& cell : model.plate_cells) {
    const int n = static_cast<int>(cell.sides.size());
    rot.clear();
    Eigen::VectorXd theta(2 * n);
    for (int k = 0; k < n; ++k) {
      const PlateCellSide& side = cell.sides[k];
      rot.push_back(side_rotation(model.elements[side.element], state));
      theta.segment<2>(2 * k) = (side.sign * side.R_BF * rot[k].theta_F).head<2>();
    }
    const Eigen::VectorXd m = cell.Q * theta;
    as.add_energy(0.5 * theta.dot(m));
    // dE = sum_k m_k . dTheta_k, dTheta_k = sign R_BF R_WF^T (dphi_inner - dphi_outer).
    std::vector<Mat3> to_theta(n);  // dTheta_k (padded to 3) / dphi_inner, world
    for (int k = 0; k < n; ++k) {
      const PlateCellSide& side = cell.sides[k];
      const ElementDef& e = model.elements[side.element];
      to_theta[k] = side.sign * side.R_BF * rot[k].R_WF.transpose();
      const Vec3 tau = -to_theta[k].transpose() * Vec3(m[2 * k], m[2 * k + 1], 0);
      as.add(e.inner, {Vec3::Zero(), tau});
      as.add(e.outer, {Vec3::Zero(), Vec3(-tau)});
    }
    if (!as.want_jacobian()) continue;
    // d tau / d phi = -T^T Q T over the bodies the sides join, dTheta = T dphi (+ on a side's
    // inner body, - on its outer): one block per pair of bodies.
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
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(2 * n, 3 * nb);
    for (int k = 0; k < n; ++k) {
      const ElementDef& e = model.elements[cell.sides[k].element];
      T.block<2, 3>(2 * k, 3 * local(e.inner)) += to_theta[k].topRows<2>();
      T.block<2, 3>(2 * k, 3 * local(e.outer)) -= to_theta[k].topRows<2>();
    }
    const Eigen::MatrixXd K = -T.transpose() * cell.Q * T;
    for (int a = 0; a < nb; ++a) {
      for (int b = 0; b < nb; ++b) {
        as.add_rotation_block(bodies[a], bodies[b], K.block<3, 3>(3 * a, 3 * b));
      }
    }
  }
}

}  // namespace finseg
