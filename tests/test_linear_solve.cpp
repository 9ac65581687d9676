// sparse_solve on manufactured systems A x = b with x known: the 5-point Laplacian of a square
// grid (closed-form eigenvalues 4 - 2 cos(pi i/(n+1)) - 2 cos(pi j/(n+1))), shifted to be
// positive definite or indefinite, with a skew part added to make it unsymmetric. The error
// bound is the classical one: relative error <= condition number * backward error, with the
// solver's accepted backward error (1e-14) and the condition number from the eigenvalues.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "solvers/linear_solve.hpp"

namespace finseg {
namespace linear_solve_test {

using SpMat = Eigen::SparseMatrix<double>;

// What sparse_solve accepts (componentwise, linear_solve.cpp; it bounds the normwise one).
constexpr double kBackwardError = 1e-14;

// Laplacian of an n x n grid (Dirichlet), minus sigma I, plus `skew` times the upwind
// convection operator's skew part (x-direction differences).
SpMat grid_matrix(int n, double sigma, double skew = 0) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [n](int i, int j) { return i * n + j; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      t.emplace_back(id(i, j), id(i, j), 4.0 - sigma);
      if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -1.0 + skew);
      if (i + 1 < n) t.emplace_back(id(i, j), id(i + 1, j), -1.0 - skew);
      if (j > 0) t.emplace_back(id(i, j), id(i, j - 1), -1.0);
      if (j + 1 < n) t.emplace_back(id(i, j), id(i, j + 1), -1.0);
    }
  }
  SpMat A(n * n, n * n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// Sorted eigenvalues of the n x n grid Laplacian (closed form).
std::vector<double> laplacian_eigenvalues(int n) {
  std::vector<double> lambda;
  for (int i = 1; i <= n; ++i) {
    for (int j = 1; j <= n; ++j) {
      lambda.push_back(4 - 2 * std::cos(std::numbers::pi * i / (n + 1)) -
                       2 * std::cos(std::numbers::pi * j / (n + 1)));
    }
  }
  std::sort(lambda.begin(), lambda.end());
  return lambda;
}

// 2-norm condition number of the symmetric L - sigma I.
double condition_number(int n, double sigma) {
  double lo = INFINITY, hi = 0;
  for (const double l : laplacian_eigenvalues(n)) {
    lo = std::min(lo, std::abs(l - sigma));
    hi = std::max(hi, std::abs(l - sigma));
  }
  return hi / lo;
}

Eigen::VectorXd known_solution(int size) {
  Eigen::VectorXd x(size);
  for (int k = 0; k < size; ++k) x[k] = std::sin(0.37 * k) + 0.5 * std::cos(1.3 * k * k);
  return x;
}

double relative_error(const Eigen::VectorXd& x, const Eigen::VectorXd& x_true) {
  return (x - x_true).norm() / x_true.norm();
}

void expect_solves(const SpMat& A, double cond, LinearSolveInfo& info) {
  const Eigen::VectorXd x_true = known_solution(static_cast<int>(A.rows()));
  const Eigen::VectorXd b = A * x_true;
  Eigen::VectorXd x;
  ASSERT_TRUE(sparse_solve(A, b, x, &info));
  EXPECT_LT((A * x - b).norm() / b.norm(), 1e-12);
  // 2-norm bound from the infinity-norm backward error: a factor sqrt(size) for the norms.
  EXPECT_LT(relative_error(x, x_true), std::sqrt(double(A.rows())) * cond * kBackwardError);
}

TEST(LinearSolve, SymmetricPositiveDefiniteTakesTheCholmodPath) {
  for (const int n : {8, 120}) {  // CHOLMOD's simplicial L D L^T, then its supernodal L L^T
    const double sigma = -0.5;
    LinearSolveInfo info;
    expect_solves(grid_matrix(n, sigma), condition_number(n, sigma), info);
    EXPECT_NE(info.path, LinearSolvePath::LU) << n;
    EXPECT_EQ(info.asymmetry, 0) << n;
    EXPECT_LE(info.refinements, 1) << n;
  }
  const double cond = condition_number(120, -0.5);
  EXPECT_LT(cond, 20);  // so the bound above is a 1e-10 one at most
}

TEST(LinearSolve, LargeSymmetricPositiveDefiniteUsesCholesky) {
  LinearSolveInfo info;
  expect_solves(grid_matrix(120, -0.5), condition_number(120, -0.5), info);
  EXPECT_EQ(info.path, LinearSolvePath::Cholesky);
}

TEST(LinearSolve, SymmetricIndefiniteUsesLdlt) {
  for (const int n : {8, 120}) {
    // sigma halfway between two eigenvalues in the lower part of the spectrum: several
    // negative pivots, a moderate condition number.
    const std::vector<double> lambda = laplacian_eigenvalues(n);
    const double sigma = 0.5 * (lambda[3] + lambda[4]);
    const double cond = condition_number(n, sigma);
    ASSERT_LT(cond, 1e5) << n;
    LinearSolveInfo info;
    expect_solves(grid_matrix(n, sigma), cond, info);
    EXPECT_EQ(info.path, LinearSolvePath::LDLT) << n;
  }
}

TEST(LinearSolve, RoundOffAsymmetryTakesTheSymmetricPathAndIsRefined) {
  // A skew part at the level of assembly round-off (1e-15 relative) is symmetric for the
  // solver: CHOLMOD on the symmetric part, refined against the whole matrix.
  const SpMat A = grid_matrix(30, -0.5, 1e-15);
  LinearSolveInfo info;
  // The skew part changes the condition number by a relative 1e-15 at most; bound with 2x.
  expect_solves(A, 2 * condition_number(30, -0.5), info);
  EXPECT_NE(info.path, LinearSolvePath::LU);
  EXPECT_GT(info.asymmetry, 0);
}

TEST(LinearSolve, SlightAsymmetryBeyondRoundOffUsesLu) {
  // A skew part of 1e-4 (relative), like a Newton matrix of the sheet away from equilibrium.
  const SpMat A = grid_matrix(30, -0.5, 1e-4);
  LinearSolveInfo info;
  expect_solves(A, 2 * condition_number(30, -0.5), info);
  EXPECT_EQ(info.path, LinearSolvePath::LU);
  EXPECT_GT(info.asymmetry, 1e-6);
}

TEST(LinearSolve, UnsymmetricUsesLu) {
  // Strong convection (skew 0.5): far from symmetric.
  const SpMat A = grid_matrix(12, -0.5, 0.5);
  const Eigen::VectorXd x_true = known_solution(static_cast<int>(A.rows()));
  const Eigen::VectorXd b = A * x_true;
  Eigen::VectorXd x;
  LinearSolveInfo info;
  ASSERT_TRUE(sparse_solve(A, b, x, &info));
  EXPECT_EQ(info.path, LinearSolvePath::LU);
  EXPECT_GT(info.asymmetry, 0.1);
  EXPECT_LT((A * x - b).norm() / b.norm(), 1e-12);
  // Its singular values are not in closed form; the dense solution is the reference.
  const Eigen::MatrixXd Ad(A);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Ad);
  const double cond = svd.singularValues()(0) / svd.singularValues().tail(1)(0);
  EXPECT_LT(relative_error(x, x_true), std::sqrt(double(A.rows())) * cond * kBackwardError);
}

