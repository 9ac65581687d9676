#include "elements/membrane_cells.hpp"

#include <algorithm>
#include <vector>

#include "core/so3.hpp"
#include "elements/assembler.hpp"
#include "elements/cell_bodies.hpp"

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

// One side of a cell at the current state: its two points, their separation u and the force
// f = sign R_WB (m_k, 0) that the outer point takes (the inner one -f).
struct MembraneSideNow {
  int inner = -1, outer = -1;
  Attachment a_in, a_out;
  Vec3 u_W, f_W;
};

using Rows3 = Eigen::Matrix<double, 3, Eigen::Dynamic>;

// d x / d pose of a point with lever r: [I, -[r]x] (world-frame rotation increments).
void add_point_motion(Rows3& D, int col, const Vec3& r, double sign) {
  D.middleCols<3>(col) += sign * Mat3::Identity();
  D.middleCols<3>(col + 3) -= sign * hat<double>(r);
}

// A cell's dense work, kept between the cells of one evaluation (no allocation per
// cell where they have the same number of sides; three fixed rows: small products unrolled).
struct MembraneWork {
  Eigen::VectorXd delta, m;
  Eigen::MatrixXd T, QT, J;
  std::vector<Rows3> Du;
  Rows3 Df;
};

// The exact Jacobian of the cell's generalized forces (its own rows and those of every body
// its sides join), in w.J: the strain part -T^T Q T and the geometric part of the turning
// frames and levers, so that Newton stays quadratic where membrane forces are comparable to
// soft creases.
void cell_jacobian(const MembraneCellDef& cell, const Mat3& R_WB,
                   const std::vector<MembraneSideNow>& now, CellBodies& cb, MembraneWork& w) {
  const int n = static_cast<int>(now.size()), c = 6 * cb.local(cell.body);
  for (const MembraneSideNow& s : now) cb.local(s.inner), cb.local(s.outer);
  const int nq = 6 * cb.size();
  // T: d delta / d pose.
  w.T.setZero(2 * n, nq);
  w.Du.resize(n);
  for (int k = 0; k < n; ++k) {
    const MembraneSideNow& s = now[k];
    w.Du[k].setZero(3, nq);
    add_point_motion(w.Du[k], 6 * cb.local(s.inner), s.a_in.r_W, 1);
    add_point_motion(w.Du[k], 6 * cb.local(s.outer), s.a_out.r_W, -1);
    const Eigen::Matrix<double, 2, 3> read = cell.sides[k].sign * R_WB.transpose().topRows<2>();
    w.T.middleRows<2>(2 * k).noalias() = read * w.Du[k];
    w.T.block<2, 3>(2 * k, c + 3) += read * hat<double>(s.u_W);  // d(R^T u) = R^T [u]x dphi
  }
  w.QT.noalias() = cell.Q * w.T;
  w.J.setZero(nq, nq);
  for (int k = 0; k < n; ++k) {
    const MembraneSideNow& s = now[k];
    const int i = 6 * cb.local(s.inner), o = 6 * cb.local(s.outer);
    // df = -[f]x dphi_cell + sign R_WB (dm_k, 0).
    const Eigen::Matrix<double, 3, 2> lift = cell.sides[k].sign * R_WB.leftCols<2>();
    w.Df.noalias() = lift * w.QT.middleRows<2>(2 * k);
    w.Df.middleCols<3>(c + 3) -= hat<double>(s.f_W);
    const Mat3 F = hat<double>(s.f_W);
    w.J.middleRows<3>(i) -= w.Df;
    w.J.middleRows<3>(i + 3).noalias() -= hat<double>(s.a_in.r_W) * w.Df;
    w.J.block<3, 3>(i + 3, i + 3) -= F * hat<double>(s.a_in.r_W);
    w.J.middleRows<3>(o) += w.Df;
    w.J.middleRows<3>(o + 3).noalias() += hat<double>(s.a_out.r_W) * w.Df;
    w.J.block<3, 3>(o + 3, o + 3) += F * hat<double>(s.a_out.r_W);
    w.J.middleRows<3>(c + 3).noalias() += hat<double>(s.u_W) * w.Df;
    w.J.middleRows<3>(c + 3).noalias() -= F * w.Du[k];
  }
}

}  // namespace

void add_membrane_cells(const Model& model, const State& state, Assembler& as) {
  CellBodies cb;
  std::vector<MembraneSideNow> now;
  MembraneWork work;
  for (const MembraneCellDef& cell : model.membrane_cells) {
    const int n = static_cast<int>(cell.sides.size());
    const Mat3& R_WB = state.R_WB[cell.body];
    now.assign(n, MembraneSideNow{});
    Eigen::VectorXd& delta = work.delta;
    delta.resize(2 * n);
    for (int k = 0; k < n; ++k) {
      const ElementDef& e = model.elements[cell.sides[k].element];
      MembraneSideNow& s = now[k];
      s.inner = e.inner;
      s.outer = e.outer;
      s.a_in = attachment(state, e.inner, e.c_inner_B);
      s.a_out = attachment(state, e.outer, e.c_outer_B);
      s.u_W = s.a_in.x_W - s.a_out.x_W;
      delta.segment<2>(2 * k) = cell.sides[k].sign * (R_WB.transpose() * s.u_W).head<2>();
    }
    Eigen::VectorXd& m = work.m;
    m.noalias() = cell.Q * delta;
    as.add_energy(0.5 * delta.dot(m));
    // dE/du_W of side k is f_k: the inner point takes -f_k, the outer +f_k, and the cell,
    // whose frame reads u, the couple u x f_k.
    for (int k = 0; k < n; ++k) {
      MembraneSideNow& s = now[k];
      s.f_W = cell.sides[k].sign * (R_WB * Vec3(m[2 * k], m[2 * k + 1], 0));
      as.add(s.inner, {Vec3(-s.f_W), s.a_in.r_W.cross(-s.f_W)});
      as.add(s.outer, {s.f_W, s.a_out.r_W.cross(s.f_W)});
      as.add(cell.body, {Vec3::Zero(), s.u_W.cross(s.f_W)});
    }
    if (!as.want_jacobian()) continue;
    cb.clear();
    cell_jacobian(cell, R_WB, now, cb, work);
    for (int a = 0; a < cb.size(); ++a) {
      for (int b = 0; b < cb.size(); ++b)
        as.add_pose_block(cb.body(a), cb.body(b), work.J.block<6, 6>(6 * a, 6 * b));
    }
  }
}

}  // namespace finseg
