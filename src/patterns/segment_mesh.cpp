#include "patterns/segment_mesh.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include "core/error.hpp"
#include "core/grading.hpp"
#include "model/segment_shape.hpp"

namespace finseg {
namespace {

using Key = std::pair<int, int>;

Key key(int a, int b) {
  return a < b ? Key(a, b) : Key(b, a);
}

// Pattern edge of each face side: sides[f][k] runs loop[k] -> loop[k + 1].
std::vector<std::vector<int>> face_side_edges(const CreasePattern& p) {
  std::map<Key, int> by_ends;
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    by_ends[key(p.edges[e].vertices[0], p.edges[e].vertices[1])] = static_cast<int>(e);
  }
  std::vector<std::vector<int>> sides(p.faces.size());
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const std::vector<int>& loop = p.faces[f];
    for (std::size_t k = 0; k < loop.size(); ++k) {
      sides[f].push_back(by_ends.at(key(loop[k], loop[(k + 1) % loop.size()])));
    }
  }
  return sides;
}

// A crease the sheet is folded along: cells are graded towards its vertices.
bool folded_crease(const PatternEdge& e) {
  switch (e.assignment) {
    case EdgeAssignment::Mountain:
    case EdgeAssignment::Valley:
      return true;
    case EdgeAssignment::Flat:
    case EdgeAssignment::Unassigned:
      return e.fold_angle != 0;
    default:
      return false;
  }
}

int root(std::vector<int>& parent, int e) {
  while (parent[e] != e) e = parent[e] = parent[parent[e]];
  return e;
}

// How each pattern edge is cut: cell count and the ends it is graded towards.
struct CutPlan {
  std::vector<int> n;
  std::vector<std::array<bool, 2>> toward;  // towards vertices[0], vertices[1]
  double refinement = 1;

  // Cell boundaries along edge e, from its vertices[0] (0) to vertices[1] (1).
  std::vector<double> fractions(int e) const {
    return graded_fractions(n[e], refinement, toward[e][0], toward[e][1]);
  }
};

// Fewest cells along an edge of length `len` whose largest cell is at most `size`.
int cells_for_size(double len, double size, double refinement, std::array<bool, 2> toward) {
  int m = std::max(1, static_cast<int>(std::ceil(len / size - 1e-9)));
  for (;; ++m) {
    const std::vector<double> f = graded_fractions(m, refinement, toward[0], toward[1]);
    double largest = 0;
    for (int k = 0; k < m; ++k) largest = std::max(largest, f[k + 1] - f[k]);
    if (len * largest <= size * (1 + 1e-9) || m > (1 << 20)) return m;
  }
}

CutPlan plan_cut(const CreasePattern& p, const Subdivision& s, const std::string& source,
                 const std::string& field, int max_cells) {
  const int ne = static_cast<int>(p.edges.size());
  std::vector<int> parent(ne);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<bool> gradable(ne, true);
  const auto join = [&](int a, int b) { parent[root(parent, a)] = root(parent, b); };
  for (const std::vector<int>& sides : face_side_edges(p)) {
    if (sides.size() == 4) {
      join(sides[0], sides[2]);
      join(sides[1], sides[3]);
      continue;
    }
    // A triangle's barycentric grid (and a fan's spokes) need uniform sides.
    for (int e : sides) join(sides[0], e), gradable[e] = false;
  }
  for (const auto& seam : p.seams) {  // matching points: the same count, uniform
    join(seam[0], seam[1]);
    gradable[seam[0]] = gradable[seam[1]] = false;
  }
  std::vector<bool> class_gradable(ne, true);
  for (int e = 0; e < ne; ++e) {
    if (!gradable[e]) class_gradable[root(parent, e)] = false;
  }
  std::vector<int> creases_at(p.vertices_flat_m.size(), 0);
  for (const PatternEdge& e : p.edges) {
    if (folded_crease(e)) ++creases_at[e.vertices[0]], ++creases_at[e.vertices[1]];
  }
  CutPlan plan;
  plan.refinement = s.crease_refinement;
  plan.toward.resize(ne);
  for (int e = 0; e < ne; ++e) {
    const PatternEdge& pe = p.edges[e];
    const int own = folded_crease(pe) ? 1 : 0;
    for (int k = 0; k < 2; ++k) {
      plan.toward[e][k] = s.crease_refinement != 1 && class_gradable[root(parent, e)] &&
                          creases_at[pe.vertices[k]] > own;
    }
  }
  std::vector<int> class_n(ne, s.segment_size > 0 ? 1 : std::max(s.n, 1));
  if (s.segment_size > 0) {
    for (int e = 0; e < ne; ++e) {
      const double len =
          (p.vertices_flat_m[p.edges[e].vertices[1]] - p.vertices_flat_m[p.edges[e].vertices[0]])
              .norm();
      const int m = cells_for_size(len, s.segment_size, s.crease_refinement, plan.toward[e]);
      if (m > max_cells) {
        throw InputError(source, field,
                         fmt::format("{:.6g} m needs {} cells along edge {} ({:.6g} m long); "
                                     "at most {} allowed",
                                     s.segment_size, m, e, len, max_cells));
      }
      int& n = class_n[root(parent, e)];
      n = std::max(n, m);
    }
  }
  plan.n.resize(ne);
  for (int e = 0; e < ne; ++e) plan.n[e] = class_n[root(parent, e)];
  return plan;
}