TEST(LinearSolve, SingularMatrixIsRefused) {
  // An unrestrained degree of freedom: its row and column are zero.
  for (const double skew : {0.0, 0.5}) {
    SpMat A = grid_matrix(6, -0.5, skew);
    A.prune([](int i, int j, double) { return i != 7 && j != 7; });
    Eigen::VectorXd x;
    EXPECT_FALSE(sparse_solve(A, Eigen::VectorXd::Ones(A.rows()), x)) << skew;
  }
}

TEST(LinearSolve, NonFiniteEntriesAreRefused) {
  SpMat A = grid_matrix(4, -0.5);
  Eigen::VectorXd x, b = Eigen::VectorXd::Ones(A.rows());
  b[3] = NAN;
  EXPECT_FALSE(sparse_solve(A, b, x));
  A.coeffRef(2, 2) = INFINITY;
  EXPECT_FALSE(sparse_solve(A, Eigen::VectorXd::Ones(A.rows()), x));
}

TEST(LinearSolve, RepeatedSolvesAreBitIdentical) {
  // The same system solved again (analysis reused) and after another pattern in between.
  const SpMat A = grid_matrix(120, 0.3), other = grid_matrix(10, 0.0);
  const Eigen::VectorXd b = A * known_solution(static_cast<int>(A.rows()));
  Eigen::VectorXd x1, x2, x3, y;
  ASSERT_TRUE(sparse_solve(A, b, x1));
  ASSERT_TRUE(sparse_solve(A, b, x2));
  ASSERT_TRUE(sparse_solve(other, Eigen::VectorXd::Ones(other.rows()), y));
  ASSERT_TRUE(sparse_solve(A, b, x3));
  EXPECT_EQ(x1, x2);
  EXPECT_EQ(x1, x3);
}

