// Sparse matrix assembled from 6 x 6 body blocks (one free body = 6 consecutive dofs).
// Element Jacobians arrive as blocks; converting them to compressed columns by a counting
// sort over block columns is linear in the number of blocks, where scalar triplets cost a
// sort of 36 times as many entries. Blocks are stored dense, so the sparsity pattern of a
// model's Jacobian does not change when an entry happens to be zero (the LU keeps its
// ordering).
#pragma once

#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace finseg {

using Mat6 = Eigen::Matrix<double, 6, 6>;

/// Accumulates blocks; repeated (row, column) blocks are summed. Keeps its storage between
/// uses (clear() does not free).
class BlockMatrix {
 public:
  void clear() {
    keys_.clear();
    blocks_.clear();
  }
  /// Adds m at rows row0..row0+5, columns col0..col0+5 (both multiples of 6 apart from a
  /// common offset: the first dof of a body).
  void add(int row0, int col0, const Mat6& m) {
    keys_.emplace_back(row0, col0);
    blocks_.push_back(m);
  }
  /// Appends `count` blocks to be written by set(); returns the first one's slot.
  int append(int count) {
    const int first = static_cast<int>(keys_.size());
    keys_.resize(first + count);
    blocks_.resize(first + count);
    return first;
  }
  /// Writes block `slot` (from append); different slots may be written in parallel.
  void set(int slot, int row0, int col0, const Mat6& m) {
    keys_[slot] = {row0, col0};
    blocks_[slot] = m;
  }
  /// Writes the sum of the blocks into A (n x n, compressed, rows sorted in each column).
  void to_sparse(int n, Eigen::SparseMatrix<double>& A);

 private:
  void sort_by_column(int num_cols);  // fills order_ and start_

  std::vector<std::pair<int, int>> keys_;  // (row0, col0)
  std::vector<Mat6, Eigen::aligned_allocator<Mat6>> blocks_;
  std::vector<int> order_, start_, fill_, slot_, col_base_;  // scratch of to_sparse
};

}  // namespace finseg
