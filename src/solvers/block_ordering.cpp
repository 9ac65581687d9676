#include "solvers/block_ordering.hpp"

#include <algorithm>
#include <memory>
#include <type_traits>

namespace finseg {

namespace {

// True where the columns of block column c hold the same rows, in aligned runs of six.
bool block_column_is_dense(const int* outer, const int* inner, int c) {
  const int first = outer[kBlockSize * c];
  const int count = outer[kBlockSize * c + 1] - first;
  if (count % kBlockSize != 0) return false;
  for (int j = 1; j < kBlockSize; ++j) {
    const int at = outer[kBlockSize * c + j];
    if (outer[kBlockSize * c + j + 1] - at != count) return false;
    if (!std::equal(inner + first, inner + first + count, inner + at)) return false;
  }
  for (int k = 0; k < count; k += kBlockSize) {
    const int row0 = inner[first + k];
    if (row0 % kBlockSize != 0) return false;
    for (int i = 1; i < kBlockSize; ++i) {
      if (inner[first + k + i] != row0 + i) return false;
    }
  }
  return true;
}

// The orderings tried on the block graph, set for one analysis and then restored: method 1,
// CHOLMOD's AMD, and in place of METIS (method 2) CHOLMOD's nested dissection down to parts of
// 4 nodes without constrained minimum degree (its default method 6). On the lab cone's Newton
// matrices the latter needed 3-4 % fewer flops than AMD and METIS on the scalar matrix and
// than METIS on the block graph (BENCHMARKS.md).
class BlockGraphSettings {
 public:
  explicit BlockGraphSettings(cholmod_common& c)
      : c_(c), supernodal_(c.supernodal), nmethods_(c.nmethods), method2_(c.method[2]) {
    c.supernodal = CHOLMOD_SIMPLICIAL;  // only the ordering is wanted of this analysis
    c.nmethods = 3;                     // method 0, the given permutation: none, skipped
    c.method[2] = c.method[6];
  }
  ~BlockGraphSettings() {
    c_.supernodal = supernodal_;
    c_.nmethods = nmethods_;
    c_.method[2] = method2_;
  }
  BlockGraphSettings(const BlockGraphSettings&) = delete;
  BlockGraphSettings& operator=(const BlockGraphSettings&) = delete;

 private:
  cholmod_common& c_;
  int supernodal_, nmethods_;
  std::remove_reference_t<decltype(cholmod_common::method[2])> method2_;
};

}  // namespace

std::optional<BlockGraph> block_graph(const Eigen::SparseMatrix<double>& S) {
  if (S.rows() != S.cols() || S.rows() % kBlockSize != 0 || !S.isCompressed()) {
    return std::nullopt;
  }
  const int nb = static_cast<int>(S.rows() / kBlockSize);
  const int* outer = S.outerIndexPtr();
  const int* inner = S.innerIndexPtr();
  BlockGraph g;
  g.outer.reserve(nb + 1);
  g.outer.push_back(0);
  for (int c = 0; c < nb; ++c) {
    if (!block_column_is_dense(outer, inner, c)) return std::nullopt;
    for (int at = outer[kBlockSize * c]; at < outer[kBlockSize * c + 1]; at += kBlockSize) {
      const int rb = inner[at] / kBlockSize;
      if (rb >= c) g.inner.push_back(rb);
    }
    g.outer.push_back(static_cast<int>(g.inner.size()));
  }
  return g;
}

std::optional<std::vector<int>> block_ordering(const Eigen::SparseMatrix<double>& S,
                                               cholmod_common& common) {
  const std::optional<BlockGraph> g = block_graph(S);
  if (!g) return std::nullopt;
  const auto nb = static_cast<std::size_t>(g->outer.size() - 1);
  cholmod_sparse B{};
  B.nrow = B.ncol = nb;
  B.nzmax = g->inner.size();
  B.p = const_cast<int*>(g->outer.data());
  B.i = const_cast<int*>(g->inner.data());
  B.stype = -1;  // the lower triangle
  B.itype = CHOLMOD_INT;
  B.xtype = CHOLMOD_PATTERN;
  B.dtype = CHOLMOD_DOUBLE;
  B.sorted = 1;
  B.packed = 1;
  const BlockGraphSettings settings(common);
  const auto free_factor = [&common](cholmod_factor* L) { cholmod_free_factor(&L, &common); };
  const std::unique_ptr<cholmod_factor, decltype(free_factor)> L(cholmod_analyze(&B, &common),
                                                                 free_factor);
  if (L == nullptr || common.status != CHOLMOD_OK) return std::nullopt;
  const auto* block_perm = static_cast<const int*>(L->Perm);
  std::vector<int> perm(nb * kBlockSize);
  for (std::size_t k = 0; k < nb; ++k) {
    for (int i = 0; i < kBlockSize; ++i) perm[kBlockSize * k + i] = kBlockSize * block_perm[k] + i;
  }
  return perm;
}

}  // namespace finseg
