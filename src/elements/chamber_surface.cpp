#include "elements/chamber_surface.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <numeric>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "elements/assembler.hpp"
#include "elements/chamber_volume.hpp"

namespace finseg {
namespace {

Vec3 vertex_W(const State& s, const SurfaceVertex& v) {
  return v.body < 0 ? v.x : Vec3(s.p_W[v.body] + s.R_WB[v.body] * v.x);
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Node of each point: points closer than tol are one node (sweep along x, n log n for
// spread-out points).
std::vector<int> cluster(const std::vector<Vec3>& x, double tol) {
  std::vector<int> order(x.size()), parent(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::iota(parent.begin(), parent.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return x[a].x() < x[b].x(); });
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      if (x[order[j]].x() - x[order[i]].x() > tol) break;
      if ((x[order[i]] - x[order[j]]).norm() <= tol) {
        parent[find_root(parent, order[i])] = find_root(parent, order[j]);
      }
    }
  }
  std::vector<int> node(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) node[i] = find_root(parent, static_cast<int>(i));
  return node;
}

// Face corners lying strictly inside a plate's edges become fixed vertices of the plate (the
// plate stays the same polygon), so that plate and faces meet edge to edge.
void split_plate_edges(std::vector<SurfaceVertex>& v, std::vector<std::vector<int>>& loops,
                       std::size_t first_plate, std::size_t face_corners, double tol) {
  for (std::size_t l = first_plate; l < loops.size(); ++l) {
    std::vector<int> out;
    const std::vector<int> loop = loops[l];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Vec3 a = v[loop[k]].x, b = v[loop[(k + 1) % loop.size()]].x;
      out.push_back(loop[k]);
      std::vector<std::pair<double, Vec3>> inside;
      for (std::size_t c = 0; c < face_corners; ++c) {
        const Vec3& x = v[c].x;  // initial world position (set by the caller)
        const double t = (x - a).dot(b - a) / (b - a).squaredNorm();
        if (t * (b - a).norm() <= tol || (1 - t) * (b - a).norm() <= tol) continue;
        if ((a + t * (b - a) - x).norm() > tol) continue;
        if (std::none_of(inside.begin(), inside.end(),
                         [&](const auto& q) { return (q.second - x).norm() <= tol; })) {
          inside.push_back({t, x});
        }
      }
      std::sort(inside.begin(), inside.end(),
                [](const auto& p, const auto& q) { return p.first < q.first; });
      for (const auto& q : inside) {
        out.push_back(static_cast<int>(v.size()));
        v.push_back({-1, q.second});
      }
    }
    loops[l] = out;
  }
}

struct HalfEdge {
  int loop, from, to;  ///< vertex indices
};

// The open boundaries of the face loops: chains of the edges no other loop's edge meets
// (by node), each as the `from` vertices of its edges in order. Throws where two open edges
// leave one node (a boundary touching itself). Only the first `face_loops` loops (the faces)
// may be open; every loop may meet them.
std::vector<std::vector<int>> open_boundaries(const std::vector<std::vector<int>>& loops,
                                              std::size_t face_loops, const std::vector<int>& node,
                                              const std::string& source, const std::string& field) {
  std::map<std::pair<int, int>, int> count;
  for (const auto& loop : loops) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      ++count[{node[loop[k]], node[loop[(k + 1) % loop.size()]]}];
    }
  }
  std::map<int, std::pair<int, int>> open_from;  // node -> (from vertex, next node)
  for (std::size_t l = 0; l < face_loops; ++l) {
    const std::vector<int>& loop = loops[l];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int a = loop[k], b = loop[(k + 1) % loop.size()];
      if (count.count({node[b], node[a]})) continue;
      if (!open_from.emplace(node[a], std::make_pair(a, node[b])).second) {
        throw InputError(source, field,
                         "cap_open_ends: the faces' open boundary touches itself at a corner; "
                         "each open end must be a simple loop of edges");
      }
    }
  }
  std::vector<std::vector<int>> out;
  std::map<int, bool> used;
  for (const auto& [start, first] : open_from) {
    if (used[start]) continue;
    std::vector<int> chain;
    for (int n = start; !used[n];) {
      used[n] = true;
      const auto it = open_from.find(n);
      if (it == open_from.end()) {
        throw InputError(source, field, "cap_open_ends: an open boundary does not close");
      }
      chain.push_back(it->second.first);
      n = it->second.second;
    }
    out.push_back(chain);
  }
  return out;
}

}  // namespace

