// Contact between segments: pair rules, broad phase, narrow phase, normal force (eq. 18),
// friction (eq. 19) and the friction history. docs/contact.md describes the model.
#include "collision/contact_forces.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "collision/broadphase.hpp"
#include "collision/candidate_cache.hpp"
#include "collision/contact_jacobian.hpp"
#include "collision/contact_laws.hpp"
#include "collision/contact_pair.hpp"
#include "collision/joint_stops.hpp"
#include "collision/narrowphase.hpp"
#include "collision/pair_rules.hpp"
#include "elements/assembler.hpp"

namespace finseg {

namespace {

/// Key of one contact point: pair (a < b), direction (0: points of a on b, 1: points of b
/// on a), sample index.
std::uint64_t point_key(int a, int b, int dir, int sample) {
  return (static_cast<std::uint64_t>(a) << 40) | (static_cast<std::uint64_t>(b) << 16) |
         (static_cast<std::uint64_t>(dir) << 12) | static_cast<std::uint64_t>(sample);
}

/// The first anchor of the history with a key not below `key` (the anchors are sorted by key).
std::vector<ContactAnchor>::const_iterator first_anchor_from(const ContactState& cs,
                                                             std::uint64_t key) {
  return std::lower_bound(cs.anchors.begin(), cs.anchors.end(), key,
                          [](const ContactAnchor& x, std::uint64_t k) { return x.key < k; });
}

const ContactAnchor* find_anchor(const ContactState& cs, std::uint64_t key) {
  const auto it = first_anchor_from(cs, key);
  return (it != cs.anchors.end() && it->key == key) ? &*it : nullptr;
}

BodyKin<double> kin_of(const State& s, int i) {
  return {s.p_W[i], s.R_WB[i], s.v_W[i], s.w_W[i]};
}

/// Where the source's point r_B was in the target's frame at the last commit of the history;
/// false when the state has none.
bool committed_place(const State& state, int src, int tgt, const Vec3& r_B, Vec3& was) {
  const ContactState& h = state.contact;
  if (h.p_W.size() != state.p_W.size() || h.R_WB.size() != state.R_WB.size()) return false;
  was = h.R_WB[tgt].transpose() * (h.p_W[src] + h.R_WB[src] * r_B - h.p_W[tgt]);
  return true;
}

/// True for a point kept on `side` that was past the target's mid-plane already at the last
/// commit (sunk into it then): beside the polygon it is still pushed back
/// (collision/sunk_edge.hpp); one that crossed the mid-plane beside it since went round the rim.
bool sunk_at_commit(const State& state, int src, int tgt, const Vec3& r_B, int side) {
  Vec3 was;
  return side != 0 && committed_place(state, src, tgt, r_B, was) && side * was.z() < 0;
}

/// Side of the target plate (+1 / -1 along its normal) a sample point of the source enters
/// the contact from: the side it is on, unless its path since the last commit (straight, in
/// the target's frame) went through the target's face; then the side it came from, so that
/// a step carrying the plates through each other meets the full force. Without history, for
/// nearly parallel plates the side of the source centroid where the point lies within `reach`
/// (the two half thicknesses) of the target's plane (robust for stacks set up with some
/// penetration); a point farther is on its own side (plates at an angle whose planes cross
/// beside each other, as nested folded layers do, are not through each other).
int entry_side(const State& state, int src, int tgt, const Vec3& r_B, const PlateShape& st,
               double reach) {
  const Vec3 now =
      state.R_WB[tgt].transpose() * (state.p_W[src] + state.R_WB[src] * r_B - state.p_W[tgt]);
  Vec3 was;
  if (committed_place(state, src, tgt, r_B, was)) {
    if ((was.z() > 0) != (now.z() > 0)) {
      const Vec3 cross = was + (was.z() / (was.z() - now.z())) * (now - was);
      if (polygon_contains(*st.outline, Vec2(cross.x(), cross.y()), 0)) return was.z() > 0 ? 1 : -1;
    }
    return now.z() >= 0 ? 1 : -1;
  }
  const Vec3 n_tgt = state.R_WB[tgt].col(2);
  const bool parallel = std::abs(n_tgt.dot(state.R_WB[src].col(2))) > std::cos(30 * kDegToRad);
  if (parallel && std::abs(now.z()) < reach) {
    return n_tgt.dot(state.p_W[src] - state.p_W[tgt]) >= 0 ? 1 : -1;
  }
  return now.z() >= 0 ? 1 : -1;
}

/// False when no sample of the source plate can touch the target, decided on the source's
/// vertices in the target frame (the samples lie in their convex hull, and every test below is
/// linear in the point): beyond one of the target's edge lines by more than the two half
/// thicknesses, or all beyond that distance over one face of it, with no point of the pair's
/// direction kept in the history (`anchored`) and, at the last commit, all on that side too
/// (so that entry_side() gives every sample the side it is on). Saves the samples of the many
/// pairs whose boxes overlap only because the plates are tilted.
bool direction_may_touch(const State& state, int src, int tgt, const PlateShape& ss,
                         const PlateShape& st, bool anchored) {
  const Outline& vs = *ss.outline;
  const Outline& vt = *st.outline;
  const double reach = ss.r + st.r;
  thread_local std::vector<Vec3> q;  // source vertices in the target frame
  q.resize(vs.size());
  const Mat3 R_TW = state.R_WB[tgt].transpose();
  for (std::size_t k = 0; k < vs.size(); ++k)
    q[k] =
        R_TW * (state.p_W[src] + state.R_WB[src] * Vec3(vs[k].x(), vs[k].y(), 0) - state.p_W[tgt]);
  for (std::size_t i = 0; i < vt.size(); ++i) {
    const Vec2 nrm = edge_normal(vt, static_cast<int>(i));
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec3& x : q) nearest = std::min(nearest, nrm.dot(Vec2(x.x(), x.y()) - vt[i]));
    if (nearest > reach) return false;
  }
  double lo = q[0].z(), hi = q[0].z();
  for (const Vec3& x : q) lo = std::min(lo, x.z()), hi = std::max(hi, x.z());
  const int above = lo >= reach ? 1 : hi <= -reach ? -1 : 0;
  if (above == 0 || anchored) return true;
  const ContactState& h = state.contact;
  // Without history every sample, beyond reach on that side, is on its own (entry_side).
  if (h.p_W.size() != state.p_W.size() || h.R_WB.size() != state.R_WB.size()) return false;
  const Mat3 R_TW_was = h.R_WB[tgt].transpose();
  for (const Vec2& v : vs) {
    const double was =
        (R_TW_was * (h.p_W[src] + h.R_WB[src] * Vec3(v.x(), v.y(), 0) - h.p_W[tgt])).z();
    if (!(above * was > 0)) return true;
  }
  return false;
}

/// True when the history keeps a point of pair (a, b) in direction `dir`.
bool anchored(const ContactState& cs, int a, int b, int dir) {
  const std::uint64_t first = point_key(a, b, dir, 0);
  const auto it = first_anchor_from(cs, first);
  return it != cs.anchors.end() && it->key < first + (std::uint64_t{1} << 12);
}

/// What a detection is for: forces see the points that push (penetration beyond their
/// overlap); a commit keeps every point that touches, so that its overlap can shrink; the
/// commit at the start of a run gives new points their overlap under `initial_overlap: ignore`.
enum class DetectFor { Forces, Commit, Start };

/// The pairs whose boxes overlap at the poses of `state` and that the rules allow: from the
/// candidates of the last commit where they cover these poses, else by a fresh search.
std::vector<std::pair<int, int>> candidate_pairs(const Model& model, const State& state,
                                                 const ContactCandidates* kept) {
  // Buffers kept per thread between calls: large models then detect without page faults.
  thread_local std::vector<Aabb> boxes;
  thread_local BroadPhase broad;
  if (kept != nullptr && covers(*kept, model, state))
    return present_pairs(*kept, model, state, boxes);
  return contact_candidates(model, state, PairRules(model), broad, boxes);
}

/// Calls visit(const PairContact&) for every touching pair, in pair order; `kept`: candidates
/// that may serve (null: search afresh).
template <class Visit>
void detect(const Model& model, const State& state, DetectFor what, const ContactCandidates* kept,
            Visit&& visit) {
  const ContactDef& def = model.contact;
  thread_local PairContact pc;
  const auto candidates = candidate_pairs(model, state, kept);
  for (const auto& [a, b] : candidates) {
    pc.a = a;
    pc.b = b;
    pc.sa = plate_shape(model.bodies[a]);
    pc.sb = plate_shape(model.bodies[b]);
    pc.points.clear();
    const DirectionShares shares = direction_shares(pc.sa, pc.sb);
    for (int dir = 0; dir < 2; ++dir) {
      const double dir_share = dir == 0 ? shares.a_on_b : shares.b_on_a;
      if (dir_share <= 0) continue;
      const int src = dir == 0 ? a : b, tgt = dir == 0 ? b : a;
      const PlateShape& ss = dir == 0 ? pc.sa : pc.sb;
      const PlateShape& st = dir == 0 ? pc.sb : pc.sa;
      if (!direction_may_touch(state, src, tgt, ss, st, anchored(state.contact, a, b, dir)))
        continue;
      const BodyKin<double> S = kin_of(state, src), G = kin_of(state, tgt);
      const std::vector<PlateSample> samples = plate_samples(ss, def.samples_per_edge);
      for (int k = 0; k < static_cast<int>(samples.size()); ++k) {
        const Vec3 p_W = S.point_W(samples[k].r_B);
        const ContactAnchor* an = find_anchor(state.contact, point_key(a, b, dir, k));
        const bool ignored =
            !an && what == DetectFor::Start && def.initial_overlap == InitialOverlap::Ignore;
        // Overlapping layers that have not parted have no side: the one the point is on now.
        const int kept = an        ? an->side
                         : ignored ? 0
                                   : entry_side(state, src, tgt, samples[k].r_B, st, ss.r + st.r);
        const int side = kept != 0 ? kept : G.R_WB.col(2).dot(p_W - G.p_W) >= 0 ? 1 : -1;
        const bool sunk = an && sunk_at_commit(state, src, tgt, samples[k].r_B, an->side);
        const PointContact<double> c = point_on_plate(G, st, p_W, ss.r, side, sunk);
        if (!(c.depth > 0)) continue;
        const double overlap = ignored ? c.depth : an ? an->overlap : 0;
        // No force before the point has a side: the layers pass each other freely until then.
        if (what == DetectFor::Forces && (kept == 0 || !(c.depth > overlap))) continue;
        pc.points.push_back(
            {dir, k, samples[k].r_B, dir_share * samples[k].weight, side, kept, an, overlap, sunk});
      }
    }
    if (!pc.points.empty()) visit(std::as_const(pc));
  }
}

/// Friction force of one point for scalar T (eq. 19 or the anchor spring).
/// `report` (may be null) records which caps acted.
template <class T>
Vec3T<T> friction_force(const ContactDef& def, const ActivePoint& pt, const T& fn,
                        const Vec3T<T>& n, const Vec3T<T>& v_t, const BodyKin<T>& src,
                        const BodyKin<T>& tgt, PointReport* report) {
  if (def.friction == FrictionModel::Continuous ||
      (def.friction == FrictionModel::Anchor && pt.anchor == nullptr))
    return continuous_friction(def, fn, v_t, lag_speed(def, pt));
  if (def.friction != FrictionModel::Anchor) return Vec3T<T>::Zero();
  using std::sqrt;
  const ContactAnchor& an = *pt.anchor;
  const Vec3T<T> z = src.point_W(an.r_src_B) - tgt.point_W(an.r_tgt_B);
  const Vec3T<T> z_t = z - n * n.dot(z);
  const T limit = T(an.sliding ? def.mu_dynamic : def.mu_static) * fn;
  bool ignored = false;
  auto capped = [&](const Vec3T<T>& f, bool& was_capped) {
    const T f2 = f.squaredNorm();
    was_capped = !(value_of(f2) <= value_of(limit) * value_of(limit));
    if (!was_capped) return f;
    return value_of(f2) > 0 ? Vec3T<T>(f * (limit / sqrt(f2))) : Vec3T<T>(Vec3T<T>::Zero());
  };
  const Vec3T<T> spring = -T(pt.share * def.tangential_stiffness) * z_t;
  const Vec3T<T> damper = -T(pt.share * def.tangential_damping) * v_t;
  // Sticking, the damper acts beside the capped spring: capping their sum takes the damping
  // away just when a load comes on, and the spring then overshoots the static limit (a plate
  // set down on an incline at 26 deg slid off with mu_s = 0.5). Sliding, the sum is capped.
  bool& spring_capped = report ? report->spring_capped : ignored;
  bool& damper_capped = report ? report->damper_capped : ignored;
  if (!an.sliding) return Vec3T<T>(capped(spring, spring_capped) + capped(damper, damper_capped));
  return capped(spring + damper, spring_capped);
}

/// Forces of one pair for scalar T; adds them to the two wrenches, returns elastic energy.
template <class T>
T evaluate_pair(const ContactDef& def, const PairContact& pc, const BodyKin<T>& A,
                const BodyKin<T>& B, Wrench<T>& wa, Wrench<T>& wb,
                std::vector<PointReport>* report) {
  double energy = 0;
  for (const ActivePoint& pt : pc.points) {
    const BodyKin<T>& src = pt.dir == 0 ? A : B;
    const BodyKin<T>& tgt = pt.dir == 0 ? B : A;
    Wrench<T>& w_src = pt.dir == 0 ? wa : wb;
    Wrench<T>& w_tgt = pt.dir == 0 ? wb : wa;
    const PlateShape& ss = pt.dir == 0 ? pc.sa : pc.sb;
    const PlateShape& st = pt.dir == 0 ? pc.sb : pc.sa;
    const PointContact<T> c = point_on_plate(tgt, st, src.point_W(pt.r_B), ss.r, pt.side, pt.sunk);
    const T depth = c.depth - T(pt.overlap);  // what the force pushes against
    const Vec3T<T> v_rel =
        (src.v_W + src.w_W.cross(c.x_W - src.p_W)) - (tgt.v_W + tgt.w_W.cross(c.x_W - tgt.p_W));
    const T rate = -c.n_W.dot(v_rel);
    const double v0 = pt.anchor ? pt.anchor->impact_speed : value_of(rate);
    const T fn = T(pt.share) * normal_force(def, depth, rate, v0);
    energy += pt.share * contact_energy(def, value_of(depth));
    const Vec3T<T> v_t = v_rel - c.n_W * c.n_W.dot(v_rel);
    PointReport r;
    const Vec3T<T> f_t = friction_force(def, pt, fn, c.n_W, v_t, src, tgt, report ? &r : nullptr);
    const Vec3T<T> f = fn * c.n_W + f_t;
    w_src.add_force_at(f, c.x_W, src.p_W);
    w_tgt.add_force_at(-f, c.x_W, tgt.p_W);
    if (report) {
      for (int i = 0; i < 3; ++i) {
        r.x_W[i] = value_of(c.x_W[i]);
        r.n_W[i] = value_of(c.n_W[i]);
        r.v_t[i] = value_of(v_t[i]);
        r.f_t[i] = value_of(f_t[i]);
      }
      r.depth = value_of(depth);
      r.normal = value_of(fn);
      r.friction = r.f_t.norm();
      r.share = pt.share;
      r.penetration_rate = value_of(rate);
      r.dist = value_of(c.dist);
      r.height = value_of(c.height);
      r.du = value_of(c.du);
      r.dv = value_of(c.dv);
      r.feature = c.feature;
      report->push_back(r);
    }
  }
  return T(energy);
}

/// Shrinks an overlapped point's overlap to its penetration when the plates have parted
/// further than before (`r.depth` is the penetration beyond `overlap` the kernel saw, `radii`
/// the plates' half thicknesses summed). A point with no side yet takes the side it is on once
/// the plates are a quarter of their thickness apart (coinciding layers choose their order by
/// how they part, not by round-off or the first step's jitter). False when it no longer touches.
bool part_overlap(ContactAnchor& an, const PointReport& r, double overlap, double radii) {
  const double touching = r.depth + overlap;
  if (an.side == 0) {
    if (touching > 0.75 * radii) return true;
    an.side = r.height >= 0 ? 1 : -1;
  }
  an.overlap = std::min(overlap, touching);
  return touching > 0;
}

}  // namespace

