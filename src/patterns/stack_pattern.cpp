#include "patterns/stack_pattern.hpp"

#include <fmt/format.h>

#include "core/error.hpp"

namespace finseg {

CreasePattern folded_stack_pattern(int layers, int cells, double cell, double gap) {
  if (layers < 1 || cells < 1 || !(cell > 0) || !(gap > 0)) {
    throw InputError("<api>", "stack",
                     fmt::format("{} layers of {} x {} cells of {} m, gap {} m; need >= 1 "
                                 "layer and cell, positive lengths",
                                 layers, cells, cells, cell, gap));
  }
  CreasePattern p;
  p.meta.file_creator = "finseg";
  p.meta.frame_title = fmt::format("stack of {} folded layers", layers);
  p.has_fold_angles = true;
  const double L = cells * cell;
  // Columns of vertices along x: cells + 1 per layer; column c of layer k at material
  // x = k (L + gap) + c cell.
  const int per = cells + 1, columns = layers * per;
  auto id = [&](int column, int row) { return column * (cells + 1) + row; };
  std::vector<int> layer_of(columns), fold_column(columns, 0);
  for (int k = 0; k < layers; ++k) {
    for (int c = 0; c < per; ++c) {
      const int col = k * per + c;
      layer_of[col] = k;
      const double u = c * cell;  // along the layer from its start on the flat sheet
      for (int r = 0; r <= cells; ++r) {
        p.vertices_flat_m.emplace_back(k * (L + gap) + u, r * cell);
        p.vertices_folded_m.emplace_back(k % 2 == 0 ? u : L - u, r * cell, k * gap);
      }
    }
    if (k > 0) fold_column[k * per] = fold_column[k * per - 1] = 1;
  }
  for (int col = 0; col + 1 < columns; ++col) {
    for (int r = 0; r < cells; ++r)
      p.faces.push_back({id(col, r), id(col + 1, r), id(col + 1, r + 1), id(col, r + 1)});
  }
  p.edges = edges_from_faces(p.faces);
  for (PatternEdge& e : p.edges) {
    if (e.assignment == EdgeAssignment::Boundary) continue;
    const int col = e.vertices[0] / (cells + 1);
    if (e.vertices[1] / (cells + 1) != col || !fold_column[col]) {
      e.assignment = EdgeAssignment::Join;
      continue;
    }
    // The fold after layer k turns the sheet over towards its flat +z face for even k.
    const int k = layer_of[col] - (col % per == 0 ? 1 : 0);
    const bool valley = k % 2 == 0;
    e.assignment = valley ? EdgeAssignment::Valley : EdgeAssignment::Mountain;
    e.fold_angle = (valley ? 1 : -1) * 0.5 * kPi;
  }
  derive_edge_faces(p, "<stack>");
  return p;
}

}  // namespace finseg
