#include "elements/plate_cells.hpp"

#include <vector>

#include "core/so3.hpp"
#include "elements/assembler.hpp"
#include "elements/cell_bodies.hpp"
#include "elements/element_jacobian.hpp"

namespace finseg {
namespace {

// One side of a cell at the current state: the element's frame F (on its outer body), the
// relative rotation theta = log(R_FE) (F components) and its inverse left Jacobian, and
// A = sign (R_BF theta).head<2> / theta, which reads the side's measurement Theta = A theta.
struct PlateSideNow {
  int inner = -1, outer = -1;
  Mat3 R_WF;
  Vec3 theta_F;
  Mat3 Jl_inv;
  Eigen::Matrix<double, 2, 3> A;
  Vec3 g_F;  // the couple's F components: Jl^-T A^T m_k (on the outer body; -R_WF g on the inner)
};

PlateSideNow side_now(const Model& model, const State& s, const PlateCellSide& side) {
  const ElementDef& e = model.elements[side.element];
  PlateSideNow n;
  n.inner = e.inner;
  n.outer = e.outer;
  n.R_WF = s.R_WB[e.outer] * e.R_outer_F;
  const Mat3 R_WE = s.R_WB[e.inner] * e.R_inner_E;
  n.theta_F = so3_log<double>(n.R_WF.transpose() * R_WE);
  n.Jl_inv = left_jacobian_inverse(n.theta_F);
  n.A = side.sign * side.R_BF.topRows<2>();
  return n;
}

// The exact Jacobian of the cell's couples over its local bodies' rotations (3 per body).
// d theta_k = Jl^-1 R_WF^T (dphi_inner - dphi_outer); d g_k = H_k d theta_k + Jl^-T A^T dm_k
// with H_k the turning of Jl^-T at fixed A^T m_k; and R_WF turns with the outer body.
Eigen::MatrixXd cell_jacobian(const PlateCellDef& cell, const std::vector<PlateSideNow>& now,
                              const Eigen::VectorXd& m, CellBodies& cb) {
  const int n = static_cast<int>(now.size());
  for (const PlateSideNow& s : now) cb.local(s.inner), cb.local(s.outer);
  const int nr = 3 * cb.size();
  std::vector<Eigen::MatrixXd> dtheta(n, Eigen::MatrixXd::Zero(3, nr));
  Eigen::MatrixXd T(2 * n, nr);
  for (int k = 0; k < n; ++k) {
    const PlateSideNow& s = now[k];
    const Mat3 U = s.Jl_inv * s.R_WF.transpose();
    dtheta[k].middleCols<3>(3 * cb.local(s.inner)) += U;
    dtheta[k].middleCols<3>(3 * cb.local(s.outer)) -= U;
    T.middleRows<2>(2 * k) = s.A * dtheta[k];
  }
  const Eigen::MatrixXd QT = cell.Q * T;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nr, nr);
  for (int k = 0; k < n; ++k) {
    const PlateSideNow& s = now[k];
    const Vec3 w = s.A.transpose() * m.segment<2>(2 * k);
    const Eigen::MatrixXd dg =
        left_jacobian_inverse_transpose_derivative(s.theta_F, w) * dtheta[k] +
        s.Jl_inv.transpose() * s.A.transpose() * QT.middleRows<2>(2 * k);
    Eigen::MatrixXd dtau = -s.R_WF * dg;  // the inner body's couple
    const int i = 3 * cb.local(s.inner), o = 3 * cb.local(s.outer);
    dtau.middleCols<3>(o) += hat<double>(Vec3(s.R_WF * s.g_F));
    J.middleRows<3>(i) += dtau;
    J.middleRows<3>(o) -= dtau;
  }
  return J;
}

}  // namespace

void add_plate_cells(const Model& model, const State& state, Assembler& as) {
  std::vector<PlateSideNow> now;
  CellBodies cb;
  for (const PlateCellDef& cell : model.plate_cells) {
    const int n = static_cast<int>(cell.sides.size());
    now.clear();
    Eigen::VectorXd theta(2 * n);
    for (int k = 0; k < n; ++k) {
      now.push_back(side_now(model, state, cell.sides[k]));
      theta.segment<2>(2 * k) = now[k].A * now[k].theta_F;
    }
    const Eigen::VectorXd m = cell.Q * theta;
    as.add_energy(0.5 * theta.dot(m));
    // dE = sum_k m_k . A_k Jl_k^-1 R_WF^T (dphi_inner - dphi_outer): the inner body takes
    // -R_WF Jl^-T A^T m_k, the outer the opposite.
    for (int k = 0; k < n; ++k) {
      PlateSideNow& s = now[k];
      s.g_F = s.Jl_inv.transpose() * (s.A.transpose() * m.segment<2>(2 * k));
      const Vec3 tau = -s.R_WF * s.g_F;
      as.add(s.inner, {Vec3::Zero(), tau});
      as.add(s.outer, {Vec3::Zero(), Vec3(-tau)});
    }
    if (!as.want_jacobian()) continue;
    cb.clear();
    const Eigen::MatrixXd J = cell_jacobian(cell, now, m, cb);
    for (int a = 0; a < cb.size(); ++a) {
      for (int b = 0; b < cb.size(); ++b) {
        as.add_rotation_block(cb.body(a), cb.body(b), J.block<3, 3>(3 * a, 3 * b));
      }
    }
  }
}

}  // namespace finseg