void add_contact_forces(const Model& model, const State& state, Assembler& assembler) {
  if (!model.contact.enabled) return;
  validate_contact(model.contact, model.source);  // models built through the API
  const ContactDef& def = model.contact;
  if (assembler.want_jacobian() && assembler.autodiff_elements()) {
    // The automatic-differentiation oracle of the closed form.
    detect(model, state, DetectFor::Forces, state.contact.candidates.get(),
           [&](const PairContact& pc) {
             assembler.pair(pc.a, pc.b, [&](const auto& A, const auto& B, auto& wa, auto& wb) {
               return evaluate_pair(def, pc, A, B, wa, wb, nullptr);
             });
           });
    return;
  }
  const bool jacobian = assembler.want_jacobian();
  const bool with_velocity = assembler.want_velocity_jacobian();
  const FrictionSlope slope =
      assembler.friction_secant() ? FrictionSlope::Secant : FrictionSlope::Tangent;
  std::vector<PointReport> reports;
  detect(
      model, state, DetectFor::Forces, state.contact.candidates.get(), [&](const PairContact& pc) {
        const BodyKin<double> A = assembler.kin(pc.a), B = assembler.kin(pc.b);
        Wrench<double> wa, wb;
        reports.clear();
        assembler.add_energy(evaluate_pair(def, pc, A, B, wa, wb, jacobian ? &reports : nullptr));
        assembler.add(pc.a, wa);
        assembler.add(pc.b, wb);
        if (!jacobian) return;
        const PairSlots slots = assembler.reserve_pair(pc.a, pc.b, with_velocity);
        if (!slots.any()) return;
        Mat12 dq = Mat12::Zero(), dv = Mat12::Zero();
        if (add_contact_pair_jacobian(def, pc, reports, A, B, slots.with_velocity, slope, dq, dv)) {
          assembler.mark_secant_differs();
        }
        assembler.fill_pair(slots, dq, dv);
      });
}

