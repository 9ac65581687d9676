#include "solvers/volume_stiffness.hpp"

#include <Eigen/Dense>

#include "elements/assemble.hpp"
#include "elements/assembler.hpp"
#include "elements/chamber_gas.hpp"
#include "elements/chamber_surface.hpp"
#include "solvers/linear_solve.hpp"

namespace finseg {

VolumeStiffness volume_stiffness(const Model& model, const State& state) {
  VolumeStiffness out;
  for (std::size_t c = 0; c < model.chambers.size(); ++c) {
    const ChamberDef& def = model.chambers[c];
    if (def.gas == GasModel::Prescribed) continue;
    const double slope =
        gas_pressure_slope(def, state.chambers[c], state.t, surface_volume(state, def),
                           state.load_scale, state.quasi_static);
    if (slope == 0) continue;
    // a = dV/dq: the generalized pressure force of one pascal.
    BodyForces unit;
    unit.f_W.assign(model.bodies.size(), Vec3::Zero());
    unit.tau_W.assign(model.bodies.size(), Vec3::Zero());
    Assembler as(model, state, unit, nullptr);
    add_surface_pressure(state, def, 1.0, as);
    out.a.push_back(generalized_forces(model, unit));
    out.k.push_back(-slope);
  }
  return out;
}

bool solve_with_volume_stiffness(const Eigen::SparseMatrix<double>& A, double s,
                                 const VolumeStiffness& terms, const Eigen::VectorXd& b,
                                 Eigen::VectorXd& x) {
  const int n = static_cast<int>(terms.a.size());
  if (n == 0) return sparse_solve(A, b, x);
  // (A + U C U^T)^-1 b = y - Z (C^-1 + U^T Z)^-1 U^T y with y = A^-1 b, Z = A^-1 U: one
  // factorization of A for b and the a_k.
  Eigen::MatrixXd B(b.size(), n + 1), Y;
  B.col(0) = b;
  for (int j = 0; j < n; ++j) B.col(j + 1) = terms.a[j];
  if (!sparse_solve(A, B, Y)) return false;
  const auto Z = Y.rightCols(n);
  Eigen::MatrixXd cap(n, n);
  Eigen::VectorXd Uty(n);
  for (int i = 0; i < n; ++i) {
    Uty[i] = terms.a[i].dot(Y.col(0));
    for (int j = 0; j < n; ++j) cap(i, j) = terms.a[i].dot(Z.col(j));
    cap(i, i) += 1 / (s * terms.k[i]);
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(cap);
  if (!lu.isInvertible()) return false;
  x = Y.col(0) - Z * lu.solve(Uty);
  return x.allFinite();
}

bool KeptNewtonMatrix::factor_and_solve(const Eigen::SparseMatrix<double>& A, double s,
                                        VolumeStiffness terms, const Eigen::VectorXd& b,
                                        Eigen::VectorXd& x) {
  const int n = static_cast<int>(terms.a.size());
  a_.clear();
  Eigen::MatrixXd B(b.size(), n + 1), Y;
  B.col(0) = b;
  for (int j = 0; j < n; ++j) B.col(j + 1) = terms.a[j];
  if (!factor_.factor_and_solve(A, B, Y)) return false;
  if (n == 0) {
    x = Y.col(0);
    return true;
  }
  // As in solve_with_volume_stiffness, with Z and the capacitance matrix kept.
  Z_ = Y.rightCols(n);
  Eigen::MatrixXd cap(n, n);
  Eigen::VectorXd Uty(n);
  for (int i = 0; i < n; ++i) {
    Uty[i] = terms.a[i].dot(Y.col(0));
    for (int j = 0; j < n; ++j) cap(i, j) = terms.a[i].dot(Z_.col(j));
    cap(i, i) += 1 / (s * terms.k[i]);
  }
  capacitance_.compute(cap);
  if (!capacitance_.isInvertible()) {
    factor_.clear();
    return false;
  }
  a_ = std::move(terms.a);
  x = Y.col(0) - Z_ * capacitance_.solve(Uty);
  if (!x.allFinite()) factor_.clear();
  return valid();
}

bool KeptNewtonMatrix::factor_and_solve(const SymmetricMatrix& S, const Eigen::VectorXd& b,
                                        Eigen::VectorXd& x) {
  a_.clear();
  Eigen::MatrixXd X;
  if (!factor_.factor_and_solve(S, Eigen::MatrixXd(b), X)) return false;
  x = X.col(0);
  return true;
}

bool KeptNewtonMatrix::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  Eigen::VectorXd y;
  if (!factor_.solve(b, y)) return false;
  if (a_.empty()) {
    x = std::move(y);
    return true;
  }
  Eigen::VectorXd Uty(static_cast<Eigen::Index>(a_.size()));
  for (std::size_t i = 0; i < a_.size(); ++i) Uty[static_cast<Eigen::Index>(i)] = a_[i].dot(y);
  x = y - Z_ * capacitance_.solve(Uty);
  return x.allFinite();
}

}  // namespace finseg
