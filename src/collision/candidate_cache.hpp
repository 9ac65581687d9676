// Contact candidates kept between detections (a Verlet list): the broad phase run once, at a
// commit, with every box grown by a margin; the allowed pairs kept with the poses they were
// found at. While no segment has moved further than the margin since (its centre's
// displacement plus its reach times the chord of its turn), every pair whose boxes overlap now
// is among the kept ones, so testing the kept pairs' present boxes gives the candidates a fresh
// search gives, in the same order: the same contact to the bit, without the grid, its sort
// and the pair rules at every force evaluation (docs/contact.md, "Broad phase").
#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "collision/broadphase.hpp"
#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// Candidate pairs found with grown boxes, and where they were found. Immutable once made;
/// States share it (ContactState::candidates).
struct ContactCandidates {
  const Model* model = nullptr;     ///< the model they were found for ...
  const BodyDef* bodies = nullptr;  ///< ... and its segments (a model at a reused address
  std::size_t count = 0;            ///<     with other segments is not served)
  double margin = 0;                ///< m, by which every box was grown
  std::vector<Vec3> p_W;            ///< segment poses they were found at
  std::vector<Mat3> R_WB;
  std::vector<double> reach;  ///< per segment: farthest outline vertex from its origin, m
  std::vector<std::pair<int, int>> pairs;  ///< allowed pairs whose grown boxes overlap (sorted)
};

/// Finds the candidates at the poses of `state` (a commit's, before it records them) with the
/// boxes grown by a margin: twice the largest distance a segment moved since the last commit
/// (the poses in `state.contact`), at least the thinnest segment's thickness, at most the median
/// box extent (beyond it a fresh search is as cheap).
std::shared_ptr<const ContactCandidates> find_contact_candidates(const Model& model,
                                                                 const State& state);

/// True when `c` was found for `model` and no segment of `state` has moved by its margin.
bool covers(const ContactCandidates& c, const Model& model, const State& state);

/// The pairs of `c` whose boxes (grown by the model's contact margin only) overlap at the poses
/// of `state`, as contact_candidates() finds them; `boxes` is a buffer. Needs covers().
std::vector<std::pair<int, int>> present_pairs(const ContactCandidates& c, const Model& model,
                                               const State& state, std::vector<Aabb>& boxes);

}  // namespace finseg
