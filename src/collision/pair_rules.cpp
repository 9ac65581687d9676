// Pair rules of the contact. Vertices of two segments are the same material point when a
// force element maps one onto the other in its rest (flat-sheet) configuration, where its
// frames E and F coincide; classes of such vertices (union-find over all outlines) tell which
// segments meet at a corner, also diagonally and across a seam whose sides lie far apart on
// the flat sheet.
#include "collision/pair_rules.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace finseg {

namespace {

int find_root(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

bool valid_pair(const ElementDef& e, int n) {
  return e.inner >= 0 && e.outer >= 0 && e.inner < n && e.outer < n && e.inner != e.outer;
}

}  // namespace

double crease_zone_width(const ContactDef& c, const BodyDef& a, const BodyDef& b) {
  return c.crease_zone ? *c.crease_zone : 2 * std::max(a.thickness, b.thickness);
}

PairRules::PairRules(const Model& m) : model_(m), def_(m.contact) {
  const int n = static_cast<int>(m.bodies.size());
  start_.assign(n + 1, 0);
  for (const ElementDef& e : m.elements) {
    if (!valid_pair(e, n)) continue;
    ++start_[e.inner + 1];
    ++start_[e.outer + 1];
  }
  for (int i = 0; i < n; ++i) start_[i + 1] += start_[i];
  nbr_.resize(start_[n]);
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (const ElementDef& e : m.elements) {
    if (!valid_pair(e, n)) continue;
    nbr_[fill[e.inner]++] = e.outer;
    nbr_[fill[e.outer]++] = e.inner;
  }

  // Vertex classes: every outline vertex a node; an element joins the vertices of its two
  // bodies that its rest configuration puts on the same point.
  vstart_.assign(n + 1, 0);
  for (int i = 0; i < n; ++i)
    vstart_[i + 1] = vstart_[i] + static_cast<int>(m.bodies[i].outline_B.size());
  std::vector<int> parent(vstart_[n]);
  std::iota(parent.begin(), parent.end(), 0);
  for (const ElementDef& e : m.elements) {
    if (!valid_pair(e, n)) continue;
    const BodyDef& I = m.bodies[e.inner];
    const BodyDef& J = m.bodies[e.outer];
    if (I.outline_B.empty() || J.outline_B.empty()) continue;
    const double tol = 1e-3 * std::sqrt(std::min(segment_area(I), segment_area(J)));
    // The outer body's frame in the inner one's at rest (E = F): R_IJ and its centroid p_J_I.
    const Mat3 R_IJ = e.R_inner_E * e.R_outer_F.transpose();
    const Vec3 p_J_I = e.c_inner_B - e.R_inner_E * e.z0_F - R_IJ * e.c_outer_B;
    // Only an element between side-by-side pieces of sheet names shared corners; one whose
    // rest puts the outer segment's centroid onto the inner one's polygon (zero lever arms
    // in a hand-built model) says nothing about them.
    if (polygon_contains(I.outline_B, Vec2(p_J_I.x(), p_J_I.y()), tol)) continue;
    for (std::size_t v = 0; v < J.outline_B.size(); ++v) {
      const Vec3 q = p_J_I + R_IJ * Vec3(J.outline_B[v].x(), J.outline_B[v].y(), 0);
      for (std::size_t u = 0; u < I.outline_B.size(); ++u) {
        if ((q - Vec3(I.outline_B[u].x(), I.outline_B[u].y(), 0)).norm() > tol) continue;
        const int a = find_root(parent, vstart_[e.inner] + static_cast<int>(u));
        const int b = find_root(parent, vstart_[e.outer] + static_cast<int>(v));
        parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  vclass_.resize(parent.size());
  for (int i = 0; i < n; ++i) {
    for (int k = vstart_[i]; k < vstart_[i + 1]; ++k) vclass_[k] = find_root(parent, k);
    std::sort(vclass_.begin() + vstart_[i], vclass_.begin() + vstart_[i + 1]);
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

bool PairRules::shares_vertex(int a, int b) const {
  int i = vstart_[a], j = vstart_[b];
  while (i < vstart_[a + 1] && j < vstart_[b + 1]) {
    if (vclass_[i] == vclass_[j]) return true;
    vclass_[i] < vclass_[j] ? ++i : ++j;
  }
  return false;
}

bool PairRules::may_touch(int a, int b) const {
  const BodyDef& A = model_.bodies[a];
  const BodyDef& B = model_.bodies[b];
  if (A.fixed && B.fixed) return false;
  if (!allowed_.empty()) {
    if (A.panel < 0 || B.panel < 0) return false;
    if (!allowed_[static_cast<std::size_t>(A.panel) * panels_ + B.panel]) return false;
  }
  for (int k = start_[a]; k < start_[a + 1]; ++k)
    if (nbr_[k] == b) return false;
  // A shared edge or corner is held together by the joints, so the plates always overlap
  // there by their thickness: never a contact.
  if (shares_vertex(a, b)) return false;
  // On the flat sheet: touching (a shared corner the elements do not name, e.g. next to a
  // cut) or within the crease zone, the material a real fold bends through.
  if (A.centroid_M && B.centroid_M) {
    const double touch = 1e-3 * std::sqrt(std::min(segment_area(A), segment_area(B)));
    const double reach = std::max(touch, crease_zone_width(def_, A, B));
    // Most pairs (stacked layers) lie far apart on the sheet: their circumcircles tell.
    const double apart = (*A.centroid_M - *B.centroid_M).norm() - outline_radius(A.outline_B) -
                         outline_radius(B.outline_B);
    if (!(apart > reach)) {
      const double d = polygon_distance(material_outline(A), material_outline(B));
      if (d <= touch || d < reach) return false;
    }
  }
  if (A.panel == B.panel && def_.panel_exclusion > 0 && within_hops(a, b, A.panel)) return false;
  return true;
}

// Breadth-first search from a inside its panel, at most panel_exclusion elements deep.
bool PairRules::within_hops(int a, int b, int panel) const {
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

std::vector<std::pair<int, int>> contact_candidates(const Model& model, const State& state,
                                                    const PairRules& rules, BroadPhase& broad,
                                                    std::vector<Aabb>& boxes) {
  const int n = static_cast<int>(model.bodies.size());
  boxes.resize(n);
  for (int i = 0; i < n; ++i)
    boxes[i] = plate_aabb(state.p_W[i], state.R_WB[i], model.bodies[i], model.contact.margin);
  std::vector<std::pair<int, int>> pairs = broad.find_pairs(boxes);
  pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                             [&](const auto& p) { return !rules.may_touch(p.first, p.second); }),
              pairs.end());
  return pairs;
}

}  // namespace finseg
