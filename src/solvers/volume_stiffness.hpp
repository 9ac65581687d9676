// The gas's stiffness against volume changes in Newton's matrix. A chamber whose pressure
// follows its volume adds -(dp/dV) a a^T to the stiffness -dF/dq, a = dV/dq (generalized: the
// pressure forces per pascal). Dense over the chamber's faces, it is kept out of the sparse
// matrix and added by the Sherman-Morrison-Woodbury formula (docs/gas.md, "Newton").
#pragma once

#include <Eigen/LU>
#include <Eigen/SparseCore>
#include <vector>

#include "model/model.hpp"
#include "model/state.hpp"
#include "solvers/linear_solve.hpp"

namespace finseg {

/// One rank-one term per chamber whose pressure depends on its volume.
struct VolumeStiffness {
  std::vector<Eigen::VectorXd> a;  ///< dV/dq: m^2 on translations, m^3 on rotations
  std::vector<double> k;           ///< -dp/dV, Pa/m^3
  bool empty() const { return a.empty(); }
};

/// The terms at `state` (its trial poses, its time and its chambers' last records).
VolumeStiffness volume_stiffness(const Model& model, const State& state);

/// Solves (A + s sum_k k_k a_k a_k^T) x = b with one sparse_solve of A for b and every a_k;
/// false where sparse_solve fails or the small capacitance system is singular.
bool solve_with_volume_stiffness(const Eigen::SparseMatrix<double>& A, double s,
                                 const VolumeStiffness& terms, const Eigen::VectorXd& b,
                                 Eigen::VectorXd& x);

/// Newton's matrix A + s sum_k k_k a_k a_k^T (or a symmetric S) factored once and solved
/// many times (modified Newton): the factor of A, Z = A^-1 a_k and the capacitance matrix's
/// LU are kept, so that a later solve is one back substitution and a k x k solve.
class KeptNewtonMatrix {
 public:
  /// Solves as solve_with_volume_stiffness does (LU unrefined: KeptFactorization) and keeps
  /// the factors.
  bool factor_and_solve(const Eigen::SparseMatrix<double>& A, double s, VolumeStiffness terms,
                        const Eigen::VectorXd& b, Eigen::VectorXd& x);
  /// Solves as sparse_solve(S, b, x) does and keeps the factor (no gas terms).
  bool factor_and_solve(const SymmetricMatrix& S, const Eigen::VectorXd& b, Eigen::VectorXd& x);
  /// Solves with the kept factors; false if none are kept or x is not finite.
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  bool valid() const { return factor_.valid(); }
  void clear() { factor_.clear(); }

 private:
  KeptFactorization factor_;
  std::vector<Eigen::VectorXd> a_;  // the gas terms' a_k (empty: none)
  Eigen::MatrixXd Z_;               // A^-1 a_k
  Eigen::FullPivLU<Eigen::MatrixXd> capacitance_;
};

}  // namespace finseg