// Builds the mesh: vertices, the points along every edge (shared by the faces on both
// sides), and the cells of each face.
class Cutter {
 public:
  Cutter(const CreasePattern& p, const CutPlan& plan, bool triangles)
      : p_(p), triangles_(triangles) {
    mesh_.flat_m = p.vertices_flat_m;
    mesh_.folded_m = p.vertices_folded_m;
    for (std::size_t e = 0; e < p.edges.size(); ++e) {
      const auto [u, v] = p.edges[e].vertices;
      make_side(u, v, plan.fractions(static_cast<int>(e)), static_cast<int>(e));
    }
  }

  void cut_face(int f) {
    const std::vector<int>& loop = p_.faces[f];
    if (loop.size() == 3) return triangle(loop[0], loop[1], loop[2], f);
    if (loop.size() == 4) return quadrilateral(loop, f);
    // A fan from the centroid; the centroid's folded position by the same affine weights.
    std::vector<double> w(loop.size(), 0.0);
    double area = 0;
    for (std::size_t t = 1; t + 1 < loop.size(); ++t) {
      const Vec2 &a = flat(loop[0]), &b = flat(loop[t]), &c = flat(loop[t + 1]);
      const double at = 0.5 * cross2d(b - a, c - a);
      area += at;
      for (const std::size_t k : {std::size_t{0}, t, t + 1}) w[k] += at / 3;
    }
    std::vector<std::pair<int, double>> parts;
    for (std::size_t k = 0; k < loop.size(); ++k) parts.push_back({loop[k], w[k] / area});
    const int c = combine(parts);
    const int n = static_cast<int>(side(loop[0], loop[1]).size()) - 1;
    for (int v : loop) make_side(c, v, graded_fractions(n, 1, false, false));
    for (std::size_t k = 0; k < loop.size(); ++k) {
      triangle(c, loop[k], loop[(k + 1) % loop.size()], f);
    }
  }

