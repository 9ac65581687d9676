// Block assembly of the Jacobians against Eigen's own triplet assembly.
#include <gtest/gtest.h>

#include <Eigen/Dense>

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

}  // namespace block_matrix_test
}  // namespace finseg