TEST(LinearSolve, AsymmetryRatio) {
  SpMat A(2, 2);
  A.insert(0, 0) = 3;
  A.insert(0, 1) = 1;
  A.insert(1, 0) = 0;  // stored zero: the pattern stays symmetric, the values do not
  A.insert(1, 1) = 3;
  // ||A - A^T||_F = sqrt(1 + 1), ||A||_F = sqrt(9 + 1 + 9).
  EXPECT_DOUBLE_EQ(asymmetry_ratio(A), std::sqrt(2.0 / 19.0));
  EXPECT_EQ(asymmetry_ratio(SpMat(3, 3)), 0);
}

// The symmetric part of the convected grid operator is the Laplacian (the convection's skew
// part cancels exactly), and as an exactly symmetric matrix it takes the Cholesky path.
TEST(LinearSolve, SymmetricPartDropsTheSkewPart) {
  const SpMat A = grid_matrix(12, -0.5, 0.3), L = grid_matrix(12, -0.5);
  const SpMat S = symmetric_part(A);
  EXPECT_EQ(asymmetry_ratio(S), 0);
  EXPECT_EQ(Eigen::MatrixXd(S), Eigen::MatrixXd(L));
  LinearSolveInfo info;
  expect_solves(S, condition_number(12, -0.5), info);
  EXPECT_NE(info.path, LinearSolvePath::LU);
}

// A matrix symmetric in value but not in stored pattern (an entry stored above the diagonal,
// its mirror not stored: an explicit zero, as assembly can leave): its SymmetricMatrix stores
// both, is exactly symmetric, and CHOLMOD solves it directly.
TEST(LinearSolve, SymmetricMatrixStoresASymmetricPattern) {
  SpMat A = grid_matrix(12, -0.5);
  A.coeffRef(3, 40) = 0;  // stored, its mirror (40, 3) is not
  A.makeCompressed();
  const SymmetricMatrix S = SymmetricMatrix::symmetric_part_of(A);
  const SpMat& M = S.matrix();
  const SpMat Mt = M.transpose();
  ASSERT_EQ(M.nonZeros(), Mt.nonZeros());
  EXPECT_TRUE(std::equal(M.innerIndexPtr(), M.innerIndexPtr() + M.nonZeros(), Mt.innerIndexPtr()));
  EXPECT_EQ(M.nonZeros(), A.nonZeros() + 1);
  EXPECT_EQ(asymmetry_ratio(M), 0);
  const Eigen::VectorXd x_true = known_solution(static_cast<int>(A.rows()));
  const Eigen::VectorXd b = A * x_true;
  Eigen::VectorXd x;
  LinearSolveInfo info;
  ASSERT_TRUE(sparse_solve(S, b, x, &info));
  EXPECT_NE(info.path, LinearSolvePath::LU);
  EXPECT_LT(relative_error(x, x_true),
            std::sqrt(double(A.rows())) * condition_number(12, -0.5) * kBackwardError);
  ASSERT_EQ(cholesky_solve(S, b, x), CholeskyStatus::Solved);
  EXPECT_LT(relative_error(x, x_true),
            std::sqrt(double(A.rows())) * condition_number(12, -0.5) * kBackwardError);
}