void build_chamber_surface(const Model& model, ChamberDef& def, double tol,
                           const std::string& field) {
  const State state = initial_state(model);
  std::vector<SurfaceVertex> v;
  std::vector<std::vector<int>> loops;
  std::vector<Vec3> corners_B;
  for (const ChamberFace& f : def.faces) {
    std::vector<int> loop;
    for (const Vec3& c_B : face_corners_B(model, f)) {
      loop.push_back(static_cast<int>(v.size()));
      // While building, x holds the initial world position; corners_B the body-frame point.
      v.push_back({f.body, state.p_W[f.body] + state.R_WB[f.body] * c_B});
      corners_B.push_back(c_B);
    }
    loops.push_back(loop);
  }
  const std::size_t face_corners = v.size();
  for (const auto& plate : def.end_plates) {
    std::vector<int> loop;
    for (const Vec3& x : plate) {
      loop.push_back(static_cast<int>(v.size()));
      v.push_back({-1, x});
    }
    loops.push_back(loop);
  }
  split_plate_edges(v, loops, def.faces.size(), face_corners, tol);
  std::vector<Vec3> x0(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) x0[i] = v[i].x;
  std::vector<int> node = cluster(x0, tol);
  // Caps: each open boundary run backwards, by copies of its corners (moving with them).
  std::vector<std::pair<int, Vec3>> cap_corners_B;  // vertex, its point in the body frame
  if (def.cap_open_ends) {
    for (const std::vector<int>& chain :
         open_boundaries(loops, def.faces.size(), node, model.source, field + ".cap_open_ends")) {
      std::vector<int> cap;
      for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        cap.push_back(static_cast<int>(v.size()));
        cap_corners_B.push_back({cap.back(), corners_B[*it]});
        v.push_back(v[*it]);
        x0.push_back(x0[*it]);
        node.push_back(node[*it]);  // a copy of the corner: its node, no new clustering
      }
      loops.push_back(cap);
    }
  }
  // Each edge u -> v must meet exactly one edge v' -> u' of another loop.
  std::vector<HalfEdge> edges;
  std::map<std::pair<int, int>, std::vector<int>> by_nodes;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    for (std::size_t k = 0; k < loops[l].size(); ++k) {
      const int a = loops[l][k], b = loops[l][(k + 1) % loops[l].size()];
      by_nodes[{node[a], node[b]}].push_back(static_cast<int>(edges.size()));
      edges.push_back({static_cast<int>(l), a, b});
    }
  }
  std::vector<std::vector<int>> bridges;
  std::vector<int> patch_next(v.size(), -1);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const HalfEdge& h = edges[e];
    const auto it = by_nodes.find({node[h.to], node[h.from]});
    if (it == by_nodes.end() || it->second.size() != 1 ||
        by_nodes[{node[h.from], node[h.to]}].size() != 1) {
      const bool plate = h.loop >= static_cast<int>(def.faces.size());
      const bool cap = h.loop >= static_cast<int>(def.faces.size() + def.end_plates.size());
      throw InputError(
          model.source,
          cap     ? field + ".cap_open_ends"
          : plate ? fmt::format("{}.end_plates[{}]", field, h.loop - def.faces.size())
                  : fmt::format("{}.faces[{}]", field, h.loop),
          fmt::format("its edge from ({:.6g}, {:.6g}, {:.6g}) to ({:.6g}, {:.6g}, {:.6g}) m does "
                      "not meet exactly one edge of another face end to end (a corner inside "
                      "another face's edge, or more than two faces on one edge): a chamber's "
                      "faces must meet corner to corner",
                      x0[h.from].x(), x0[h.from].y(), x0[h.from].z(), x0[h.to].x(), x0[h.to].y(),
                      x0[h.to].z()));
    }
    const int t = it->second.front();
    if (t < static_cast<int>(e)) continue;  // each pair once
    // Edge a -> b and its twin b' -> a': the strip between them runs b, a, a', b'.
    const int a = h.from, b = h.to, b2 = edges[t].from, a2 = edges[t].to;
    bridges.push_back({b, a, a2, b2});
    patch_next[a2] = a;  // the corner patches run the strips' short edges backwards
    patch_next[b] = b2;
  }
  std::vector<bool> seen(v.size(), false);
  for (std::size_t s = 0; s < v.size(); ++s) {
    if (patch_next[s] < 0 || seen[s]) continue;
    std::vector<int> patch;
    for (int c = static_cast<int>(s); !seen[c] && c >= 0; c = patch_next[c]) {
      seen[c] = true;
      patch.push_back(c);
    }
    if (patch.size() >= 3) bridges.push_back(patch);
  }
  for (std::size_t i = 0; i < face_corners; ++i) v[i].x = corners_B[i];
  for (const auto& [i, c_B] : cap_corners_B) v[i].x = c_B;
  def.vertices = v;
  def.loops = loops;
  def.loops.insert(def.loops.end(), bridges.begin(), bridges.end());
}