void commit_contact_history(const Model& model, State& state, bool start) {
  if (!model.contact.enabled) {
    state.contact = ContactState{};
    return;
  }
  const ContactDef& def = model.contact;
  std::vector<ContactAnchor> next;
  std::vector<PointReport> rep;
  // The candidates of the next step's detections, found here once with grown boxes.
  std::shared_ptr<const ContactCandidates> found = find_contact_candidates(model, state);
  detect(model, state, start ? DetectFor::Start : DetectFor::Commit, found.get(),
         [&](const PairContact& pc) {
           rep.clear();
           const BodyKin<double> A = kin_of(state, pc.a), B = kin_of(state, pc.b);
           Wrench<double> wa, wb;
           evaluate_pair(def, pc, A, B, wa, wb, &rep);
           for (std::size_t k = 0; k < rep.size(); ++k) {
             const PointReport& r = rep[k];
             const ActivePoint& pt = pc.points[k];
             const BodyKin<double>& src = pt.dir == 0 ? A : B;
             const BodyKin<double>& tgt = pt.dir == 0 ? B : A;
             ContactAnchor an;
             an.key = point_key(pc.a, pc.b, pt.dir, pt.sample);
             const double kt = r.share * def.tangential_stiffness;
             if (pt.anchor) {
               an = *pt.anchor;
               if (def.friction == FrictionModel::Anchor && kt > 0) {
                 const Vec3 xs = src.point_W(an.r_src_B), xt = tgt.point_W(an.r_tgt_B);
                 const Vec3 z = xs - xt;
                 const Vec3 z_t = z - r.n_W * r.n_W.dot(z);
                 const double mu = an.sliding ? def.mu_dynamic : def.mu_static;
                 if (kt * z_t.norm() > mu * r.normal) {
                   // Slipping: drag the anchor so that the spring carries the dynamic limit.
                   an.sliding = true;
                   const Vec3 z_new = z_t * (def.mu_dynamic * r.normal / (kt * z_t.norm()));
                   an.r_src_B = src.R_WB.transpose() * (xt + z_new - src.p_W);
                 } else if (an.sliding && r.v_t.norm() < def.stiction_speed) {
                   an.sliding = false;
                 }
               }
             } else {
               an.side = pt.anchor_side;
               an.overlap = pt.overlap;
               an.impact_speed = r.penetration_rate;
               an.sliding = false;
               // New anchor placed so that its spring starts with the friction force just applied.
               Vec3 offset = Vec3::Zero();
               if (def.friction == FrictionModel::Anchor && kt > 0) offset = -r.f_t / kt;
               an.r_tgt_B = tgt.R_WB.transpose() * (r.x_W - tgt.p_W);
               an.r_src_B = src.R_WB.transpose() * (r.x_W + offset - src.p_W);
             }
             // Beside the polygon, past the mid-plane, not sunk at the last commit: it went
             // round the rim and is on the side it is on (the rim's force either way).
             if (!pt.sunk && an.side * r.height < 0 && (r.du != 0 || r.dv != 0)) an.side = -an.side;
             an.slip_speed = r.v_t.norm();
             if (pt.overlap > 0 && !part_overlap(an, r, pt.overlap, pc.sa.r + pc.sb.r)) continue;
             next.push_back(an);
           }
         });
  std::sort(next.begin(), next.end(),
            [](const ContactAnchor& x, const ContactAnchor& y) { return x.key < y.key; });
  state.contact.anchors = std::move(next);
  state.contact.p_W = state.p_W;
  state.contact.R_WB = state.R_WB;
  state.contact.candidates = std::move(found);
}