// cholesky_solve solves only positive definite matrices: the grid Laplacian L - sigma I, with
// sigma between its two smallest eigenvalues (closed form), has one negative eigenvalue; a
// shift mu I makes it positive definite exactly when mu > sigma - lambda_1. sparse_solve still
// solves it (L D L^T or LU). Sizes: small (CHOLMOD's simplicial L D L^T, positive D checked)
// and large (supernodal L L^T).
TEST(LinearSolve, CholeskySolveReportsIndefiniteAndTheShiftThatCuresIt) {
  for (const int n : {12, 120}) {
    const std::vector<double> lambda = laplacian_eigenvalues(n);
    const double sigma = 0.5 * (lambda[0] + lambda[1]), gap = sigma - lambda[0];
    const SymmetricMatrix S = SymmetricMatrix::symmetric_part_of(grid_matrix(n, sigma));
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(S.size());
    Eigen::VectorXd x;
    EXPECT_EQ(cholesky_solve(S, b, x), CholeskyStatus::NotPositiveDefinite) << n;
    EXPECT_EQ(cholesky_solve(S.plus_diagonal(Eigen::VectorXd::Constant(S.size(), 0.9 * gap)), b, x),
              CholeskyStatus::NotPositiveDefinite)
        << n;
    const SymmetricMatrix shifted = S.plus_diagonal(Eigen::VectorXd::Constant(S.size(), 1.1 * gap));
    LinearSolveInfo info;
    ASSERT_EQ(cholesky_solve(shifted, b, x, &info), CholeskyStatus::Solved) << n;
    EXPECT_EQ(info.path, n == 12 ? LinearSolvePath::LDLT : LinearSolvePath::Cholesky) << n;
    EXPECT_LT((shifted.matrix() * x - b).norm() / b.norm(), 1e-10) << n;
    ASSERT_TRUE(sparse_solve(S, b, x, &info)) << n;
    EXPECT_LT((S.matrix() * x - b).norm() / b.norm(), 1e-10) << n;
  }
}

TEST(LinearSolve, NonFiniteSymmetricMatrixIsRefused) {
  SpMat A = grid_matrix(4, -0.5);
  A.coeffRef(2, 2) = NAN;
  const SymmetricMatrix S = SymmetricMatrix::symmetric_part_of(A);
  EXPECT_FALSE(S.finite());
  Eigen::VectorXd x;
  EXPECT_FALSE(sparse_solve(S, Eigen::VectorXd::Ones(S.size()), x));
  EXPECT_EQ(cholesky_solve(S, Eigen::VectorXd::Ones(S.size()), x), CholeskyStatus::Failed);
  const SymmetricMatrix T = SymmetricMatrix::symmetric_part_of(grid_matrix(4, -0.5));
  EXPECT_FALSE(T.plus_diagonal(Eigen::VectorXd::Constant(T.size(), INFINITY)).finite());
  EXPECT_FALSE(SymmetricMatrix::symmetric_part_of(SpMat(3, 4)).finite());
}

// Two patterns solved in turn (the static solver's stiffness and translation block) keep
// their analyses: two analyses for six solves, and the same bits as a first solve.
TEST(LinearSolve, AlternatingPatternsKeepTheirAnalyses) {
  const SymmetricMatrix A = SymmetricMatrix::symmetric_part_of(grid_matrix(40, -0.5));
  const SymmetricMatrix B = SymmetricMatrix::symmetric_part_of(grid_matrix(30, -0.2));
  const Eigen::VectorXd a = Eigen::VectorXd::Ones(A.size()), b = Eigen::VectorXd::Ones(B.size());
  Eigen::VectorXd x1, y1, x, y;
  linear_solve_counters() = {};
  ASSERT_TRUE(sparse_solve(A, a, x1));
  ASSERT_TRUE(sparse_solve(B, b, y1));
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(sparse_solve(A, a, x));
    ASSERT_TRUE(sparse_solve(B, b, y));
    EXPECT_EQ(x, x1);
    EXPECT_EQ(y, y1);
  }
  EXPECT_EQ(linear_solve_counters().analyses, 2);
  EXPECT_EQ(linear_solve_counters().factorizations, 6);
}

