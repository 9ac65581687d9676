// A strip folded flat into a stack of layers: the pattern of the contact tests and benchmarks
// (docs/contact.md), with its folded coordinates.
#pragma once

#include "patterns/crease_pattern.hpp"

namespace finseg {

/// `layers` square layers of `cells` x `cells` square faces of edge `cell` (m), joined one to
/// the next by a fold: a row of `cells` faces `gap` (m) wide on the flat sheet that stands
/// upright between the two layers when folded, its two sides creases folded 90 degrees each
/// (valley, valley between layers 1-2, mountain, mountain between 2-3, ...). Flat: the layers
/// follow each other along x. Folded: layer k (0-based) lies at z = k gap, over x in
/// [0, cells cell], every other one turned over; the folds alternate between its two ends.
/// Faces inside a layer are joined by J edges.
CreasePattern folded_stack_pattern(int layers, int cells, double cell, double gap);

}  // namespace finseg