namespace {

// Joints folded flat press as contact does (collision/joint_stops.hpp): one point each, no
// friction, a couple and no net force on the pair.
void add_stop_reports(const Model& model, const State& state, ContactSummary& s) {
  for (const JointStopReport& r : joint_stop_reports(model, state)) {
    ++s.active;
    s.total_normal_force += r.force;
    s.max_penetration = std::max(s.max_penetration, r.depth);
    s.points_W.push_back(r.x_W);
    s.point_normal.push_back(r.force);
    s.point_penetration.push_back(r.depth);
    s.point_friction.push_back(0);
    ContactPairForce pair;
    pair.a = std::min(r.inner, r.outer);
    pair.b = std::max(r.inner, r.outer);
    pair.points = 1;
    pair.normal_force = r.force;
    pair.max_penetration = r.depth;
    s.pairs.push_back(pair);
  }
  std::stable_sort(s.pairs.begin(), s.pairs.end(), [](const auto& x, const auto& y) {
    return std::pair(x.a, x.b) < std::pair(y.a, y.b);
  });
}

}  // namespace

ContactSummary contact_summary(const Model& model, const State& state) {
  ContactSummary s;
  if (!model.contact.enabled) return s;
  std::vector<PointReport> rep;
  detect(model, state, DetectFor::Forces, state.contact.candidates.get(),
         [&](const PairContact& pc) {
           rep.clear();
           Wrench<double> wa, wb;
           evaluate_pair(model.contact, pc, kin_of(state, pc.a), kin_of(state, pc.b), wa, wb, &rep);
           ContactPairForce pair;
           pair.a = pc.a;
           pair.b = pc.b;
           for (const PointReport& r : rep) {
             ++s.active;
             s.total_normal_force += r.normal;
             s.total_friction_force += r.friction;
             s.max_penetration = std::max(s.max_penetration, r.depth);
             s.points_W.push_back(r.x_W);
             s.point_normal.push_back(r.normal);
             s.point_penetration.push_back(r.depth);
             s.point_friction.push_back(r.friction);
             ++pair.points;
             pair.normal_force += r.normal;
             pair.friction_force += r.friction;
             pair.max_penetration = std::max(pair.max_penetration, r.depth);
             // Force on b: the reported normal points from the target towards the source point.
             const double sign = pc.points[&r - rep.data()].dir == 0 ? -1.0 : 1.0;
             pair.f_b_W += sign * (r.normal * r.n_W + r.f_t);
           }
           s.pairs.push_back(pair);
         });
  add_stop_reports(model, state, s);
  return s;
}

}  // namespace finseg