// A pattern cache keeps the numeric factor of its most recent pattern only (linear_solve.cpp):
// a pattern solved again after others is factored anew on its kept analysis, which must give
// the bits of its first solve, on every path: supernodal L L^T (120 x 120 grid), simplicial
// L D L^T of an indefinite matrix (after the failed L L^T), and UMFPACK's LU; and a kept
// factorization that returns to a pattern solves with the new factor.
TEST(LinearSolve, APatternSolvedAgainAfterOthersGivesItsFirstBits) {
  const std::vector<double> lambda = laplacian_eigenvalues(12);
  const SpMat cases[] = {grid_matrix(120, -0.5), grid_matrix(12, 0.5 * (lambda[3] + lambda[4])),
                         grid_matrix(20, -0.5, 0.5)};
  const LinearSolvePath paths[] = {LinearSolvePath::Cholesky, LinearSolvePath::LDLT,
                                   LinearSolvePath::LU};
  for (int c = 0; c < 3; ++c) {
    const SpMat& A = cases[c];
    const Eigen::VectorXd b = A * known_solution(static_cast<int>(A.rows()));
    Eigen::VectorXd x_first, x_again, y;
    LinearSolveInfo info;
    ASSERT_TRUE(sparse_solve(A, b, x_first, &info));
    EXPECT_EQ(info.path, paths[c]) << c;
    for (int k = 0; k < kCachedPatterns - 1; ++k) {  // A's slot stays cached, behind others
      const SpMat other = grid_matrix(10 + k, -0.5, c == 2 ? 0.5 : 0.0);
      ASSERT_TRUE(sparse_solve(other, Eigen::VectorXd::Ones(other.rows()), y));
    }
    const int analyses = linear_solve_counters().analyses;
    ASSERT_TRUE(sparse_solve(A, b, x_again));
    EXPECT_EQ(linear_solve_counters().analyses, analyses) << c;  // the kept analysis
    EXPECT_EQ(x_again, x_first) << c;
  }
  const SymmetricMatrix S1 = SymmetricMatrix::symmetric_part_of(grid_matrix(120, -0.5));
  const SymmetricMatrix S2 = SymmetricMatrix::symmetric_part_of(grid_matrix(100, -0.5));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(S1.size(), -1, 2);
  KeptFactorization kept;
  Eigen::MatrixXd X;
  Eigen::VectorXd x_first, x_again;
  ASSERT_TRUE(kept.factor_and_solve(S1, Eigen::MatrixXd(b), X));
  ASSERT_TRUE(kept.solve(b, x_first));
  ASSERT_TRUE(kept.factor_and_solve(S2, Eigen::MatrixXd(Eigen::VectorXd::Ones(S2.size())), X));
  ASSERT_TRUE(kept.factor_and_solve(S1, Eigen::MatrixXd(b), X));
  ASSERT_TRUE(kept.solve(b, x_again));
  EXPECT_EQ(x_again, x_first);
}

// From 10 000 rows on the analysis compares AMD with METIS (linear_solve.cpp): a 150 x 150 grid
// (22 500 rows) is solved by its Cholesky to the classical bound.
TEST(LinearSolve, LargeSystemWithComparedOrderingsSolves) {
  const int n = 150;
  const SymmetricMatrix S = SymmetricMatrix::symmetric_part_of(grid_matrix(n, -0.5));
  const Eigen::VectorXd x_true = known_solution(static_cast<int>(S.size()));
  Eigen::VectorXd x;
  LinearSolveInfo info;
  ASSERT_TRUE(sparse_solve(S, S.matrix() * x_true, x, &info));
  EXPECT_EQ(info.path, LinearSolvePath::Cholesky);
  EXPECT_LT(relative_error(x, x_true),
            std::sqrt(double(S.size())) * condition_number(n, -0.5) * kBackwardError);
}

