// A supernodal Cholesky factor kept in single precision for the solves that reuse it. At 10^4
// segments a factor is about 200 MB, read twice by every triangular solve, so these solves
// run at the memory's speed: a quarter of the lab cone's deploy went into the kept factor's
// solves (the modified Newton steps and the Krylov steps' preconditioner, docs/solvers.md).
// Half the bytes, half the time; what they solve is corrected by the iteration that asks
// (Newton's exact residual, GMRES on the exact matrix), as for any kept factor.
#pragma once

#include <Eigen/Core>
#include <vector>

struct cholmod_factor_struct;

namespace finseg {

/// The factor L of P A P^T = L L^T (CHOLMOD, supernodal, real) with its values rounded to
/// single precision, and the solves with it.
class SinglePrecisionFactor {
 public:
  /// Copies CHOLMOD's supernodal L L^T factor `L` (int indices, real values) to single
  /// precision; invalid() for any other factor, or one whose values single precision does
  /// not hold (a diagonal entry below FLT_MIN, an entry above FLT_MAX).
  static SinglePrecisionFactor of(const cholmod_factor_struct& L);
  /// x = A^-1 b by the two triangular solves in single precision (b, x: the original order);
  /// false if invalid or x is not finite.
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  bool valid() const { return n_ > 0; }

 private:
  // Supernode s: columns first .. first + cols - 1, its rows x cols block of L (column-major;
  // the diagonal block on top) and the row indices of the rows below the diagonal block.
  struct Supernode {
    int first, cols, rows;
    const float* L;
    const int* below;
  };
  Supernode supernode(int s) const;

  int n_ = 0;
  std::vector<int> super_, pi_, px_, rows_, perm_;  // CHOLMOD's supernodal layout
  std::vector<float> values_;
  mutable std::vector<float> y_, t_;  // work space of a solve
};

}  // namespace finseg
