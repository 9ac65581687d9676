// Verlet list of contact candidates.
#include "collision/candidate_cache.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "collision/pair_rules.hpp"
#include "model/segment_shape.hpp"

namespace finseg {
namespace {

// Farthest any point of a segment of reach `reach` moved from pose (p0, R0) to (p, R): the
// centre's displacement plus reach |R - R0|_2, the chord 2 sin(theta / 2) = sqrt(3 - tr(R R0^T))
// of the turn theta between them.
double moved(const Vec3& p0, const Mat3& R0, const Vec3& p, const Mat3& R, double reach) {
  const double trace = R.cwiseProduct(R0).sum();
  return (p - p0).norm() + reach * std::sqrt(std::max(0.0, 3 - trace));
}

}  // namespace

std::shared_ptr<const ContactCandidates> find_contact_candidates(const Model& model,
                                                                 const State& state) {
  auto c = std::make_shared<ContactCandidates>();
  const std::size_t n = model.bodies.size();
  c->model = &model;
  c->bodies = model.bodies.data();
  c->count = n;
  c->p_W = state.p_W;
  c->R_WB = state.R_WB;
  c->reach.resize(n);
  // One pass: each segment's reach, box and motion since the last commit.
  const ContactState& was = state.contact;
  const bool known = was.p_W.size() == n && was.R_WB.size() == n;
  double thinnest = std::numeric_limits<double>::infinity(), last = 0;
  std::vector<Aabb> boxes(n);
  std::vector<double> extents(n);
  for (std::size_t i = 0; i < n; ++i) {
    const BodyDef& b = model.bodies[i];
    c->reach[i] = outline_radius(b.outline_B);
    thinnest = std::min(thinnest, b.thickness);
    boxes[i] = plate_aabb(state.p_W[i], state.R_WB[i], b, 0);
    extents[i] = (boxes[i].hi - boxes[i].lo).maxCoeff();
    if (known)
      last =
          std::max(last, moved(was.p_W[i], was.R_WB[i], state.p_W[i], state.R_WB[i], c->reach[i]));
  }
  if (n == 0) return c;
  std::nth_element(extents.begin(), extents.begin() + n / 2, extents.end());
  c->margin = std::min(std::max(2 * last, thinnest), extents[n / 2]);
  const Vec3 grow = Vec3::Constant(model.contact.margin + c->margin);
  for (Aabb& box : boxes) box = {box.lo - grow, box.hi + grow};
  thread_local BroadPhase broad;
  c->pairs = broad.find_pairs(boxes);
  const PairRules rules(model);
  c->pairs.erase(std::remove_if(c->pairs.begin(), c->pairs.end(),
                                [&](const auto& p) { return !rules.may_touch(p.first, p.second); }),
                 c->pairs.end());
  return c;
}

bool covers(const ContactCandidates& c, const Model& model, const State& state) {
  const std::size_t n = model.bodies.size();
  if (c.model != &model || c.bodies != model.bodies.data() || c.count != n ||
      state.p_W.size() != n || state.R_WB.size() != n)
    return false;
  // A tenth of the margin left for the round-off of the boxes.
  const double allowed = 0.9 * c.margin;
  for (std::size_t i = 0; i < n; ++i)
    if (!(moved(c.p_W[i], c.R_WB[i], state.p_W[i], state.R_WB[i], c.reach[i]) <= allowed))
      return false;
  return true;
}

std::vector<std::pair<int, int>> present_pairs(const ContactCandidates& c, const Model& model,
                                               const State& state, std::vector<Aabb>& boxes) {
  const std::size_t n = model.bodies.size();
  boxes.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    boxes[i] = plate_aabb(state.p_W[i], state.R_WB[i], model.bodies[i], model.contact.margin);
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(c.pairs.size());
  for (const auto& p : c.pairs)
    if (boxes_overlap(boxes[p.first], boxes[p.second])) pairs.push_back(p);
  return pairs;
}

}  // namespace finseg