// The LU path (UMFPACK) on an unsymmetric system whose diagonal is zero: the rows of the
// convection-diffusion matrix shifted cyclically by two (its entries lie at offsets 0, +-1 and +-n
// from the diagonal), so every pivot is off the diagonal. Reference: the dense LU with partial
// pivoting; both must be backward stable (normwise backward error ||b - A x|| / (||A|| ||x|| +
// ||b||) at round-off), and agree to within the classical bound cond(A) x backward error.
SpMat zero_diagonal_matrix(int n) {
  const SpMat G = grid_matrix(n, -0.5, 0.5);
  const int size = n * n;
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < size; ++c) {
    for (SpMat::InnerIterator it(G, c); it; ++it) {
      t.emplace_back((it.row() + 2) % size, c, it.value());
    }
  }
  SpMat A(size, size);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

double normwise_backward_error(const Eigen::MatrixXd& A, const Eigen::VectorXd& x,
                               const Eigen::VectorXd& b) {
  return (b - A * x).norm() / (A.norm() * x.norm() + b.norm());
}

TEST(LinearSolve, UnsymmetricLuMatchesTheDenseLu) {
  const SpMat A = zero_diagonal_matrix(10);
  for (Eigen::Index k = 0; k < A.rows(); ++k) ASSERT_EQ(A.coeff(k, k), 0.0);
  const Eigen::MatrixXd Ad(A);
  const Eigen::VectorXd b = A * known_solution(static_cast<int>(A.rows()));
  Eigen::VectorXd x;
  LinearSolveInfo info;
  linear_solve_counters() = {};
  ASSERT_TRUE(sparse_solve(A, b, x, &info));
  EXPECT_EQ(info.path, LinearSolvePath::LU);
  EXPECT_EQ(linear_solve_counters().lu_factorizations, 1);
  const Eigen::VectorXd x_dense = Ad.partialPivLu().solve(b);
  const double eps = std::numeric_limits<double>::epsilon();
  EXPECT_LT(normwise_backward_error(Ad, x, b), 10 * eps);
  EXPECT_LT(normwise_backward_error(Ad, x_dense, b), 10 * eps);
  EXPECT_LT((Ad * x - b).norm() / b.norm(), 1e-14);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Ad);
  const double cond = svd.singularValues()(0) / svd.singularValues().tail(1)(0);
  EXPECT_LT(relative_error(x, x_dense), 4 * cond * 10 * eps);  // 2 x (cond x 2 x 10 eps)
}

// Singular unsymmetric systems are refused: a zero row, a zero column (structurally singular),
// and an exactly singular 2 x 2 block [2 4; 1 2] (its elimination leaves an exact zero pivot
// whichever row is chosen: 2 - 0.5 x 4 and 4 - 2 x 2).
TEST(LinearSolve, SingularUnsymmetricMatrixIsRefused) {
  const SpMat G = grid_matrix(6, -0.5, 0.5);
  Eigen::VectorXd x;
  SpMat zero_row = G, zero_column = G;
  zero_row.prune([](int i, int, double) { return i != 7; });
  zero_column.prune([](int, int j, double) { return j != 7; });
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < G.outerSize(); ++c) {
    for (SpMat::InnerIterator it(G, c); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
  }
  const int n = static_cast<int>(G.rows());
  t.emplace_back(n, n, 2.0);
  t.emplace_back(n, n + 1, 4.0);
  t.emplace_back(n + 1, n, 1.0);
  t.emplace_back(n + 1, n + 1, 2.0);
  SpMat block(n + 2, n + 2);
  block.setFromTriplets(t.begin(), t.end());
  for (const SpMat* A : {&zero_row, &zero_column, &block}) {
    LinearSolveInfo info;
    EXPECT_FALSE(sparse_solve(*A, Eigen::VectorXd::Ones(A->rows()), x, &info));
    EXPECT_EQ(info.path, LinearSolvePath::LU);
  }
}

