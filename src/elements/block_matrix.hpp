// Sparse matrix assembled from 6 x 6 body blocks (one free body = 6 consecutive dofs).
// Element Jacobians arrive as blocks; converting them to compressed columns by a counting
// sort over block columns is linear in the number of blocks, where scalar triplets cost a
// sort of 36 times as many entries. Blocks are stored dense, so the sparsity pattern of a
// model's Jacobian does not change when an entry happens to be zero (the LU keeps its
// ordering).
//
// A matrix keeps the block layout of the last one it made: a block that falls on it is summed
// in place instead of being listed, sorted and summed later (on a sheet most blocks are the
// cells' and elements', in the same places at every evaluation). The layout only saves work:
// blocks are summed in the order they were added whatever it is, so the result is the same
// to the bit with or without it.
#pragma once

#include <Eigen/SparseCore>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace finseg {

using Mat6 = Eigen::Matrix<double, 6, 6>;

/// Accumulates blocks; repeated (row, column) blocks are summed. Keeps its storage and its
/// last layout between uses (clear() does not free).
class BlockMatrix {
 public:
  /// Starts a new matrix (no blocks).
  void clear();
  /// Adds m at rows row0..row0+5, columns col0..col0+5 (both multiples of 6 apart from a
  /// common offset: the first dof of a body).
  void add(int row0, int col0, const Mat6& m);
  /// Adds m to the lower right 3 x 3 of that block (rotations by rotations), the rest zero.
  void add_corner(int row0, int col0, const Mat3& m);
  /// Appends `count` blocks to be written by set(); returns the first one's slot. They must
  /// be written before the next add() or add_corner().
  int append(int count);
  /// Writes block `slot` (from append); different slots may be written in parallel.
  void set(int slot, int row0, int col0, const Mat6& m) {
    keys_[slot] = {row0, col0};
    blocks_[slot] = m;
  }
  /// Writes the sum of the blocks into A (n x n, compressed, rows sorted in each column).
  void to_sparse(int n, Eigen::SparseMatrix<double>& A);

 private:
  int slot_of(int row0, int col0) const;  // the layout's slot of a block, or -1
  int slot_to_add(int row0, int col0);    // slot_of, made ready to add to (or -1)
  void fold_listed();                     // listed blocks that fall on the layout summed there
  void sort_listed(int num_cols);         // fills order_ and start_ (unfolded blocks only)
  void learn_layout(int num_cols, const Eigen::SparseMatrix<double>& A);

  // Blocks listed (not on the layout, or written by set()) in the order they were added;
  // a folded one's key is (-1, -1).
  std::vector<std::pair<int, int>> keys_;  // (row0, col0)
  std::vector<Mat6, Eigen::aligned_allocator<Mat6>> blocks_;
  std::size_t folded_ = 0;  // listed blocks before this one are folded

  // The layout: per block column its row blocks (sorted), their sums and whether any block
  // reached them since clear().
  std::vector<int> layout_start_, layout_row_;
  std::vector<Mat6, Eigen::aligned_allocator<Mat6>> layout_sum_;
  std::vector<char> touched_;

  std::vector<int> order_, start_, fill_, col_base_;  // scratch of to_sparse
};

}  // namespace finseg
