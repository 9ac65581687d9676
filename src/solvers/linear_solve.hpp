// Sparse linear solves for the Newton iterations. A system symmetric up to round-off goes to
// CHOLMOD (sparse Cholesky or L D L^T with a fill-reducing ordering), refined against the
// matrix; any other (friction, follower loads, a rotation Jacobian away from equilibrium), or
// one CHOLMOD cannot factor, to UMFPACK's LU (AMD on A + A^T). A SymmetricMatrix (symmetric by
// construction) goes to CHOLMOD without these checks. The symbolic analyses of the last few
// sparsity patterns are kept between solves. docs/solvers.md: when and why.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstddef>
#include <memory>

namespace finseg {

/// Which factorization solved the system.
enum class LinearSolvePath {
  Cholesky,  ///< CHOLMOD supernodal L L^T of the symmetric part (large, positive definite)
  LDLT,      ///< CHOLMOD simplicial L D L^T of the symmetric part (small, or indefinite)
  LU,        ///< UMFPACK's LU of the whole matrix (unsymmetric, or the symmetric path failed)
};

/// What a solve did, for tests and benchmarks.
struct LinearSolveInfo {
  LinearSolvePath path = LinearSolvePath::LU;
  double asymmetry = 0;  ///< ||A - A^T||_F / ||A||_F
  int refinements = 0;   ///< refinement steps taken on the symmetric path
};

/// A square sparse matrix symmetric by construction, in its values and in its stored pattern
/// (entry (i, j) stored iff (j, i) is), with finite entries and subnormals flushed to zero:
/// what CHOLMOD may be given directly. Made only by `symmetric_part_of` and `plus_diagonal`.
class SymmetricMatrix {
 public:
  /// (A + A^T) / 2 with the pattern of A + A^T. A not square or with a non-finite entry makes
  /// it unusable (`finite()` false: the solves refuse it).
  static SymmetricMatrix symmetric_part_of(const Eigen::SparseMatrix<double>& A);
  /// The same with A^T given (A's transpose, made once for this and asymmetry_ratio).
  static SymmetricMatrix symmetric_part_of(const Eigen::SparseMatrix<double>& A,
                                           const Eigen::SparseMatrix<double>& At);
  /// This matrix plus diag(d) (d finite; the pattern gains the diagonal).
  SymmetricMatrix plus_diagonal(const Eigen::VectorXd& d) const;
  /// The scale of a Levenberg-Marquardt shift mu diag(...): |S_ii|, raised to 1e-12 of the
  /// largest so that no zero diagonal entry goes unshifted.
  Eigen::VectorXd shift_scale() const;
  const Eigen::SparseMatrix<double>& matrix() const { return S_; }
  bool finite() const { return finite_; }
  Eigen::Index size() const { return S_.rows(); }