// A pattern's kept analysis gives the same bits as a fresh one: a second matrix of the same
// pattern solved with the first one's analysis, then again after kCachedPatterns other
// patterns evicted it (a new analysis); one LU solve of several right-hand sides gives each
// column's single solve to the bit.
TEST(LinearSolve, LuAnalysisReuseGivesTheBitsOfAFreshAnalysis) {
  const SpMat A1 = grid_matrix(30, -0.5, 0.5), A2 = grid_matrix(30, -0.7, 0.3);
  const Eigen::VectorXd b = A2 * known_solution(static_cast<int>(A2.rows()));
  Eigen::VectorXd x_reused, x_fresh, y;
  linear_solve_counters() = {};
  ASSERT_TRUE(sparse_solve(A1, b, y));
  ASSERT_TRUE(sparse_solve(A2, b, x_reused));
  EXPECT_EQ(linear_solve_counters().analyses, 1);
  for (int k = 0; k < kCachedPatterns; ++k) {
    const SpMat other = grid_matrix(10 + k, -0.5, 0.5);
    ASSERT_TRUE(sparse_solve(other, Eigen::VectorXd::Ones(other.rows()), y));
  }
  ASSERT_TRUE(sparse_solve(A2, b, x_fresh));
  EXPECT_EQ(linear_solve_counters().analyses, 2 + kCachedPatterns);
  EXPECT_EQ(linear_solve_counters().lu_factorizations, 3 + kCachedPatterns);
  EXPECT_EQ(x_reused, x_fresh);
  Eigen::MatrixXd B(b.size(), 2), X;
  B << b, Eigen::VectorXd::Ones(b.size());
  ASSERT_TRUE(sparse_solve(A2, B, X));
  Eigen::VectorXd x_ones;
  ASSERT_TRUE(sparse_solve(A2, Eigen::VectorXd(B.col(1)), x_ones));
  EXPECT_EQ(Eigen::VectorXd(X.col(0)), x_fresh);
  EXPECT_EQ(Eigen::VectorXd(X.col(1)), x_ones);
}

// From 10 000 rows on UMFPACK's analysis also tries METIS (UMFPACK_ORDERING_BEST): the zero-
// diagonal convection-diffusion system of 101 x 101 cells (10 201 rows, every pivot off the
// diagonal) is solved backward stably, as the dense LU of the small one above (normwise
// backward error at round-off).
TEST(LinearSolve, LuWithComparedOrderingsIsBackwardStable) {
  const SpMat A = zero_diagonal_matrix(101);
  const Eigen::VectorXd b = A * known_solution(static_cast<int>(A.rows()));
  Eigen::VectorXd x;
  LinearSolveInfo info;
  ASSERT_TRUE(sparse_solve(A, b, x, &info));
  EXPECT_EQ(info.path, LinearSolvePath::LU);
  const double eps = std::numeric_limits<double>::epsilon();
  EXPECT_LT((b - A * x).norm() / (A.norm() * x.norm() + b.norm()), 10 * eps);
}

// A kept factorization's later solves are unrefined (modified Newton corrects them), so they
// carry the factorization's own backward error. Unsymmetric (UMFPACK): the convection-diffusion
// matrix shifted by 0.5 is strictly diagonally dominant by columns, where Gaussian elimination
// with diagonal pivots (the symmetric strategy's choice) grows entries by at most 2, and the
// backward error is below 3 n eps x 2 (Higham, Accuracy and Stability, 9.3 and 9.5); the
// solution then lies within cond x that of the dense LU's. Symmetric positive definite
// (CHOLMOD): within the Cholesky bound of the exact solution (closed-form condition number).
// The factoring LU solve is unrefined too: a later solve of its right-hand side gives its bits,
// and both stay within the bound.
TEST(LinearSolve, KeptFactorizationSolvesUnrefinedToTheClassicalBound) {
  const double eps = std::numeric_limits<double>::epsilon();
  const SpMat A = grid_matrix(10, -0.5, 0.5);
  const Eigen::MatrixXd Ad(A);
  const Eigen::VectorXd b1 = A * known_solution(static_cast<int>(A.rows()));
  const Eigen::VectorXd b2 = Eigen::VectorXd::LinSpaced(A.rows(), -1, 2);
  KeptFactorization kept;
  Eigen::MatrixXd X;
  Eigen::VectorXd x;
  ASSERT_TRUE(kept.factor_and_solve(A, Eigen::MatrixXd(b1), X));
  const Eigen::VectorXd x_first = X.col(0);
  ASSERT_TRUE(kept.solve(b1, x));
  EXPECT_EQ(x, x_first);
  const double backward_bound = 3 * double(A.rows()) * eps * 2;
  EXPECT_LT(normwise_backward_error(Ad, x_first, b1), backward_bound);
  ASSERT_TRUE(kept.solve(b2, x));
  EXPECT_LT(normwise_backward_error(Ad, x, b2), backward_bound);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Ad);
  const double cond = svd.singularValues()(0) / svd.singularValues().tail(1)(0);
  EXPECT_LT(relative_error(x, Ad.partialPivLu().solve(b2)), 4 * cond * backward_bound);

  const int n = 40;  // 1 600 rows: CHOLMOD's simplicial L D L^T
  const SymmetricMatrix S = SymmetricMatrix::symmetric_part_of(grid_matrix(n, -0.5));
  const Eigen::VectorXd x_true = known_solution(static_cast<int>(S.size()));
  ASSERT_TRUE(kept.factor_and_solve(S, Eigen::MatrixXd(Eigen::VectorXd::Ones(S.size())), X));
  ASSERT_TRUE(kept.solve(S.matrix() * x_true, x));
  EXPECT_LT(relative_error(x, x_true),
            std::sqrt(double(S.size())) * condition_number(n, -0.5) * kBackwardError);
}

