// Which pairs of segments may touch (docs/contact.md, "Which pairs"): a rule on the model's
// connectivity and material coordinates, not a list of panels. Built once per detection.
#pragma once

#include <utility>
#include <vector>

#include "collision/broadphase.hpp"
#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// Width of the crease zone of a pair of segments, m: ContactDef::crease_zone when set,
/// else twice the larger of the two thicknesses.
double crease_zone_width(const ContactDef& c, const BodyDef& a, const BodyDef& b);

/// Excludes pairs that are both fixed, joined by a force element, share a vertex of their
/// outlines through the force elements (also across a seam), lie within the crease zone of each
/// other on the flat sheet, or are excluded by `panel_exclusion` / `groups`.
class PairRules {
 public:
  explicit PairRules(const Model& m);
  bool may_touch(int a, int b) const;

 private:
  bool shares_vertex(int a, int b) const;
  bool within_hops(int a, int b, int panel) const;

  const Model& model_;
  const ContactDef& def_;
  std::vector<int> start_, nbr_;      // bodies joined by elements (CSR)
  std::vector<int> vstart_, vclass_;  // per body: sorted vertex classes (CSR)
  std::vector<char> allowed_;         // groups: panel x panel
  int panels_ = 0;
};

/// Candidate pairs (a < b, sorted) at the poses of `state`: broad-phase overlaps of the plates'
/// boxes that `rules` allow. `broad` and `boxes` are buffers kept between calls.
std::vector<std::pair<int, int>> contact_candidates(const Model& model, const State& state,
                                                    const PairRules& rules, BroadPhase& broad,
                                                    std::vector<Aabb>& boxes);

}  // namespace finseg
