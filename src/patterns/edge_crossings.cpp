// find_edge_crossing (pattern_checks.hpp): a uniform grid of about one cell per edge; each
// edge is entered in the cells its touch-widened segment passes through, row by row, so
// the work is linear in the cells crossed, and only edges sharing a cell are compared.
#include <algorithm>
#include <cmath>
#include <utility>

#include "model/segment_shape.hpp"
#include "patterns/pattern_checks.hpp"

namespace finseg {
namespace {

bool edges_meet(const std::vector<Vec2>& xy, const PatternEdge& e1, const PatternEdge& e2,
                double touch) {
  const int a = e1.vertices[0], b = e1.vertices[1], c = e2.vertices[0], d = e2.vertices[1];
  const bool ac = a == c, ad = a == d, bc = b == c, bd = b == d;
  if ((ac || ad) && (bc || bd)) return true;  // the same pair of vertices twice
  if (ac || ad || bc || bd) {
    // One shared vertex: they meet elsewhere only by overlapping along a line.
    const int v = ac || ad ? a : b, p = v == a ? b : a, q = (ac || bc) ? d : c;
    return point_segment_distance(xy[p], xy[v], xy[q]) <= touch ||
           point_segment_distance(xy[q], xy[v], xy[p]) <= touch;
  }
  const Vec2 &A = xy[a], &B = xy[b], &C = xy[c], &D = xy[d];
  if (segments_cross(A, B, C, D)) return true;
  return std::min({point_segment_distance(A, C, D), point_segment_distance(B, C, D),
                   point_segment_distance(C, A, B), point_segment_distance(D, A, B)}) <= touch;
}

struct Grid {
  Vec2 origin;
  double h = 1;
  long nx = 1, ny = 1;
};

Grid make_grid(const std::vector<Vec2>& xy, std::size_t n_edges, double touch) {
  Eigen::AlignedBox2d box;
  for (const Vec2& v : xy) box.extend(v);
  Grid g;
  g.origin = box.min() - Vec2::Constant(touch);
  const Vec2 size = box.sizes() + Vec2::Constant(2 * touch);
  const double n = static_cast<double>(std::max<std::size_t>(n_edges, 1));
  g.h = std::sqrt(size.x() * size.y() / n);
  g.h = std::max({g.h, size.maxCoeff() / n, 1e-300});
  g.nx = static_cast<long>(size.x() / g.h) + 1;
  g.ny = static_cast<long>(size.y() / g.h) + 1;
  return g;
}

long clamp_cell(double x, long n) {
  return std::clamp(static_cast<long>(std::floor(x)), 0L, n - 1);
}

// Cells (row-major ids) that segment a-b, widened by `touch`, passes through.
void cells_of(const Grid& g, const Vec2& a, const Vec2& b, double touch, int edge,
              std::vector<std::pair<long, int>>& out) {
  const double y_lo = std::min(a.y(), b.y()) - touch, y_hi = std::max(a.y(), b.y()) + touch;
  const long r0 = clamp_cell((y_lo - g.origin.y()) / g.h, g.ny);
  const long r1 = clamp_cell((y_hi - g.origin.y()) / g.h, g.ny);
  for (long r = r0; r <= r1; ++r) {
    const double band_lo = g.origin.y() + r * g.h - touch;
    const double band_hi = g.origin.y() + (r + 1) * g.h + touch;
    double t0 = 0, t1 = 1;  // part of the segment inside the band
    const double dy = b.y() - a.y();
    if (dy != 0) {
      const double ta = (band_lo - a.y()) / dy, tb = (band_hi - a.y()) / dy;
      t0 = std::max(0.0, std::min(ta, tb));
      t1 = std::min(1.0, std::max(ta, tb));
      if (t0 > t1) continue;
    }
    const double xa = a.x() + t0 * (b.x() - a.x()), xb = a.x() + t1 * (b.x() - a.x());
    const long c0 = clamp_cell((std::min(xa, xb) - touch - g.origin.x()) / g.h, g.nx);
    const long c1 = clamp_cell((std::max(xa, xb) + touch - g.origin.x()) / g.h, g.nx);
    for (long c = c0; c <= c1; ++c) out.emplace_back(r * g.nx + c, edge);
  }
}

}  // namespace

std::optional<std::array<int, 2>> find_edge_crossing(const std::vector<Vec2>& xy,
                                                     const std::vector<PatternEdge>& edges,
                                                     double touch) {
  if (edges.size() < 2) return std::nullopt;
  const Grid g = make_grid(xy, edges.size(), touch);
  std::vector<std::pair<long, int>> entries;
  entries.reserve(edges.size() * 4);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    cells_of(g, xy[edges[e].vertices[0]], xy[edges[e].vertices[1]], touch, static_cast<int>(e),
             entries);
  }
  std::sort(entries.begin(), entries.end());
  std::optional<std::array<int, 2>> best;
  for (std::size_t begin = 0; begin < entries.size();) {
    std::size_t end = begin;
    while (end < entries.size() && entries[end].first == entries[begin].first) ++end;
    for (std::size_t i = begin; i < end; ++i) {
      for (std::size_t j = i + 1; j < end; ++j) {
        const std::array<int, 2> pair{entries[i].second, entries[j].second};  // sorted
        if (best && pair >= *best) break;
        if (edges_meet(xy, edges[pair[0]], edges[pair[1]], touch)) best = pair;
      }
    }
    begin = end;
  }
  return best;
}

}  // namespace finseg
