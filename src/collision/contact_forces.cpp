// Contact between segments: pair rules, broad phase, narrow phase, normal force (eq. 18),
// friction (eq. 19) and the friction history. docs/contact.md describes the model.
#include "collision/contact_forces.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "collision/broadphase.hpp"
#include "collision/contact_laws.hpp"
#include "collision/narrowphase.hpp"
#include "elements/assembler.hpp"

namespace finseg {

namespace {

/// Key of one contact point: pair (a < b), which plate is the reference, vertex identity.
std::uint64_t point_key(int a, int b, bool ref_is_a, int vertex_id) {
  return (static_cast<std::uint64_t>(a) << 40) | (static_cast<std::uint64_t>(b) << 16) |
         (static_cast<std::uint64_t>(ref_is_a ? 1 : 0) << 8) |
         static_cast<std::uint64_t>(vertex_id);
}

const ContactAnchor* find_anchor(const ContactState& cs, std::uint64_t key) {
  const auto it =
      std::lower_bound(cs.anchors.begin(), cs.anchors.end(), key,
                       [](const ContactAnchor& x, std::uint64_t k) { return x.key < k; });
  return (it != cs.anchors.end() && it->key == key) ? &*it : nullptr;
}

/// Reference plate the pair used at the last accepted step (0 = a, 1 = b), -1 if none.
int previous_reference(const ContactState& cs, int a, int b) {
  const std::uint64_t lo = point_key(a, b, false, 0), hi = point_key(a, b, true, 255);
  const auto it =
      std::lower_bound(cs.anchors.begin(), cs.anchors.end(), lo,
                       [](const ContactAnchor& x, std::uint64_t k) { return x.key < k; });
  if (it == cs.anchors.end() || it->key > hi) return -1;
  return ((it->key >> 8) & 1) ? 0 : 1;
}

/// Which pairs may touch (docs/contact.md, "Which pairs"): built once per evaluation.
class PairRules {
 public:
  explicit PairRules(const Model& m) : model_(m), def_(m.contact) {
    const int n = static_cast<int>(m.bodies.size());
    start_.assign(n + 1, 0);
    for (const ElementDef& e : m.elements) {
      if (e.inner < 0 || e.outer < 0 || e.inner >= n || e.outer >= n) continue;
      ++start_[e.inner + 1];
      ++start_[e.outer + 1];
    }
    for (int i = 0; i < n; ++i) start_[i + 1] += start_[i];
    nbr_.resize(start_[n]);
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (const ElementDef& e : m.elements) {
      if (e.inner < 0 || e.outer < 0 || e.inner >= n || e.outer >= n) continue;
      nbr_[fill[e.inner]++] = e.outer;
      nbr_[fill[e.outer]++] = e.inner;
    }
    if (!def_.groups.empty()) {
      int panels = 0;
      for (const BodyDef& b : m.bodies) panels = std::max(panels, b.panel + 1);
      for (const auto& g : def_.groups)
        for (int p : g) panels = std::max(panels, p + 1);
      panels_ = panels;
      allowed_.assign(static_cast<std::size_t>(panels) * panels, 0);
      for (const auto& g : def_.groups)
        for (int p : g)
          for (int q : g) allowed_[static_cast<std::size_t>(p) * panels + q] = 1;
    }
  }

  bool may_touch(int a, int b) const {
    const BodyDef& A = model_.bodies[a];
    const BodyDef& B = model_.bodies[b];
    if (A.fixed && B.fixed) return false;
    if (!allowed_.empty()) {
      if (A.panel < 0 || B.panel < 0) return false;
      if (!allowed_[static_cast<std::size_t>(A.panel) * panels_ + B.panel]) return false;
    }
    for (int k = start_[a]; k < start_[a + 1]; ++k)
      if (nbr_[k] == b) return false;
    // Neighbours on the flat sheet (also diagonal ones and across a crease) share an edge
    // or a corner that the joints hold together: never a contact.
    if (A.s_max > A.s_min && B.s_max > B.s_min && A.y_max > A.y_min && B.y_max > B.y_min) {
      const double tol = 1e-3 * std::min({A.s_max - A.s_min, B.s_max - B.s_min, A.y_max - A.y_min,
                                          B.y_max - B.y_min});
      const double gap_s = std::max(A.s_min, B.s_min) - std::min(A.s_max, B.s_max);
      const double gap_y = std::max(A.y_min, B.y_min) - std::min(A.y_max, B.y_max);
      if (gap_s <= tol && gap_y <= tol) return false;
    }
    if (A.panel == B.panel && def_.panel_exclusion > 0 && within_hops(a, b, A.panel)) return false;
    return true;
  }

