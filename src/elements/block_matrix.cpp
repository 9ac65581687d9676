#include "elements/block_matrix.hpp"

#include <algorithm>

namespace finseg {

void BlockMatrix::sort_by_column(int num_cols) {
  // Counting sort by column block, then insertion sort by row block within each column
  // (few per column; stable, so equal blocks keep the order they were added in).
  start_.assign(num_cols + 1, 0);
  for (const auto& key : keys_) ++start_[key.second / 6 + 1];
  for (int c = 0; c < num_cols; ++c) start_[c + 1] += start_[c];
  order_.resize(keys_.size());
  fill_.assign(start_.begin(), start_.end() - 1);
  for (int k = 0; k < static_cast<int>(keys_.size()); ++k) {
    order_[fill_[keys_[k].second / 6]++] = k;
  }
  for (int c = 0; c < num_cols; ++c) {
    for (int k = start_[c] + 1; k < start_[c + 1]; ++k) {
      const int moving = order_[k];
      int j = k;
      for (; j > start_[c] && keys_[order_[j - 1]].first > keys_[moving].first; --j) {
        order_[j] = order_[j - 1];
      }
      order_[j] = moving;
    }
  }
}

void BlockMatrix::to_sparse(int n, Eigen::SparseMatrix<double>& A) {
  const int num_cols = n / 6;
  sort_by_column(num_cols);
  // Slot of each block among the distinct row blocks of its column: a column block with u
  // distinct row blocks holds 6 u entries in each of its 6 columns.
  slot_.resize(keys_.size());
  col_base_.assign(num_cols + 1, 0);
  for (int c = 0; c < num_cols; ++c) {
    int distinct = 0;
    for (int k = start_[c]; k < start_[c + 1]; ++k) {
      if (k > start_[c] && keys_[order_[k]].first != keys_[order_[k - 1]].first) ++distinct;
      slot_[order_[k]] = distinct;
    }
    col_base_[c + 1] = col_base_[c] + (start_[c + 1] > start_[c] ? 36 * (distinct + 1) : 0);
  }
  A.resize(n, n);
  A.resizeNonZeros(col_base_[num_cols]);
  int* outer = A.outerIndexPtr();
  int* inner = A.innerIndexPtr();
  double* value = A.valuePtr();
  for (int col = 0; col < n; ++col) {
    const int c = col / 6;
    outer[col] = col_base_[c] + (col - 6 * c) * (col_base_[c + 1] - col_base_[c]) / 6;
  }
  outer[n] = col_base_[num_cols];
  for (int k = 0; k < static_cast<int>(keys_.size()); ++k) {
    const auto [row0, col0] = keys_[k];
    for (int j = 0; j < 6; ++j) {
      const int at = outer[col0 + j] + 6 * slot_[k];
      for (int i = 0; i < 6; ++i) inner[at + i] = row0 + i;
    }
  }
  // Blocks summed in the order they were added (deterministic) and read sequentially.
  std::fill(value, value + col_base_[num_cols], 0.0);
  for (int k = 0; k < static_cast<int>(keys_.size()); ++k) {
    const int col0 = keys_[k].second;
    const Mat6& m = blocks_[k];
    for (int j = 0; j < 6; ++j) {
      double* dst = value + outer[col0 + j] + 6 * slot_[k];
      for (int i = 0; i < 6; ++i) dst[i] += m(i, j);
    }
  }
}

}  // namespace finseg