namespace {

// d(x of vertex v)/d(pose of its body): [I, -[r]x] for the lever r = x - p_W (world-frame
// rotation increments); zero for a fixed point.
Eigen::Matrix<double, 3, 6> vertex_motion(const Vec3& r) {
  Eigen::Matrix<double, 3, 6> J;
  J.leftCols<3>() = Mat3::Identity();
  J.rightCols<3>() = -hat<double>(r);
  return J;
}

// p d2V/dq2 of the fanned loops. The Hessian of a triangle's volume x_a . (x_b x x_c) / 6 in
// its vertices has the blocks d g_a / d x_b = -[x_c]x / 6, d g_a / d x_c = [x_b]x / 6 (and
// cyclically); chained to the bodies' poses, the force rows of vertex a take
// H_ab J_b and its couple rows [r_a]x H_ab J_b, and turning a body turns its levers:
// d(r x g)/dphi = [g]x [r]x on its own rotation block.
void add_surface_pressure_jacobian(const State& state, const ChamberDef& def, double p,
                                   const std::vector<Vec3>& g, Assembler& as) {
  const std::size_t n = def.vertices.size();
  std::vector<Vec3> x(n), r(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = vertex_W(state, def.vertices[i]);
    const int b = def.vertices[i].body;
    r[i] = b < 0 ? Vec3::Zero() : Vec3(state.R_WB[b] * def.vertices[i].x);
  }
  // Rows of vertex a's wrench per unit force on it: [I; [r_a]x].
  const auto wrench_rows = [&](int a) {
    Eigen::Matrix<double, 6, 3> W;
    W.topRows<3>() = Mat3::Identity();
    W.bottomRows<3>() = hat<double>(r[a]);
    return W;
  };
  const auto add_pair = [&](int a, int b, const Mat3& H) {
    const int ba = def.vertices[a].body, bb = def.vertices[b].body;
    if (ba < 0 || bb < 0) return;
    const Mat6 block = wrench_rows(a) * (p * H) * vertex_motion(r[b]);
    as.add_pose_block(ba, bb, block);
  };
  for (const auto& loop : def.loops) {
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
      const int t[3] = {loop[0], loop[k], loop[k + 1]};
      for (int m = 0; m < 3; ++m) {
        const int a = t[m], b = t[(m + 1) % 3], c = t[(m + 2) % 3];
        add_pair(a, b, -hat<double>(x[c]) / 6);
        add_pair(a, c, hat<double>(x[b]) / 6);
      }
    }
  }
  for (std::size_t a = 0; a < n; ++a) {
    const int b = def.vertices[a].body;
    if (b < 0) continue;
    Mat6 block = Mat6::Zero();
    block.bottomRightCorner<3, 3>() = hat<double>(Vec3(p * g[a])) * hat<double>(r[a]);
    as.add_pose_block(b, b, block);
  }
}

}  // namespace

double surface_volume(const State& state, const ChamberDef& def, std::vector<Vec3>* gradient) {
  std::vector<Vec3> x(def.vertices.size());
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = vertex_W(state, def.vertices[i]);
  if (gradient) gradient->assign(x.size(), Vec3::Zero());
  double vol = 0;
  for (const auto& loop : def.loops) {
    const Vec3& a = x[loop[0]];
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
      const Vec3& b = x[loop[k]];
      const Vec3& c = x[loop[k + 1]];
      vol += a.dot(b.cross(c)) / 6;
      if (!gradient) continue;
      (*gradient)[loop[0]] += b.cross(c) / 6;
      (*gradient)[loop[k]] += c.cross(a) / 6;
      (*gradient)[loop[k + 1]] += a.cross(b) / 6;
    }
  }
  return vol;
}

void add_surface_pressure(const State& state, const ChamberDef& def, double p, Assembler& as) {
  std::vector<Vec3> g;
  surface_volume(state, def, &g);
  for (std::size_t i = 0; i < def.vertices.size(); ++i) {
    const SurfaceVertex& v = def.vertices[i];
    if (v.body < 0) continue;
    Wrench<double> w;
    w.f_W = p * g[i];
    w.tau_W = (state.R_WB[v.body] * v.x).cross(w.f_W);
    as.add(v.body, w);
  }
  if (as.want_jacobian() && p != 0) add_surface_pressure_jacobian(state, def, p, g, as);
}

}  // namespace finseg
