// Block assembly of the Jacobians against Eigen's own triplet assembly.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "elements/block_matrix.hpp"

namespace finseg {
namespace block_matrix_test {

TEST(BlockMatrix, SumsRepeatedBlocksLikeTripletsAndLeavesEmptyColumnsEmpty) {
  const int n = 30;  // five column blocks; block column 3 gets nothing
  BlockMatrix bm;
  std::vector<Eigen::Triplet<double>> triplets;
  const std::pair<int, int> at[] = {{0, 0},  {24, 0},  {6, 6}, {0, 0},  {12, 24}, {24, 24},
                                    {6, 12}, {12, 12}, {0, 6}, {24, 0}, {6, 6}};
  for (int k = 0; k < static_cast<int>(std::size(at)); ++k) {
    Mat6 m;
    for (int j = 0; j < 6; ++j) {
      for (int i = 0; i < 6; ++i) m(i, j) = std::sin(1.7 * k + 0.3 * i + 0.11 * j + 0.5);
    }
    bm.add(at[k].first, at[k].second, m);
    for (int j = 0; j < 6; ++j) {
      for (int i = 0; i < 6; ++i) triplets.emplace_back(at[k].first + i, at[k].second + j, m(i, j));
    }
  }
  for (int pass = 0; pass < 2; ++pass) {  // the second pass reuses the storage
    Eigen::SparseMatrix<double> A, B(n, n);
    bm.to_sparse(n, A);
    B.setFromTriplets(triplets.begin(), triplets.end());
    EXPECT_EQ(A.nonZeros(), B.nonZeros());
    EXPECT_LE((Eigen::MatrixXd(A) - Eigen::MatrixXd(B)).cwiseAbs().maxCoeff(), 1e-15);
    for (int col = 18; col < 24; ++col) EXPECT_EQ(A.col(col).nonZeros(), 0);
    for (int col = 0; col < n; ++col) {  // rows ascending in every column
      for (int k = A.outerIndexPtr()[col] + 1; k < A.outerIndexPtr()[col + 1]; ++k) {
        EXPECT_LT(A.innerIndexPtr()[k - 1], A.innerIndexPtr()[k]);
      }
    }
  }
}

// A matrix that keeps the last layout must give, at every evaluation, the same bits as one
// that never saw a layout, whichever of its blocks fall on the old layout: blocks on it, new
// ones, old ones now absent, corner blocks, and appended blocks written by set() between them.
TEST(BlockMatrix, AKeptLayoutChangesNeitherPatternNorBits) {
  const int n = 48;  // eight column blocks
  BlockMatrix kept;
  Eigen::SparseMatrix<double> A, B;
  for (int pass = 0; pass < 6; ++pass) {
    BlockMatrix fresh;
    kept.clear();
    std::vector<Eigen::Triplet<double>> triplets;
    const auto value = [&](int k, int i, int j) {
      return std::sin(1.3 * k + 0.7 * pass + 0.3 * i + 0.11 * j) * std::pow(10.0, (k + i) % 7);
    };
    for (int k = 0; k < 40; ++k) {
      // Most blocks in the same places every pass, some moving with the pass (new or absent).
      const int r = 6 * ((3 * k + (k % 5 == 0 ? pass : 0)) % 8), c = 6 * ((k * k + k / 7) % 8);
      Mat6 m;
      for (int j = 0; j < 6; ++j) {
        for (int i = 0; i < 6; ++i) m(i, j) = value(k, i, j);
      }
      if (k % 4 == 1) {  // a corner block
        kept.add_corner(r, c, m.bottomRightCorner<3, 3>());
        fresh.add_corner(r, c, m.bottomRightCorner<3, 3>());
        m.leftCols<3>().setZero();
        m.topRightCorner<3, 3>().setZero();
      } else if (k % 4 == 2) {  // appended, written later (as the parallel elements do)
        const int sk = kept.append(1), sf = fresh.append(1);
        kept.set(sk, r, c, m);
        fresh.set(sf, r, c, m);
      } else {
        kept.add(r, c, m);
        fresh.add(r, c, m);
      }
      for (int j = 0; j < 6; ++j) {
        for (int i = 0; i < 6; ++i) triplets.emplace_back(r + i, c + j, m(i, j));
      }
    }
    kept.to_sparse(n, A);
    fresh.to_sparse(n, B);
    ASSERT_EQ(A.nonZeros(), B.nonZeros()) << "pass " << pass;
    for (int col = 0; col <= n; ++col) ASSERT_EQ(A.outerIndexPtr()[col], B.outerIndexPtr()[col]);
    for (int k = 0; k < A.nonZeros(); ++k) {
      ASSERT_EQ(A.innerIndexPtr()[k], B.innerIndexPtr()[k]);
      ASSERT_EQ(A.valuePtr()[k], B.valuePtr()[k]) << "pass " << pass << ", entry " << k;
    }
    Eigen::SparseMatrix<double> T(n, n);
    T.setFromTriplets(triplets.begin(), triplets.end());
    EXPECT_LE((Eigen::MatrixXd(A) - Eigen::MatrixXd(T)).cwiseAbs().maxCoeff(),
              1e-15 * Eigen::MatrixXd(T).cwiseAbs().maxCoeff());
  }
}

}  // namespace block_matrix_test
}  // namespace finseg
