// Orderings on the block graph (src/solvers/block_ordering.*), on A = G (x) B: G the 5-point
// Laplacian of an n x n grid shifted by +0.5 (eigenvalues 4.5 - 2 cos(pi i/(n+1)) -
// 2 cos(pi j/(n+1))), B = I + 0.5 * ones(6, 6) (eigenvalues 1, five times, and 4), every block
// stored whole as in a Newton matrix. References: the grid's edge count, the elimination of
// indistinguishable nodes (a block's six DOFs fill alike: a block column of L holds 21 entries
// on its diagonal block and 36 in each other one), and the Kronecker product's eigenvalues
// (lambda_i(G) mu_j(B)) for the solve's error bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "solvers/block_ordering.hpp"
#include "solvers/linear_solve.hpp"

namespace finseg {
namespace block_ordering_test {

using SpMat = Eigen::SparseMatrix<double>;

// G (x) B for the n x n grid, every 6 x 6 block stored.
SpMat grid_of_blocks(int n) {
  std::vector<Eigen::Triplet<double>> t;
  const auto block = [&](int r, int c, double g) {
    for (int i = 0; i < kBlockSize; ++i) {
      for (int j = 0; j < kBlockSize; ++j) {
        t.emplace_back(kBlockSize * r + i, kBlockSize * c + j, g * ((i == j ? 1.0 : 0.0) + 0.5));
      }
    }
  };
  const auto id = [n](int i, int j) { return i * n + j; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      block(id(i, j), id(i, j), 4.5);
      if (i > 0) block(id(i, j), id(i - 1, j), -1);
      if (i + 1 < n) block(id(i, j), id(i + 1, j), -1);
      if (j > 0) block(id(i, j), id(i, j - 1), -1);
      if (j + 1 < n) block(id(i, j), id(i, j + 1), -1);
    }
  }
  SpMat A(kBlockSize * n * n, kBlockSize * n * n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// CHOLMOD's workspace for one test.
struct Common {
  cholmod_common c;
  Common() { cholmod_start(&c); }
  ~Common() { cholmod_finish(&c); }
  Common(const Common&) = delete;
  Common& operator=(const Common&) = delete;
};

// nnz(L) (diagonal included) of the simplicial Cholesky factor of the lower triangle of the
// pattern (outer, inner) of size n in the ordering perm.
double factor_entries(int n, std::vector<int> outer, std::vector<int> inner, std::vector<int> perm,
                      cholmod_common& c) {
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<std::size_t>(n);
  A.nzmax = inner.size();
  A.p = outer.data();
  A.i = inner.data();
  A.stype = -1;
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_PATTERN;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  c.nmethods = 1;  // method 0: the given permutation
  c.supernodal = CHOLMOD_SIMPLICIAL;
  cholmod_factor* L = cholmod_analyze_p(&A, perm.data(), nullptr, 0, &c);
  EXPECT_NE(L, nullptr);
  const double entries = c.lnz;
  cholmod_free_factor(&L, &c);
  return entries;
}

TEST(BlockOrdering, TheBlockGraphIsTheGridsLowerTriangle) {
  const int n = 7;
  const std::optional<BlockGraph> g = block_graph(grid_of_blocks(n));
  ASSERT_TRUE(g.has_value());
  ASSERT_EQ(g->outer.size(), static_cast<std::size_t>(n * n + 1));
  // n^2 diagonal entries and the grid's 2 n (n - 1) edges, each once.
  EXPECT_EQ(g->inner.size(), static_cast<std::size_t>(n * n + 2 * n * (n - 1)));
  for (int c = 0; c < n * n; ++c) {
    EXPECT_EQ(g->inner[g->outer[c]], c);  // the diagonal first, then the rows below
    EXPECT_TRUE(std::is_sorted(g->inner.begin() + g->outer[c], g->inner.begin() + g->outer[c + 1]));
  }
}

TEST(BlockOrdering, OtherPatternsHaveNoBlockGraph) {
  const SpMat A = grid_of_blocks(4);
  SpMat missing = A;  // one entry of one block not stored
  missing.prune([](int r, int c, double) { return !(r == 7 && c == 1); });
  EXPECT_FALSE(block_graph(missing).has_value());
  SpMat shifted(A.rows() + 1, A.cols() + 1);  // the blocks off their 6-aligned places
  std::vector<Eigen::Triplet<double>> t{{0, 0, 1.0}};
  for (int c = 0; c < A.outerSize(); ++c) {
    for (SpMat::InnerIterator it(A, c); it; ++it) t.emplace_back(it.row() + 1, c + 1, it.value());
  }
  shifted.setFromTriplets(t.begin(), t.end());
  EXPECT_FALSE(block_graph(shifted).has_value());
  EXPECT_FALSE(block_graph(SpMat(12, 18)).has_value());
}

TEST(BlockOrdering, TheExpandedOrderingFillsAsTheBlockOrdering) {
  const int n = 20;
  const SpMat A = grid_of_blocks(n);
  Common common;
  const std::optional<std::vector<int>> perm = block_ordering(A, common.c);
  ASSERT_TRUE(perm.has_value());
  ASSERT_EQ(perm->size(), static_cast<std::size_t>(A.rows()));
  std::vector<int> sorted = *perm;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(sorted.size());
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(sorted, identity);  // a permutation
  std::vector<int> block_perm;
  for (std::size_t k = 0; k < perm->size(); k += kBlockSize) {
    ASSERT_EQ((*perm)[k] % kBlockSize, 0);
    for (int i = 1; i < kBlockSize; ++i) ASSERT_EQ((*perm)[k + i], (*perm)[k] + i);
    block_perm.push_back((*perm)[k] / kBlockSize);
  }
  const BlockGraph g = *block_graph(A);
  const double block_entries = factor_entries(n * n, g.outer, g.inner, block_perm, common.c);
  // The scalar matrix's lower triangle.
  std::vector<int> outer{0}, inner;
  for (int c = 0; c < A.outerSize(); ++c) {
    for (SpMat::InnerIterator it(A, c); it; ++it) {
      if (it.row() >= c) inner.push_back(static_cast<int>(it.row()));
    }
    outer.push_back(static_cast<int>(inner.size()));
  }
  const double entries = factor_entries(static_cast<int>(A.rows()), outer, inner, *perm, common.c);
  EXPECT_EQ(entries, 36 * block_entries - 15 * n * n);
  // A fill-reducing ordering: the grid's natural (banded) order fills n entries a column.
  std::vector<int> natural(n * n);
  std::iota(natural.begin(), natural.end(), 0);
  EXPECT_LT(block_entries, 0.8 * factor_entries(n * n, g.outer, g.inner, natural, common.c));
}

// From 10 000 rows on, sparse_solve orders a matrix of blocks on its block graph: a 41 x 41
// grid of blocks (10 086 rows) is solved by its Cholesky factor to the classical bound.
TEST(BlockOrdering, ALargeSystemOfBlocksSolvesToTheClassicalBound) {
  const int n = 41;
  const SymmetricMatrix S = SymmetricMatrix::symmetric_part_of(grid_of_blocks(n));
  ASSERT_GE(S.size(), 10000);
  const double h = std::numbers::pi / (n + 1);
  const double lambda_min = 4.5 - 4 * std::cos(h), lambda_max = 4.5 + 4 * std::cos(h);
  const double cond = lambda_max / lambda_min * 4.0;  // B's eigenvalues: 1 and 4
  Eigen::VectorXd x_true(S.size());
  for (Eigen::Index k = 0; k < x_true.size(); ++k) x_true[k] = std::sin(0.37 * double(k));
  Eigen::VectorXd x;
  LinearSolveInfo info;
  ASSERT_TRUE(sparse_solve(S, S.matrix() * x_true, x, &info));
  EXPECT_EQ(info.path, LinearSolvePath::Cholesky);
  EXPECT_LT((x - x_true).norm() / x_true.norm(), std::sqrt(double(S.size())) * cond * 1e-14);
}

}  // namespace block_ordering_test
}  // namespace finseg
