#include "elements/block_matrix.hpp"

#include <algorithm>

namespace finseg {

void BlockMatrix::clear() {
  keys_.clear();
  blocks_.clear();
  folded_ = 0;
  for (std::size_t s = 0; s < touched_.size(); ++s) {
    if (!touched_[s]) continue;
    layout_sum_[s].setZero();
    touched_[s] = 0;
  }
}

int BlockMatrix::slot_of(int row0, int col0) const {
  const std::size_t c = static_cast<std::size_t>(col0 / 6);
  if (c + 1 >= layout_start_.size()) return -1;
  const auto first = layout_row_.begin() + layout_start_[c];
  const auto last = layout_row_.begin() + layout_start_[c + 1];
  const auto it = std::lower_bound(first, last, row0);
  return it != last && *it == row0 ? static_cast<int>(it - layout_row_.begin()) : -1;
}

void BlockMatrix::fold_listed() {
  for (; folded_ < keys_.size(); ++folded_) {
    auto& key = keys_[folded_];
    const int s = slot_of(key.first, key.second);
    if (s < 0) continue;
    layout_sum_[s] += blocks_[folded_];
    touched_[s] = 1;
    key = {-1, -1};
  }
}

int BlockMatrix::slot_to_add(int row0, int col0) {
  const int s = slot_of(row0, col0);
  if (s < 0) return -1;
  fold_listed();  // listed blocks first: sums keep the order the blocks came in
  touched_[s] = 1;
  return s;
}

void BlockMatrix::add(int row0, int col0, const Mat6& m) {
  const int s = slot_to_add(row0, col0);
  if (s >= 0) {
    layout_sum_[s] += m;
    return;
  }
  keys_.emplace_back(row0, col0);
  blocks_.push_back(m);
}

void BlockMatrix::add_corner(int row0, int col0, const Mat3& m) {
  const int s = slot_to_add(row0, col0);
  if (s >= 0) {
    layout_sum_[s].bottomRightCorner<3, 3>() += m;
    return;
  }
  keys_.emplace_back(row0, col0);
  blocks_.push_back(Mat6::Zero());
  blocks_.back().bottomRightCorner<3, 3>() = m;
}

int BlockMatrix::append(int count) {
  const int first = static_cast<int>(keys_.size());
  keys_.resize(first + count);
  blocks_.resize(first + count);
  return first;
}

void BlockMatrix::sort_listed(int num_cols) {
  // Counting sort by column block, then insertion sort by row block within each column
  // (few per column; stable, so equal blocks keep the order they were added in).
  start_.assign(num_cols + 1, 0);
  for (const auto& key : keys_) {
    if (key.first >= 0) ++start_[key.second / 6 + 1];
  }
  for (int c = 0; c < num_cols; ++c) start_[c + 1] += start_[c];
  order_.resize(start_[num_cols]);
  fill_.assign(start_.begin(), start_.end() - 1);
  for (int k = 0; k < static_cast<int>(keys_.size()); ++k) {
    if (keys_[k].first >= 0) order_[fill_[keys_[k].second / 6]++] = k;
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

void BlockMatrix::learn_layout(int num_cols, const Eigen::SparseMatrix<double>& A) {
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  layout_start_.assign(num_cols + 1, 0);
  layout_row_.clear();
  for (int c = 0; c < num_cols; ++c) {
    for (int at = outer[6 * c]; at < outer[6 * c + 1]; at += 6) layout_row_.push_back(inner[at]);
    layout_start_[c + 1] = static_cast<int>(layout_row_.size());
  }
  layout_sum_.assign(layout_row_.size(), Mat6::Zero());
  touched_.assign(layout_row_.size(), 0);
}

void BlockMatrix::to_sparse(int n, Eigen::SparseMatrix<double>& A) {
  const int num_cols = n / 6;
  fold_listed();
  sort_listed(num_cols);
  const int layout_cols = static_cast<int>(layout_start_.size()) - 1;
  const auto layout_end = [&](int c) { return c < layout_cols ? layout_start_[c + 1] : 0; };
  const auto layout_begin = [&](int c) { return c < layout_cols ? layout_start_[c] : 0; };
  // Distinct row blocks of each column: its layout blocks reached and its listed rows (which
  // are not on the layout); a column block with u of them holds 6 u entries in each column.
  bool same_layout = layout_cols == num_cols && start_[num_cols] == 0;
  col_base_.assign(num_cols + 1, 0);
  for (int c = 0; c < num_cols; ++c) {
    int distinct = 0;
    for (int s = layout_begin(c); s < layout_end(c); ++s) distinct += touched_[s];
    same_layout = same_layout && distinct == layout_end(c) - layout_begin(c);
    for (int k = start_[c]; k < start_[c + 1]; ++k) {
      distinct += k == start_[c] || keys_[order_[k]].first != keys_[order_[k - 1]].first;
    }
    col_base_[c + 1] = col_base_[c] + 36 * distinct;
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
  // Block `p` of column c: its rows and its sum.
  const auto write = [&](int c, int p, int row0, const Mat6& sum) {
    for (int j = 0; j < 6; ++j) {
      const int at = outer[6 * c + j] + 6 * p;
      for (int i = 0; i < 6; ++i) {
        inner[at + i] = row0 + i;
        value[at + i] = sum(i, j);
      }
    }
  };
  Mat6 sum;
  for (int c = 0; c < num_cols; ++c) {
    int s = layout_begin(c), k = start_[c], p = 0;
    const int s_end = layout_end(c), k_end = start_[c + 1];
    for (;;) {
      while (s < s_end && !touched_[s]) ++s;
      if (s == s_end && k == k_end) break;
      const int row_listed = k < k_end ? keys_[order_[k]].first : -1;
      if (k == k_end || (s < s_end && layout_row_[s] < row_listed)) {
        write(c, p++, layout_row_[s], layout_sum_[s]);
        ++s;
        continue;
      }
      // Listed blocks of one row, summed in the order they were added (deterministic).
      sum.setZero();
      for (; k < k_end && keys_[order_[k]].first == row_listed; ++k) sum += blocks_[order_[k]];
      write(c, p++, row_listed, sum);
    }
  }
  if (!same_layout) learn_layout(num_cols, A);
}

}  // namespace finseg
