// Sparse linear solves for the Newton iterations. A system symmetric up to round-off goes to
// CHOLMOD (sparse Cholesky or L D L^T with a fill-reducing ordering), refined against the
// matrix; any other (friction, follower loads, a rotation Jacobian away from equilibrium), or
// one CHOLMOD cannot factor, to Eigen's SparseLU (COLAMD). Each factorization keeps its
// symbolic analysis between solves of one sparsity pattern. docs/solvers.md: when and why.
#pragma once

#include <Eigen/SparseCore>

namespace finseg {

/// Which factorization solved the system.
enum class LinearSolvePath {
  Cholesky,  ///< CHOLMOD supernodal L L^T of the symmetric part (large, positive definite)
  LDLT,      ///< CHOLMOD simplicial L D L^T of the symmetric part (small, or indefinite)
  LU,        ///< SparseLU of the whole matrix (unsymmetric, or the symmetric path failed)
};

/// What a solve did, for tests and benchmarks.
struct LinearSolveInfo {
  LinearSolvePath path = LinearSolvePath::LU;
  double asymmetry = 0;  ///< ||A - A^T||_F / ||A||_F
  int refinements = 0;   ///< refinement steps taken on the symmetric path
};

/// Work and time of sparse_solve in the calling thread since the last reset (benchmarks).
struct LinearSolveCounters {
  long solves = 0, analyses = 0, factorizations = 0, lu_factorizations = 0;
  long indefinite = 0;   ///< supernodal L L^T failed (not positive definite): simplicial L D L^T
  double analyse_s = 0;  ///< symbolic analyses (fill-reducing orderings)
  double factor_s = 0;   ///< numeric factorizations, failed ones included
  double total_s = 0;    ///< whole calls: also the checks, triangular solves and refinement
};

/// This thread's counters; assign `{}` to reset.
LinearSolveCounters& linear_solve_counters();

/// Largest asymmetry ratio that counts as symmetric (assembly round-off); linear_solve.cpp.
inline constexpr double kSymmetricAsymmetry = 1e-13;

/// Symmetric part (A + A^T) / 2, with the pattern of A + A^T (also where values cancel).
Eigen::SparseMatrix<double> symmetric_part(const Eigen::SparseMatrix<double>& A);

/// Asymmetry ratio ||A - A^T||_F / ||A||_F (0 for a zero matrix).
double asymmetry_ratio(const Eigen::SparseMatrix<double>& A);

/// Solves A x = b; returns false if A is singular (e.g. an unrestrained mechanism) or an
/// entry of A or b is not finite. Fills `info` when given.
bool sparse_solve(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                  Eigen::VectorXd& x, LinearSolveInfo* info = nullptr);

}  // namespace finseg
