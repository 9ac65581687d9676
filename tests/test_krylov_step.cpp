// Krylov steps on a kept factor: GMRES preconditioned by the factor of K solves (K + E) x = b
// where E has rank r in at most r + 1 iterations (the preconditioned matrix is the identity plus
// a rank-r term, whose minimal polynomial has degree r + 1), and reports failure when it is
// allowed fewer.
#include <gtest/gtest.h>

#include <random>

#include "solvers/krylov_step.hpp"
#include "solvers/linear_solve.hpp"

namespace finseg {
namespace krylov_step_test {

// The 5-point Laplacian of an n x n grid plus the identity: sparse, symmetric positive definite.
Eigen::SparseMatrix<double> grid_laplacian(int n) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [n](int i, int j) { return i * n + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      t.emplace_back(id(i, j), id(i, j), 5.0);
      if (i + 1 < n) t.emplace_back(id(i, j), id(i + 1, j), -1.0);
      if (i > 0) t.emplace_back(id(i, j), id(i - 1, j), -1.0);
      if (j + 1 < n) t.emplace_back(id(i, j), id(i, j + 1), -1.0);
      if (j > 0) t.emplace_back(id(i, j), id(i, j - 1), -1.0);
    }
  Eigen::SparseMatrix<double> K(n * n, n * n);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

// K plus a nonsymmetric rank-`rank` term u_k v_k^T on a few unknowns each.
Eigen::SparseMatrix<double> perturbed(const Eigen::SparseMatrix<double>& K, int rank,
                                      std::mt19937& rng) {
  std::uniform_int_distribution<int> at(0, static_cast<int>(K.rows()) - 1);
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::SparseMatrix<double> E(K.rows(), K.cols());
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < rank; ++k) {
    std::vector<std::pair<int, double>> left, right;
    for (int m = 0; m < 3; ++m)
      left.emplace_back(at(rng), u(rng)), right.emplace_back(at(rng), u(rng));
    for (const auto& [i, a] : left)
      for (const auto& [j, b] : right) t.emplace_back(i, j, 2 * a * b);
  }
  E.setFromTriplets(t.begin(), t.end());
  return K + E;
}

TEST(KrylovStep, GmresOnAKeptFactorConvergesInRankPlusOneIterations) {
  const Eigen::SparseMatrix<double> K = grid_laplacian(30);
  KeptNewtonMatrix M;
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(K.rows());
  Eigen::VectorXd x;
  ASSERT_TRUE(M.factor_and_solve(SymmetricMatrix::symmetric_part_of(K), ones, x));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int rank : {1, 3, 5}) {
    const Eigen::SparseMatrix<double> A = perturbed(K, rank, rng);
    Eigen::VectorXd b(K.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = u(rng);
    int its = 0;
    ASSERT_TRUE(krylov_solve(A, M, b, {rank + 1, 1e-10}, x, &its)) << rank;
    EXPECT_LE(its, rank + 1);
    EXPECT_LT((A * x - b).norm(), 1e-8 * b.norm()) << rank;
    // Allowed fewer iterations than the rank, it does not claim a solution.
    if (rank > 1) {
      EXPECT_FALSE(krylov_solve(A, M, b, {rank - 1, 1e-10}, x)) << rank;
    }
  }
  // No kept factor: no step.
  EXPECT_FALSE(krylov_solve(K, KeptNewtonMatrix{}, ones, {}, x));
}

}  // namespace krylov_step_test
}  // namespace finseg