  SegmentMesh finish() {
    std::map<Key, std::pair<int, int>> first;  // side -> (cell, its start vertex)
    for (std::size_t c = 0; c < mesh_.cells.size(); ++c) {
      const std::vector<int>& loop = mesh_.cells[c];
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const int a = loop[k], b = loop[(k + 1) % loop.size()];
        const auto [it, fresh] = first.try_emplace(key(a, b), static_cast<int>(c), a);
        if (fresh) continue;
        CellLink l;
        l.left = it->second.first;
        l.right = static_cast<int>(c);
        l.a = l.a_right = b;  // the first cell runs b -> a when this one runs a -> b
        l.b = l.b_right = a;
        const auto e = side_edge_.find(key(a, b));
        l.pattern_edge = e == side_edge_.end() ? -1 : e->second;
        if (l.pattern_edge >= 0 && p_.edges[l.pattern_edge].assignment == EdgeAssignment::Cut) {
          continue;
        }
        mesh_.links.push_back(l);
      }
    }
    for (std::size_t k = 0; k < p_.seams.size(); ++k) link_seam(static_cast<int>(k), first);
    return std::move(mesh_);
  }

 private:
  const Vec2& flat(int v) const { return mesh_.flat_m[v]; }

  // Links across seam k. The joined line runs as edge b's u -> v (b.u meets a.v): point i
  // of b is point n - i of a. The cell that runs a side in that direction is the link's
  // left (b's face when it lies left of b), so that the element's frame sits where a
  // crease's would on a sheet that went on past edge b (docs/stiffness.md, "Seams").
  void link_seam(int k, const std::map<Key, std::pair<int, int>>& first) {
    const int eb = p_.seams[k][1], ea = p_.seams[k][0];
    const auto points = [&](int e) {
      return side(p_.edges[e].vertices[0], p_.edges[e].vertices[1]);
    };
    const std::vector<int> pb = points(eb), pa = points(ea);
    const int n = static_cast<int>(pb.size()) - 1;  // the same along a (one edge class)
    for (int i = 0; i < n; ++i) {
      const auto [cb, start_b] = first.at(key(pb[i], pb[i + 1]));
      const int ca = first.at(key(pa[n - i], pa[n - i - 1])).first;
      CellLink l;
      l.seam = k;
      if (start_b == pb[i]) {  // b's cell runs the line forwards, a's backwards
        l.left = cb, l.a = pb[i], l.b = pb[i + 1], l.pattern_edge = eb;
        l.right = ca, l.a_right = pa[n - i], l.b_right = pa[n - i - 1];
      } else {  // both faces right of their edges (validate_pattern): a's cell forwards
        l.left = ca, l.a = pa[n - i], l.b = pa[n - i - 1], l.pattern_edge = ea;
        l.right = cb, l.a_right = pb[i], l.b_right = pb[i + 1];
      }
      mesh_.links.push_back(l);
    }
  }

  // A new vertex at the affine combination of existing ones (flat and folded alike).
  int combine(const std::vector<std::pair<int, double>>& parts) {
    Vec2 x = Vec2::Zero();
    Vec3 y = Vec3::Zero();
    for (const auto& [v, w] : parts) {
      x += w * mesh_.flat_m[v];
      if (!mesh_.folded_m.empty()) y += w * mesh_.folded_m[v];
    }
    mesh_.flat_m.push_back(x);
    if (!mesh_.folded_m.empty()) mesh_.folded_m.push_back(y);
    return static_cast<int>(mesh_.flat_m.size()) - 1;
  }

  // Makes the points along a -> b at `fractions` (0 and 1 included) unless it exists;
  // `edge`: the pattern edge it is.
  void make_side(int a, int b, const std::vector<double>& fractions, int edge = -1) {
    if (sides_.count(key(a, b))) return;
    std::vector<int> pts{a};
    for (std::size_t k = 1; k + 1 < fractions.size(); ++k) {
      pts.push_back(combine({{a, 1 - fractions[k]}, {b, fractions[k]}}));
    }
    pts.push_back(b);
    if (edge >= 0) {
      for (std::size_t k = 0; k + 1 < pts.size(); ++k) side_edge_[key(pts[k], pts[k + 1])] = edge;
    }
    sides_.emplace(key(a, b), Side{pts, fractions});
  }

  // Vertices along a -> b, ends included (made by make_side).
  std::vector<int> side(int a, int b) const {
    std::vector<int> pts = sides_.at(key(a, b)).points;
    if (pts.front() != a) std::reverse(pts.begin(), pts.end());
    return pts;
  }

  // Fractions of the length of a -> b at side(a, b)'s vertices.
  std::vector<double> side_fractions(int a, int b) const {
    const Side& s = sides_.at(key(a, b));
    if (s.points.front() == a) return s.fractions;
    std::vector<double> f;
    for (auto it = s.fractions.rbegin(); it != s.fractions.rend(); ++it) f.push_back(1 - *it);
    return f;
  }

  void add_cell(std::vector<int> loop, int face) {
    mesh_.cells.push_back(std::move(loop));
    mesh_.cell_face.push_back(face);
  }

  void triangle(int A, int B, int C, int face) {
    const std::vector<int> ab = side(A, B), ac = side(A, C), bc = side(B, C);
    const int n = static_cast<int>(ab.size()) - 1;  // all three sides (one edge class)
    std::vector<std::vector<int>> id(n + 1, std::vector<int>(n + 1, -1));
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i + j <= n; ++i) {
        if (j == 0) {
          id[i][j] = ab[i];
        } else if (i == 0) {
          id[i][j] = ac[j];
        } else if (i + j == n) {
          id[i][j] = bc[j];
        } else {
          const double s = static_cast<double>(i) / n, t = static_cast<double>(j) / n;
          id[i][j] = combine({{A, 1 - s - t}, {B, s}, {C, t}});
        }
      }
    }
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i + j < n; ++i) {
        add_cell({id[i][j], id[i + 1][j], id[i][j + 1]}, face);
        if (i + j + 1 < n) add_cell({id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]}, face);
      }
    }
  }

  // The bilinear map's grid: the parameter lines join the points of opposite sides (graded
  // sides may differ), so every interior vertex is where two of them cross.
  void quadrilateral(const std::vector<int>& q, int face) {
    const int A = q[0], B = q[1], C = q[2], D = q[3];
    const std::vector<int> ab = side(A, B), bc = side(B, C), dc = side(D, C), ad = side(A, D);
    const std::vector<double> fab = side_fractions(A, B), fdc = side_fractions(D, C),
                              fad = side_fractions(A, D), fbc = side_fractions(B, C);
    const int nu = static_cast<int>(ab.size()) - 1, nv = static_cast<int>(ad.size()) - 1;
    std::vector<std::vector<int>> id(nu + 1, std::vector<int>(nv + 1, -1));
    for (int j = 0; j <= nv; ++j) {
      for (int i = 0; i <= nu; ++i) {
        if (j == 0) {
          id[i][j] = ab[i];
        } else if (i == nu) {
          id[i][j] = bc[j];
        } else if (j == nv) {
          id[i][j] = dc[i];
        } else if (i == 0) {
          id[i][j] = ad[j];
        } else {
          // s = a + t (c - a) meets t = d + s (b - d).
          const double a = fab[i], c = fdc[i], d = fad[j], b = fbc[j];
          const double s = (a + d * (c - a)) / (1 - (b - d) * (c - a)), t = d + s * (b - d);
          id[i][j] =
              combine({{A, (1 - s) * (1 - t)}, {B, s * (1 - t)}, {C, s * t}, {D, (1 - s) * t}});
        }
      }
    }
    for (int j = 0; j < nv; ++j) {
      for (int i = 0; i < nu; ++i) {
        add_quadrilateral_cell({id[i][j], id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]}, face);
      }
    }
  }

  // The cell, or with triangles_ four triangles about the mean of its corners.
  void add_quadrilateral_cell(const std::array<int, 4>& q, int face) {
    if (!triangles_) return add_cell({q.begin(), q.end()}, face);
    const int c = combine({{q[0], 0.25}, {q[1], 0.25}, {q[2], 0.25}, {q[3], 0.25}});
    for (int k = 0; k < 4; ++k) add_cell({q[k], q[(k + 1) % 4], c}, face);
  }

  struct Side {
    std::vector<int> points;        // from the first vertex it was made from
    std::vector<double> fractions;  // of its length, at `points`
  };

  const CreasePattern& p_;
  bool triangles_ = false;
  SegmentMesh mesh_;
  std::map<Key, Side> sides_;
  std::map<Key, int> side_edge_;  // cell side on a pattern edge -> that edge
};

}  // namespace