 private:
  // Breadth-first search from a inside its panel, at most panel_exclusion elements deep.
  bool within_hops(int a, int b, int panel) const {
    std::vector<int> frontier{a}, next, seen{a};
    for (int depth = 0; depth < def_.panel_exclusion && !frontier.empty(); ++depth) {
      next.clear();
      for (int i : frontier)
        for (int k = start_[i]; k < start_[i + 1]; ++k) {
          const int j = nbr_[k];
          if (model_.bodies[j].panel != panel) continue;
          if (j == b) return true;
          if (std::find(seen.begin(), seen.end(), j) != seen.end()) continue;
          seen.push_back(j);
          next.push_back(j);
        }
      std::swap(frontier, next);
    }
    return false;
  }

  const Model& model_;
  const ContactDef& def_;
  std::vector<int> start_, nbr_;
  std::vector<char> allowed_;
  int panels_ = 0;
};

/// One touching pair after the narrow phase.
struct PairContact {
  int a = -1, b = -1;
  PlateShape sa, sb;
  Manifold m;
  std::array<bool, 8> active{};
  std::array<int, 8> side{};
  std::array<const ContactAnchor*, 8> anchor{};
};

/// Calls visit(const PairContact&) for every touching pair, in pair order.
template <class Visit>
void detect(const Model& model, const State& state, Visit&& visit) {
  const ContactDef& def = model.contact;
  const int n = static_cast<int>(model.bodies.size());
  // Buffers kept per thread between calls: large models then detect without page faults.
  thread_local std::vector<Aabb> boxes;
  thread_local BroadPhase broad;
  boxes.resize(n);
  for (int i = 0; i < n; ++i)
    boxes[i] = plate_aabb(state.p_W[i], state.R_WB[i], model.bodies[i].size, def.margin);
  const auto candidates = broad.find_pairs(boxes);
  if (candidates.empty()) return;
  const PairRules rules(model);
  for (const auto& [a, b] : candidates) {
    if (!rules.may_touch(a, b)) continue;
    PairContact pc;
    pc.a = a;
    pc.b = b;
    pc.sa = plate_shape(model.bodies[a].size);
    pc.sb = plate_shape(model.bodies[b].size);
    const BodyKin<double> A{state.p_W[a], state.R_WB[a], state.v_W[a], state.w_W[a]};
    const BodyKin<double> B{state.p_W[b], state.R_WB[b], state.v_W[b], state.w_W[b]};
    if (!clip_plates(A, pc.sa, B, pc.sb, previous_reference(state.contact, a, b), pc.m)) continue;
    const BodyKin<double>& ref = pc.m.ref_is_a ? A : B;
    const BodyKin<double>& inc = pc.m.ref_is_a ? B : A;
    const PlateShape& sr = pc.m.ref_is_a ? pc.sa : pc.sb;
    const PlateShape& si = pc.m.ref_is_a ? pc.sb : pc.sa;
    const double reach = sr.r + si.r;
    // New points of nearly parallel plates take the side of the incident centroid (robust
    // for stacks even when a point has sunk past the mid-plane); steep ones their own side.
    const Vec3 n_ref = ref.R_WB.col(2);
    const bool parallel = std::abs(n_ref.dot(inc.R_WB.col(2))) > std::cos(30 * kDegToRad);
    const int pair_side = n_ref.dot(inc.p_W - ref.p_W) >= 0 ? 1 : -1;
    bool any = false;
    for (int k = 0; k < pc.m.count; ++k) {
      const VertexGeometry<double> g = vertex_geometry(ref, sr, inc, si, pc.m.poly[k]);
      const ContactAnchor* an =
          find_anchor(state.contact, point_key(a, b, pc.m.ref_is_a, pc.m.poly[k].id()));
      const int side = an ? an->side : parallel ? pair_side : (g.height >= 0 ? 1 : -1);
      const double depth = reach - side * g.height;
      pc.side[k] = side;
      pc.anchor[k] = an;
      pc.active[k] = g.valid && depth > 0;
      any = any || pc.active[k];
    }
    if (any) visit(pc);
  }
}

/// Per-point values reported to probes and used to update the history.
struct PointReport {
  int vertex = 0;
  Vec3 x_W, n_W, v_t;
  double depth = 0, normal = 0, friction = 0, share = 0, penetration_rate = 0;
  Vec3 f_t = Vec3::Zero();
};

/// Forces of one pair for scalar T; adds them to the two wrenches, returns elastic energy.
template <class T>
T evaluate_pair(const ContactDef& def, const PairContact& pc, const BodyKin<T>& A,
                const BodyKin<T>& B, Wrench<T>& wa, Wrench<T>& wb,
                std::vector<PointReport>* report) {
  const BodyKin<T>& ref = pc.m.ref_is_a ? A : B;
  const BodyKin<T>& inc = pc.m.ref_is_a ? B : A;
  Wrench<T>& w_ref = pc.m.ref_is_a ? wa : wb;
  Wrench<T>& w_inc = pc.m.ref_is_a ? wb : wa;
  const PlateShape& sr = pc.m.ref_is_a ? pc.sa : pc.sb;
  const PlateShape& si = pc.m.ref_is_a ? pc.sb : pc.sa;
  std::array<VertexGeometry<T>, 8> g;
  for (int k = 0; k < pc.m.count; ++k) g[k] = vertex_geometry(ref, sr, inc, si, pc.m.poly[k]);
  std::array<T, 8> share;
  if (!vertex_shares(g.data(), pc.m.count, projected_area(ref, inc, si), 4 * si.hx * si.hy,
                     share.data()))
    return T(0);
  const Vec3T<T> n_ref = ref.R_WB.col(2);
  double energy = 0;
  for (int k = 0; k < pc.m.count; ++k) {
    if (!pc.active[k]) continue;
    const T side(static_cast<double>(pc.side[k]));
    const Vec3T<T> n = side * n_ref;  // from the reference towards the incident plate
    const T depth = T(sr.r + si.r) - side * g[k].height;
    const Vec3T<T> x = g[k].p_inc - n_ref * (g[k].height / T(2));
    const Vec3T<T> v_rel =
        (inc.v_W + inc.w_W.cross(x - inc.p_W)) - (ref.v_W + ref.w_W.cross(x - ref.p_W));
    const T rate = -n.dot(v_rel);
    const ContactAnchor* an = pc.anchor[k];
    const double v0 = an ? an->impact_speed : value_of(rate);
    const T fn = share[k] * normal_force(def, depth, rate, v0);
    energy += value_of(share[k]) * contact_energy(def, value_of(depth));
    const Vec3T<T> v_t = v_rel - n * n.dot(v_rel);
    Vec3T<T> f_t = Vec3T<T>::Zero();
    if (def.friction == FrictionModel::Continuous ||
        (def.friction == FrictionModel::Anchor && an == nullptr)) {
      f_t = continuous_friction(def, fn, v_t);
    } else if (def.friction == FrictionModel::Anchor) {
      using std::sqrt;
      const Vec3T<T> z = inc.point_W(an->r_inc_B) - ref.point_W(an->r_ref_B);
      const Vec3T<T> z_t = z - n * n.dot(z);
      f_t = -share[k] * (T(def.tangential_stiffness) * z_t + T(def.tangential_damping) * v_t);
      const double mu = an->sliding ? def.mu_dynamic : def.mu_static;
      const T limit = T(mu) * fn;
      const T f2 = f_t.squaredNorm();
      if (value_of(f2) > value_of(limit) * value_of(limit)) {
        f_t = value_of(f2) > 0 ? Vec3T<T>(f_t * (limit / sqrt(f2))) : Vec3T<T>::Zero();
      }
    }
    const Vec3T<T> f = fn * n + f_t;
    w_inc.add_force_at(f, x, inc.p_W);
    w_ref.add_force_at(-f, x, ref.p_W);
    if (report) {
      PointReport r;
      r.vertex = k;
      for (int i = 0; i < 3; ++i) {
        r.x_W[i] = value_of(x[i]);
        r.n_W[i] = value_of(n[i]);
        r.v_t[i] = value_of(v_t[i]);
        r.f_t[i] = value_of(f_t[i]);
      }
      r.depth = value_of(depth);
      r.normal = value_of(fn);
      r.friction = r.f_t.norm();
      r.share = value_of(share[k]);
      r.penetration_rate = value_of(rate);
      report->push_back(r);
    }
  }
  return T(energy);
}

BodyKin<double> kin_of(const State& s, int i) {
  return {s.p_W[i], s.R_WB[i], s.v_W[i], s.w_W[i]};
}

}  // namespace

void add_contact_forces(const Model& model, const State& state, Assembler& assembler) {
  if (!model.contact.enabled) return;
  validate_contact(model.contact, model.source);  // models built through the API
  const ContactDef& def = model.contact;
  detect(model, state, [&](const PairContact& pc) {
    assembler.pair(pc.a, pc.b, [&](const auto& A, const auto& B, auto& wa, auto& wb) {
      return evaluate_pair(def, pc, A, B, wa, wb, nullptr);
    });
  });
}

void commit_contact_history(const Model& model, State& state) {
  if (!model.contact.enabled) {
    state.contact.anchors.clear();
    return;
  }
  const ContactDef& def = model.contact;
  std::vector<ContactAnchor> next;
  std::vector<PointReport> rep;
  detect(model, state, [&](const PairContact& pc) {
    rep.clear();
    const BodyKin<double> A = kin_of(state, pc.a), B = kin_of(state, pc.b);
    Wrench<double> wa, wb;
    evaluate_pair(def, pc, A, B, wa, wb, &rep);
    const BodyKin<double>& ref = pc.m.ref_is_a ? A : B;
    const BodyKin<double>& inc = pc.m.ref_is_a ? B : A;
    for (const PointReport& r : rep) {
      const int k = r.vertex;
      ContactAnchor an;
      an.key = point_key(pc.a, pc.b, pc.m.ref_is_a, pc.m.poly[k].id());
      const ContactAnchor* old = pc.anchor[k];
      const double kt = r.share * def.tangential_stiffness;
      if (old) {
        an = *old;
        if (def.friction == FrictionModel::Anchor && kt > 0) {
          const Vec3 xi = inc.point_W(an.r_inc_B), xr = ref.point_W(an.r_ref_B);
          const Vec3 z = xi - xr;
          const Vec3 z_t = z - r.n_W * r.n_W.dot(z);
          const double mu = an.sliding ? def.mu_dynamic : def.mu_static;
          if (kt * z_t.norm() > mu * r.normal) {
            // Slipping: drag the anchor so that the spring carries the dynamic limit.
            an.sliding = true;
            const Vec3 z_new = z_t * (def.mu_dynamic * r.normal / (kt * z_t.norm()));
            an.r_inc_B = inc.R_WB.transpose() * (xr + z_new - inc.p_W);
          } else if (an.sliding && r.v_t.norm() < def.stiction_speed) {
            an.sliding = false;
          }
        }
      } else {
        an.side = pc.side[k];
        an.impact_speed = r.penetration_rate;
        an.sliding = false;
        // New anchor placed so that its spring starts with the friction force just applied.
        Vec3 offset = Vec3::Zero();
        if (def.friction == FrictionModel::Anchor && kt > 0) offset = -r.f_t / kt;
        an.r_ref_B = ref.R_WB.transpose() * (r.x_W - ref.p_W);
        an.r_inc_B = inc.R_WB.transpose() * (r.x_W + offset - inc.p_W);
      }
      next.push_back(an);
    }
  });
  std::sort(next.begin(), next.end(),
            [](const ContactAnchor& x, const ContactAnchor& y) { return x.key < y.key; });
  state.contact.anchors = std::move(next);
}

ContactSummary contact_summary(const Model& model, const State& state) {
  ContactSummary s;
  if (!model.contact.enabled) return s;
  std::vector<PointReport> rep;
  detect(model, state, [&](const PairContact& pc) {
    rep.clear();
    Wrench<double> wa, wb;
    evaluate_pair(model.contact, pc, kin_of(state, pc.a), kin_of(state, pc.b), wa, wb, &rep);
    for (const PointReport& r : rep) {
      if (!(r.share > 1e-12)) continue;  // edge-on-edge overlap of zero area
      ++s.active;
      s.total_normal_force += r.normal;
      s.total_friction_force += r.friction;
      s.max_penetration = std::max(s.max_penetration, r.depth);
      s.points_W.push_back(r.x_W);
    }
  });
  return s;
}

}  // namespace finseg
