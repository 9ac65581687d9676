#include "patterns/segment_mesh.hpp"

#include <map>
#include <utility>

#include "model/segment_shape.hpp"

namespace finseg {
namespace {

using Key = std::pair<int, int>;

Key key(int a, int b) {
  return a < b ? Key(a, b) : Key(b, a);
}

// Builds the mesh: vertices, the points along every edge (shared by the faces on both
// sides), and the cells of each face.
class Cutter {
 public:
  Cutter(const CreasePattern& p, int n) : p_(p), n_(n) {
    mesh_.flat_m = p.vertices_flat_m;
    mesh_.folded_m = p.vertices_folded_m;
    for (std::size_t e = 0; e < p.edges.size(); ++e) {
      const auto [u, v] = p.edges[e].vertices;
      side(u, v, static_cast<int>(e));
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
    for (int i = 0; i < n_; ++i) {
      const auto [cb, start_b] = first.at(key(pb[i], pb[i + 1]));
      const int ca = first.at(key(pa[n_ - i], pa[n_ - i - 1])).first;
      CellLink l;
      l.seam = k;
      if (start_b == pb[i]) {  // b's cell runs the line forwards, a's backwards
        l.left = cb, l.a = pb[i], l.b = pb[i + 1], l.pattern_edge = eb;
        l.right = ca, l.a_right = pa[n_ - i], l.b_right = pa[n_ - i - 1];
      } else {  // both faces right of their edges (validate_pattern): a's cell forwards
        l.left = ca, l.a = pa[n_ - i], l.b = pa[n_ - i - 1], l.pattern_edge = ea;
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

  // Vertices along a -> b (n + 1, ends included), made on first use; `edge`: pattern edge.
  std::vector<int> side(int a, int b, int edge = -1) {
    auto it = sides_.find(key(a, b));
    if (it == sides_.end()) {
      std::vector<int> pts{a};
      for (int k = 1; k < n_; ++k) {
        const double s = static_cast<double>(k) / n_;
        pts.push_back(combine({{a, 1 - s}, {b, s}}));
      }
      pts.push_back(b);
      if (edge >= 0) {
        for (int k = 0; k < n_; ++k) side_edge_[key(pts[k], pts[k + 1])] = edge;
      }
      it = sides_.emplace(key(a, b), pts).first;
    }
    std::vector<int> pts = it->second;
    if (pts.front() != a) std::reverse(pts.begin(), pts.end());
    return pts;
  }

  void add_cell(std::vector<int> loop, int face) {
    mesh_.cells.push_back(std::move(loop));
    mesh_.cell_face.push_back(face);
  }

  void triangle(int A, int B, int C, int face) {
    const std::vector<int> ab = side(A, B), ac = side(A, C), bc = side(B, C);
    std::vector<std::vector<int>> id(n_ + 1, std::vector<int>(n_ + 1, -1));
    for (int j = 0; j <= n_; ++j) {
      for (int i = 0; i + j <= n_; ++i) {
        if (j == 0) {
          id[i][j] = ab[i];
        } else if (i == 0) {
          id[i][j] = ac[j];
        } else if (i + j == n_) {
          id[i][j] = bc[j];
        } else {
          const double s = static_cast<double>(i) / n_, t = static_cast<double>(j) / n_;
          id[i][j] = combine({{A, 1 - s - t}, {B, s}, {C, t}});
        }
      }
    }
    for (int j = 0; j < n_; ++j) {
      for (int i = 0; i + j < n_; ++i) {
        add_cell({id[i][j], id[i + 1][j], id[i][j + 1]}, face);
        if (i + j + 1 < n_) add_cell({id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]}, face);
      }
    }
  }

  void quadrilateral(const std::vector<int>& q, int face) {
    const int A = q[0], B = q[1], C = q[2], D = q[3];
    const std::vector<int> ab = side(A, B), bc = side(B, C), dc = side(D, C), ad = side(A, D);
    std::vector<std::vector<int>> id(n_ + 1, std::vector<int>(n_ + 1, -1));
    for (int j = 0; j <= n_; ++j) {
      for (int i = 0; i <= n_; ++i) {
        if (j == 0) {
          id[i][j] = ab[i];
        } else if (i == n_) {
          id[i][j] = bc[j];
        } else if (j == n_) {
          id[i][j] = dc[i];
        } else if (i == 0) {
          id[i][j] = ad[j];
        } else {
          const double s = static_cast<double>(i) / n_, t = static_cast<double>(j) / n_;
          id[i][j] =
              combine({{A, (1 - s) * (1 - t)}, {B, s * (1 - t)}, {C, s * t}, {D, (1 - s) * t}});
        }
      }
    }
    for (int j = 0; j < n_; ++j) {
      for (int i = 0; i < n_; ++i) {
        add_cell({id[i][j], id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]}, face);
      }
    }
  }

  const CreasePattern& p_;
  const int n_;
  SegmentMesh mesh_;
  std::map<Key, std::vector<int>> sides_;
  std::map<Key, int> side_edge_;  // cell side on a pattern edge -> that edge
};

}  // namespace

SegmentMesh subdivide_pattern(const CreasePattern& p, int n) {
  Cutter cut(p, std::max(n, 1));
  for (std::size_t f = 0; f < p.faces.size(); ++f) cut.cut_face(static_cast<int>(f));
  return cut.finish();
}

}  // namespace finseg