std::vector<int> edge_cell_counts(const CreasePattern& p, const Subdivision& s,
                                  const std::string& source, const std::string& field,
                                  int max_cells) {
  return plan_cut(p, s, source, field, max_cells).n;
}

double planned_cell_count(const CreasePattern& p, const std::vector<int>& edge_counts,
                          bool triangles) {
  double cells = 0;
  const std::vector<std::vector<int>> sides = face_side_edges(p);
  for (const std::vector<int>& f : sides) {
    const double n0 = edge_counts[f[0]];
    cells += f.size() == 4   ? (triangles ? 4 : 1) * n0 * edge_counts[f[1]]
             : f.size() == 3 ? n0 * n0
                             : static_cast<double>(f.size()) * n0 * n0;
  }
  return cells;
}

SegmentMesh subdivide_pattern(const CreasePattern& p, const Subdivision& s) {
  Cutter cut(p, plan_cut(p, s, "<api>", "segment_size", 1 << 20), s.triangles);
  for (std::size_t f = 0; f < p.faces.size(); ++f) cut.cut_face(static_cast<int>(f));
  return cut.finish();
}

SegmentMesh subdivide_pattern(const CreasePattern& p, int n) {
  Subdivision s;
  s.n = std::max(n, 1);
  return subdivide_pattern(p, s);
}

}  // namespace finseg