// Where its Cholesky factor is large, a kept factorization solves on a copy of it in single
// precision (single_precision_factor.hpp): a solution then carries single precision's error,
// within the Cholesky bound with eps = 2^-24 (Higham, Accuracy and Stability, 10.1) in the form
// used above, and refined in double precision against the matrix it converges by a factor of
// about cond x eps a step (mixed-precision iterative refinement, Moler 1967) to double
// precision's bound. A small factor solves in double precision (the default threshold), and
// so does one whose entries single precision cannot hold.
TEST(LinearSolve, LargeKeptFactorSolvesInSinglePrecisionToItsBound) {
  const int n = 120;  // 14 400 rows: supernodal L L^T
  const SymmetricMatrix S = SymmetricMatrix::symmetric_part_of(grid_matrix(n, -0.5));
  const Eigen::VectorXd x_true = known_solution(static_cast<int>(S.size()));
  const Eigen::VectorXd b = S.matrix() * x_true;
  const double bound = std::sqrt(double(S.size())) * condition_number(n, -0.5);
  const double eps_single = std::numeric_limits<float>::epsilon() / 2;
  KeptFactorization kept;
  Eigen::MatrixXd X;
  Eigen::VectorXd x;
  ASSERT_TRUE(kept.factor_and_solve(S, Eigen::MatrixXd(b), X));
  EXPECT_FALSE(kept.single_precision());
  kept.single_precision_from(0);
  ASSERT_TRUE(kept.factor_and_solve(S, Eigen::MatrixXd(b), X));
  ASSERT_TRUE(kept.single_precision());
  EXPECT_LT(relative_error(X.col(0), x_true), bound * kBackwardError);  // the factoring solve
  ASSERT_TRUE(kept.solve(b, x));
  const double e_single = relative_error(x, x_true);
  EXPECT_LT(e_single, bound * eps_single);
  EXPECT_GT(e_single, bound * kBackwardError);
  for (int step = 0; step < 4; ++step) {
    Eigen::VectorXd dx;
    ASSERT_TRUE(kept.solve(b - S.matrix() * x, dx));
    x += dx;
  }
  EXPECT_LT(relative_error(x, x_true), bound * kBackwardError);

  // Entries about 1e40 (the matrix 1e80 times larger): beyond single precision's range.
  const SymmetricMatrix S_huge = SymmetricMatrix::symmetric_part_of(1e80 * grid_matrix(n, -0.5));
  ASSERT_TRUE(kept.factor_and_solve(S_huge, Eigen::MatrixXd(1e80 * b), X));
  EXPECT_FALSE(kept.single_precision());
  ASSERT_TRUE(kept.solve(1e80 * b, x));
  EXPECT_LT(relative_error(x, x_true), bound * kBackwardError);
}

}  // namespace linear_solve_test
}  // namespace finseg