 private:
  SymmetricMatrix(Eigen::SparseMatrix<double> S, bool finite);
  Eigen::SparseMatrix<double> S_;
  bool finite_ = true;
};

/// Outcome of cholesky_solve.
enum class CholeskyStatus {
  Solved,               ///< positive definite: x solves S x = b
  NotPositiveDefinite,  ///< a pivot was not positive (indefinite or singular); x undefined
  Failed,               ///< S or b not finite; x undefined
};

/// Work and time of sparse_solve in the calling thread since the last reset (benchmarks).
struct LinearSolveCounters {
  long solves = 0, analyses = 0, factorizations = 0, lu_factorizations = 0;
  long indefinite = 0;   ///< not positive definite (L D L^T, LU or the caller's shift followed)
  long refinements = 0;  ///< refinement steps (each a matrix product and triangular solves)
  double analyse_s = 0;  ///< symbolic analyses (fill-reducing orderings)
  double factor_s = 0;   ///< numeric factorizations, failed ones included
  double total_s = 0;    ///< whole calls: also the checks, triangular solves and refinement
};

/// The work done between two readings of the counters (`later - earlier`).
LinearSolveCounters operator-(const LinearSolveCounters& later, const LinearSolveCounters& earlier);

/// This thread's counters; assign `{}` to reset.
LinearSolveCounters& linear_solve_counters();

/// Analyses kept per factorization: distinct sparsity patterns whose symbolic analysis is
/// reused (the static solver alternates the stiffness and its translation block).
inline constexpr int kCachedPatterns = 4;

/// Largest asymmetry ratio that counts as symmetric (assembly round-off); linear_solve.cpp.
inline constexpr double kSymmetricAsymmetry = 1e-13;

/// Symmetric part (A + A^T) / 2, with the pattern of A + A^T (also where values cancel);
/// `At` is A^T where the caller has it already.
Eigen::SparseMatrix<double> symmetric_part(const Eigen::SparseMatrix<double>& A);
Eigen::SparseMatrix<double> symmetric_part(const Eigen::SparseMatrix<double>& A,
                                           const Eigen::SparseMatrix<double>& At);

/// Asymmetry ratio ||A - A^T||_F / ||A||_F (0 for a zero matrix); `At` as above.
double asymmetry_ratio(const Eigen::SparseMatrix<double>& A);
double asymmetry_ratio(const Eigen::SparseMatrix<double>& A, const Eigen::SparseMatrix<double>& At);

/// Solves A x = b; returns false if A is singular (e.g. an unrestrained mechanism) or an
/// entry of A or b is not finite. Fills `info` when given.
bool sparse_solve(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                  Eigen::VectorXd& x, LinearSolveInfo* info = nullptr);

/// Solves A X = B for the columns of B with one factorization (each column as sparse_solve
/// would solve it alone, to the same bits).
bool sparse_solve(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B,
                  Eigen::MatrixXd& X, LinearSolveInfo* info = nullptr);

/// Solves S x = b as sparse_solve does, without the symmetry checks: CHOLMOD's L L^T (or,
/// small, L D L^T); an indefinite S is factored again as simplicial L D L^T, then LU.
bool sparse_solve(const SymmetricMatrix& S, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                  LinearSolveInfo* info = nullptr);

/// Solves S x = b only if S is positive definite (CHOLMOD L L^T, or L D L^T with positive D),
/// refined against S; otherwise reports it, so that the caller can shift S (static solver).
CholeskyStatus cholesky_solve(const SymmetricMatrix& S, const Eigen::VectorXd& b,
                              Eigen::VectorXd& x, LinearSolveInfo* info = nullptr);

/// Entries of a Cholesky factor from which a kept factorization solves with its copy in single
/// precision (32 MB of doubles: beyond the caches, where the solves are memory-bound).
inline constexpr std::size_t kSinglePrecisionEntries = std::size_t{1} << 22;

/// A factorization kept for further right-hand sides: factor once, solve many (the modified
/// Newton iteration, docs/solvers.md). The factoring solve takes the path sparse_solve takes;
/// no LU solve is refined, the factoring one included (the iteration that asks corrects an
/// inexact step), the symmetric path refines as sparse_solve does (its check that the factor
/// serves). Holds its own symbolic analyses. The later solves of a supernodal Cholesky factor
/// of at least kSinglePrecisionEntries entries run on its copy in single precision
/// (single_precision_factor.hpp).
class KeptFactorization {
 public:
  KeptFactorization();
  ~KeptFactorization();
  KeptFactorization(const KeptFactorization&) = delete;
  KeptFactorization& operator=(const KeptFactorization&) = delete;
  /// Solves A X = B on sparse_solve(A, B, X)'s path (its bits but for LU's refinement) and
  /// keeps the factor; false (none kept) where sparse_solve fails.
  bool factor_and_solve(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B,
                        Eigen::MatrixXd& X);
  /// Solves S X = B as sparse_solve(S, b, x) does for each column and keeps the factor.
  bool factor_and_solve(const SymmetricMatrix& S, const Eigen::MatrixXd& B, Eigen::MatrixXd& X);
  /// x = A^-1 b with the kept factor, unrefined (on the symmetric path: the factor of the
  /// symmetric part); false if none is kept or x is not finite.
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  bool valid() const;
  /// Forgets the factor (the analyses stay).
  void clear();
  /// From how many entries of a Cholesky factor on the later solves use single precision
  /// (for the next factorization; default kSinglePrecisionEntries).
  void single_precision_from(std::size_t entries);
  /// The later solves run in single precision.
  bool single_precision() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace finseg
