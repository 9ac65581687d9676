// Bending of a plate cut into cells of any shape by a consistent discrete Hessian
// (docs/stiffness.md, "Triangular cells"): each cell's curvature from Green's formula over its
// sides with one gradient per side, shared by the two cells, plus a stabilisation that vanishes
// for every quadratic deflection. Replaces the plate joints' bending and twist springs.
#pragma once

#include <vector>

#include "model/model.hpp"
#include "patterns/segment_mesh.hpp"

namespace finseg {

/// One energy per free cell, in the relative rotations of the elements around it and around its
/// neighbours. `link_element[k]` is the element on mesh.links[k]; `weight` of an element is the
/// rotational stiffness its side would have as a plate joint (D l / h, N m), read from K[4] of
/// `elements` (which must still hold it). Across a seam the neighbour is unrolled next to the
/// cell (its material coordinates turned onto the cell's copy of the side).
/// `stabilisation`: weight of the fit residuals against the joints' stiffness (see the doc).
std::vector<PlateCellDef> plate_hessian_cells(const SegmentMesh& mesh, const Model& model,
                                              const std::vector<int>& link_element, double D,
                                              double nu, double stabilisation = 0.1);

}  // namespace finseg
