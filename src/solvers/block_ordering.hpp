// Fill-reducing orderings of Newton matrices found on the graph of their 6 x 6 blocks
// (BENCHMARKS.md, "Orderings on the block graph").
#pragma once

#include <cholmod.h>

#include <Eigen/SparseCore>
#include <optional>
#include <vector>

namespace finseg {

/// The DOFs a segment has: Newton matrices are made of blocks of this size.
constexpr int kBlockSize = 6;

/// The block graph of S (lower triangle used) where S is made of dense, aligned 6 x 6 blocks
/// (each block column's six columns hold the same rows, in aligned runs of six), as CSC
/// indices of its lower triangle; nullopt for any other pattern.
struct BlockGraph {
  std::vector<int> outer, inner;
};
std::optional<BlockGraph> block_graph(const Eigen::SparseMatrix<double>& S);

/// A fill-reducing permutation of S's rows and columns (CHOLMOD's Perm: position k holds the
/// old index), found by CHOLMOD on S's block graph with the orderings of `common`'s
/// `nmethods` (the one of fewest flops kept) and expanded block by block; nullopt where S is
/// not made of 6 x 6 blocks or CHOLMOD failed. The graph has 36 times fewer entries than S,
/// so the ordering costs a fraction of one on S; the fill is the same as that of the ordering
/// on S (a block's six DOFs are indistinguishable to the elimination).
std::optional<std::vector<int>> block_ordering(const Eigen::SparseMatrix<double>& S,
                                               cholmod_common& common);

}  // namespace finseg
