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

namespace {

// The right-hand sides [b, a_1 .. a_n] that one factorization of A solves together.
Eigen::MatrixXd with_terms(const Eigen::VectorXd& b, const VolumeStiffness& terms) {
  const auto n = static_cast<Eigen::Index>(terms.a.size());
  Eigen::MatrixXd B(b.size(), n + 1);
  B.col(0) = b;
  for (Eigen::Index j = 0; j < n; ++j) B.col(j + 1) = terms.a[static_cast<std::size_t>(j)];
  return B;
}

// (A + U C U^T)^-1 b = y - Z (C^-1 + U^T Z)^-1 U^T y from Y = A^-1 [b, U] = [y, Z]: x, with the
// capacitance matrix's LU left in `cap`; false where it is singular.
bool woodbury(const Eigen::MatrixXd& Y, double s, const VolumeStiffness& terms,
              Eigen::FullPivLU<Eigen::MatrixXd>& cap, Eigen::VectorXd& x) {
  const auto n = static_cast<Eigen::Index>(terms.a.size());
  const auto Z = Y.rightCols(n);
  Eigen::MatrixXd C(n, n);
  Eigen::VectorXd Uty(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::VectorXd& a_i = terms.a[static_cast<std::size_t>(i)];
    Uty[i] = a_i.dot(Y.col(0));
    for (Eigen::Index j = 0; j < n; ++j) C(i, j) = a_i.dot(Z.col(j));
    C(i, i) += 1 / (s * terms.k[static_cast<std::size_t>(i)]);
  }
  cap.compute(C);
  if (!cap.isInvertible()) return false;
  x = Y.col(0) - Z * cap.solve(Uty);
  return x.allFinite();
}

}  // namespace

bool solve_with_volume_stiffness(const Eigen::SparseMatrix<double>& A, double s,
                                 const VolumeStiffness& terms, const Eigen::VectorXd& b,
                                 Eigen::VectorXd& x) {
  if (terms.empty()) return sparse_solve(A, b, x);
  // One factorization of A for b and the a_k.
  Eigen::MatrixXd Y;
  if (!sparse_solve(A, with_terms(b, terms), Y)) return false;
  Eigen::FullPivLU<Eigen::MatrixXd> cap;
  return woodbury(Y, s, terms, cap, x);
}

bool KeptNewtonMatrix::factor_and_solve(const Eigen::SparseMatrix<double>& A, double s,
                                        VolumeStiffness terms, const Eigen::VectorXd& b,
                                        Eigen::VectorXd& x) {
  a_.clear();
  Eigen::MatrixXd Y;
  if (!factor_.factor_and_solve(A, with_terms(b, terms), Y)) return false;
  if (terms.empty()) {
    x = Y.col(0);
    return true;
  }
  // As solve_with_volume_stiffness, with Z and the capacitance matrix kept.
  if (!woodbury(Y, s, terms, capacitance_, x)) {
    factor_.clear();
    return false;
  }
  Z_ = Y.rightCols(static_cast<Eigen::Index>(terms.a.size()));
  a_ = std::move(terms.a);
  return true;
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
