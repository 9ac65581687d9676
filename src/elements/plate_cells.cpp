#include "elements/plate_cells.hpp"

#include <vector>

#include "core/so3.hpp"
#include "elements/assembler.hpp"
#include "elements/bushing.hpp"
#include "elements/cell_bodies.hpp"
#include "elements/element_jacobian.hpp"

namespace finseg {
namespace {

// An element's relative rotation at the current state: its frame F (on its outer body), the
// relative rotation theta = log(R_FE) (F components, unwrapped through pi) and its inverse left
// Jacobian. The same for both cells the element is a side of, so each evaluation takes it once per
// element.
struct ElementRotation {
  Mat3 R_WF;
  Vec3 theta_F;
  Mat3 Jl_inv;
};

// One side of a cell at the current state: its element's rotation `rot`, and
// A = sign (R_BF theta).head<2> / theta, which reads the side's measurement Theta = A theta.
struct PlateSideNow {
  int inner = -1, outer = -1;
  const ElementRotation* rot = nullptr;
  Eigen::Matrix<double, 2, 3> A;
  Vec3 g_F;  // the couple's F components: Jl^-T A^T m_k (on the outer body; -R_WF g on the inner)
};

class ElementRotations {
 public:
  // Forgets what it took (a new state or model); keeps its storage.
  void reset(std::size_t elements) {
    done_.assign(elements, 0);
    rotations_.resize(elements);
  }
  const ElementRotation& of(const Model& model, const State& s, int element) {
    ElementRotation& r = rotations_[element];
    if (done_[element]) return r;
    const ElementDef& e = model.elements[element];
    r.R_WF = s.R_WB[e.outer] * e.R_outer_F;
    const Mat3 R_WE = s.R_WB[e.inner] * e.R_inner_E;
    r.theta_F = rotation_near<double>(r.R_WF.transpose() * R_WE, s.history[element].rotation_F);
    r.Jl_inv = left_jacobian_inverse(r.theta_F);
    done_[element] = 1;
    return r;
  }

 private:
  std::vector<char> done_;
  std::vector<ElementRotation> rotations_;
};

PlateSideNow side_now(const Model& model, const State& s, const PlateCellSide& side,
                      ElementRotations& rotations) {
  const ElementDef& e = model.elements[side.element];
  PlateSideNow n;
  n.inner = e.inner;
  n.outer = e.outer;
  n.rot = &rotations.of(model, s, side.element);
  n.A = side.sign * side.R_BF.topRows<2>();
  return n;
}

using Rows3 = Eigen::Matrix<double, 3, Eigen::Dynamic>;

// A cell's dense work, kept between the cells of one evaluation (no allocation per cell where
// they have the same number of sides; three fixed rows: small products unrolled).
struct PlateWork {
  double scale = 1;  // State::plate_correction_scale
  Eigen::VectorXd theta, m;
  Eigen::MatrixXd T, QT, J;
  std::vector<Rows3> dtheta;
  Rows3 dg, dtau;
};

// The exact Jacobian of the cell's couples over its local bodies' rotations (3 per body), in
// w.J. d theta_k = Jl^-1 R_WF^T (dphi_inner - dphi_outer); d g_k = H_k d theta_k + Jl^-T A^T
// dm_k with H_k the turning of Jl^-T at fixed A^T m_k; and R_WF turns with the outer body.
void cell_jacobian(const PlateCellDef& cell, const std::vector<PlateSideNow>& now, CellBodies& cb,
                   PlateWork& w) {
  const int n = static_cast<int>(now.size());
  for (const PlateSideNow& s : now) cb.local(s.inner), cb.local(s.outer);
  const int nr = 3 * cb.size();
  w.dtheta.resize(n);
  w.T.resize(2 * n, nr);
  for (int k = 0; k < n; ++k) {
    const PlateSideNow& s = now[k];
    const Mat3 U = s.rot->Jl_inv * s.rot->R_WF.transpose();
    w.dtheta[k].setZero(3, nr);
    w.dtheta[k].middleCols<3>(3 * cb.local(s.inner)) += U;
    w.dtheta[k].middleCols<3>(3 * cb.local(s.outer)) -= U;
    w.T.middleRows<2>(2 * k).noalias() = s.A * w.dtheta[k];
  }
  w.QT.noalias() = w.scale * cell.Q * w.T;
  w.J.setZero(nr, nr);
  for (int k = 0; k < n; ++k) {
    const PlateSideNow& s = now[k];
    const Vec3 m_k = s.A.transpose() * w.m.segment<2>(2 * k);
    const Eigen::Matrix<double, 3, 2> lift = s.rot->Jl_inv.transpose() * s.A.transpose();
    w.dg.noalias() = left_jacobian_inverse_transpose_derivative(s.rot->theta_F, m_k) * w.dtheta[k];
    w.dg.noalias() += lift * w.QT.middleRows<2>(2 * k);
    w.dtau.noalias() = -s.rot->R_WF * w.dg;  // the inner body's couple
    const int i = 3 * cb.local(s.inner), o = 3 * cb.local(s.outer);
    w.dtau.middleCols<3>(o) += hat<double>(Vec3(s.rot->R_WF * s.g_F));
    w.J.middleRows<3>(i) += w.dtau;
    w.J.middleRows<3>(o) -= w.dtau;
  }
}

}  // namespace

void add_plate_cells(const Model& model, const State& state, Assembler& as) {
  std::vector<PlateSideNow> now;
  CellBodies cb;
  PlateWork work;
  thread_local ElementRotations rotations;  // its storage serves every evaluation
  rotations.reset(model.elements.size());
  for (const PlateCellDef& cell : model.plate_cells) {
    work.scale = cell.correction ? state.plate_correction_scale : 1.0;
    const int n = static_cast<int>(cell.sides.size());
    now.clear();
    Eigen::VectorXd& theta = work.theta;
    theta.resize(2 * n);
    for (int k = 0; k < n; ++k) {
      now.push_back(side_now(model, state, cell.sides[k], rotations));
      theta.segment<2>(2 * k) = now[k].A * now[k].rot->theta_F;
    }
    Eigen::VectorXd& m = work.m;
    m.noalias() = work.scale * cell.Q * theta;
    as.add_energy(0.5 * theta.dot(m));
    // dE = sum_k m_k . A_k Jl_k^-1 R_WF^T (dphi_inner - dphi_outer): the inner body takes
    // -R_WF Jl^-T A^T m_k, the outer the opposite.
    for (int k = 0; k < n; ++k) {
      PlateSideNow& s = now[k];
      s.g_F = s.rot->Jl_inv.transpose() * (s.A.transpose() * m.segment<2>(2 * k));
      const Vec3 tau = -s.rot->R_WF * s.g_F;
      as.add(s.inner, {Vec3::Zero(), tau});
      as.add(s.outer, {Vec3::Zero(), Vec3(-tau)});
    }
    if (!as.want_jacobian()) continue;
    cb.clear();
    cell_jacobian(cell, now, cb, work);
    for (int a = 0; a < cb.size(); ++a) {
      for (int b = 0; b < cb.size(); ++b) {
        as.add_rotation_block(cb.body(a), cb.body(b), work.J.block<3, 3>(3 * a, 3 * b));
      }
    }
  }
}

}  // namespace finseg
