#include "patterns/pattern_checks.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace finseg {
namespace {

std::string at(const char* field, std::size_t i) {
  return fmt::format("{}[{}]", field, i);
}

void check_indices(const CreasePattern& p, const std::string& src) {
  const int nv = static_cast<int>(p.vertices_flat_m.size());
  if (!p.vertices_folded_m.empty() && p.vertices_folded_m.size() != p.vertices_flat_m.size()) {
    throw InputError(src, "vertices_coords",
                     fmt::format("folded frame has {} vertices, the crease pattern {}",
                                 p.vertices_folded_m.size(), nv));
  }
  for (const PatternShape& shape : p.shapes) {
    if (shape.vertices_m.size() != p.vertices_flat_m.size()) {
      throw InputError(src, "vertices_coords",
                       fmt::format("folded frame '{}' has {} vertices, the crease pattern {}",
                                   shape.title, shape.vertices_m.size(), nv));
    }
  }
  if (p.faces.empty()) throw InputError(src, "faces_vertices", "no faces; at least one needed");
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const std::vector<int>& loop = p.faces[f];
    if (loop.size() < 3) {
      throw InputError(src, at("faces_vertices", f),
                       fmt::format("{} vertices; a face needs at least 3", loop.size()));
    }
    for (std::size_t i = 0; i < loop.size(); ++i) {
      if (loop[i] < 0 || loop[i] >= nv) {
        throw InputError(src, at("faces_vertices", f),
                         fmt::format("vertex {} out of range 0..{}", loop[i], nv - 1));
      }
      for (std::size_t j = 0; j < i; ++j) {
        if (loop[j] == loop[i]) {
          throw InputError(src, at("faces_vertices", f),
                           fmt::format("vertex {} appears twice", loop[i]));
        }
      }
    }
  }
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    const auto& v = p.edges[e].vertices;
    for (int k : v) {
      if (k < 0 || k >= nv) {
        throw InputError(src, at("edges_vertices", e),
                         fmt::format("vertex {} out of range 0..{}", k, nv - 1));
      }
    }
    if (v[0] == v[1]) {
      throw InputError(src, at("edges_vertices", e), fmt::format("both ends are vertex {}", v[0]));
    }
  }
}

void check_assignment(const PatternEdge& e, std::size_t i, const std::string& src) {
  const int n = e.face_count();
  const char letter = static_cast<char>(e.assignment);
  if (n == 0) {
    throw InputError(src, at("edges_vertices", i), "not a side of any face (dangling edge)");
  }
  if (is_crease(e.assignment) && n == 1) {
    throw InputError(src, at("edges_assignment", i),
                     fmt::format("'{}' (a crease) on the sheet's boundary: only one face", letter));
  }
  if (e.assignment == EdgeAssignment::Boundary && n == 2) {
    throw InputError(src, at("edges_assignment", i),
                     "'B' between two faces; use a crease letter, J, or C for a slit");
  }
  if (e.assignment == EdgeAssignment::Join && n == 1) {
    throw InputError(src, at("edges_assignment", i), "'J' (join) needs a face on each side");
  }
}

void check_fold_angle(const PatternEdge& e, std::size_t i, const std::string& src) {
  const double a = e.fold_angle, deg = a / kDegToRad;
  const std::string field = at("edges_foldAngle", i);
  if (!(std::abs(a) <= kPi * (1 + 1e-12))) {
    throw InputError(src, field, fmt::format("{} deg; allowed range [-180, 180]", deg));
  }
  switch (e.assignment) {
    case EdgeAssignment::Mountain:
      if (a > 0) throw InputError(src, field, fmt::format("{} deg on 'M'; must be <= 0", deg));
      break;
    case EdgeAssignment::Valley:
      if (a < 0) throw InputError(src, field, fmt::format("{} deg on 'V'; must be >= 0", deg));
      break;
    case EdgeAssignment::Unassigned:
      break;
    default:
      if (a != 0) {
        throw InputError(src, field,
                         fmt::format("{} deg on '{}'; must be 0 (only M, V, U fold)", deg,
                                     static_cast<char>(e.assignment)));
      }
  }
}

double diameter(const std::vector<Vec2>& xy, const std::vector<int>& loop) {
  double d = 0;
  for (int a : loop) {
    for (int b : loop) d = std::max(d, (xy[a] - xy[b]).norm());
  }
  return d;
}

void check_face_shape(const CreasePattern& p, std::size_t f, const PatternTolerances& tol,
                      const std::string& src) {
  const std::vector<Vec2>& xy = p.vertices_flat_m;
  const std::vector<int>& loop = p.faces[f];
  const std::size_t n = loop.size();
  const double d = diameter(xy, loop);
  double area2 = 0, turning = 0;
  for (std::size_t i = 0; i < n; ++i) area2 += cross2d(xy[loop[i]], xy[loop[(i + 1) % n]]);
  const std::string field = at("faces_vertices", f);
  if (std::abs(area2) <= 2 * tol.area * d * d) {
    throw InputError(src, field, fmt::format("zero area (diameter {:.6g} m)", d));
  }
  if (area2 < 0) throw InputError(src, field, "clockwise; faces must be counter-clockwise");
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = xy[loop[(i + 1) % n]] - xy[loop[i]];
    const Vec2 b = xy[loop[(i + 2) % n]] - xy[loop[(i + 1) % n]];
    const double s = cross2d(a, b), straight = tol.convexity * a.norm() * b.norm();
    if (s < -straight || (s <= straight && a.dot(b) < 0)) {  // reflex, or turning back
      throw InputError(src, field,
                       fmt::format("not convex at vertex {} (the segments need convex faces)",
                                   loop[(i + 1) % n]));
    }
    turning += std::atan2(s, a.dot(b));
  }
  if (turning > 2 * kPi + 1e-6) {
    throw InputError(src, field, "winds around more than once (self-intersecting loop)");
  }
}

void check_planar(const CreasePattern& p, std::size_t f, const PatternTolerances& tol,
                  const std::string& src) {
  const std::vector<int>& loop = p.faces[f];
  if (loop.size() == 3) return;
  Vec3 c = Vec3::Zero();
  for (int v : loop) c += p.vertices_folded_m[v];
  c /= static_cast<double>(loop.size());
  Mat3 cov = Mat3::Zero();
  double d = 0;
  for (int v : loop) {
    const Vec3 r = p.vertices_folded_m[v] - c;
    cov += r * r.transpose();
    for (int w : loop) d = std::max(d, (p.vertices_folded_m[v] - p.vertices_folded_m[w]).norm());
  }
  const Vec3 n = Eigen::SelfAdjointEigenSolver<Mat3>(cov).eigenvectors().col(0);
  for (int v : loop) {
    const double off = std::abs(n.dot(p.vertices_folded_m[v] - c));
    if (off > tol.planarity * d) {
      throw InputError(src, at("faces_vertices", f),
                       fmt::format("not planar when folded: vertex {} is {:.3g} m off the "
                                   "face's plane (limit {:.3g} m)",
                                   v, off, tol.planarity * d));
    }
  }
}

// Unit normal of folded face f (Newell's method: robust for any planar polygon).
Vec3 folded_normal(const CreasePattern& p, int f) {
  Vec3 n = Vec3::Zero();
  const std::vector<int>& loop = p.faces[f];
  for (std::size_t i = 0; i < loop.size(); ++i) {
    n += p.vertices_folded_m[loop[i]].cross(p.vertices_folded_m[loop[(i + 1) % loop.size()]]);
  }
  return n.normalized();
}

// Signed fold angle (valley positive) from the left face's normal to the right one's about
// the folded line u -> v.
double fold_angle_between(const CreasePattern& p, const Vec3& nl, const Vec3& nr,
                          const std::array<int, 2>& uv) {
  const Vec3 d = (p.vertices_folded_m[uv[1]] - p.vertices_folded_m[uv[0]]).normalized();
  return std::atan2(nr.cross(nl).dot(d), nl.dot(nr));
}

// Seams (docs/fold.md, "finseg:seams"): two distinct boundary edges, each in one seam, of
// equal flat length, their faces on the same side of u -> v (then a's face runs the joined
// line opposite to b's: one orientation), and when folded a.u at b.v, a.v at b.u.
void check_seams(const CreasePattern& p, double size, const PatternTolerances& tol,
                 const std::string& src) {
  const int ne = static_cast<int>(p.edges.size());
  std::vector<int> seam_of(p.edges.size(), -1);
  for (std::size_t i = 0; i < p.seams.size(); ++i) {
    const std::string field = at("finseg:seams", i);
    const auto [a, b] = p.seams[i];
    if (a == b) throw InputError(src, field, fmt::format("edge {} joined to itself", a));
    for (const int e : {a, b}) {
      if (e < 0 || e >= ne) {
        throw InputError(src, field, fmt::format("edge {} out of range 0..{}", e, ne - 1));
      }
      if (p.edges[e].assignment != EdgeAssignment::Boundary) {
        throw InputError(src, field,
                         fmt::format("edge {} is '{}'; a seam joins boundary (B) edges", e,
                                     static_cast<char>(p.edges[e].assignment)));
      }
      if (seam_of[e] >= 0) {
        throw InputError(src, field, fmt::format("edge {} is in seam {} already", e, seam_of[e]));
      }
      seam_of[e] = static_cast<int>(i);
    }
    const PatternEdge &A = p.edges[a], &B = p.edges[b];
    const auto flat_length = [&](const PatternEdge& e) {
      return (p.vertices_flat_m[e.vertices[1]] - p.vertices_flat_m[e.vertices[0]]).norm();
    };
    const double la = flat_length(A), lb = flat_length(B);
    if (std::abs(la - lb) > tol.seam_length * std::max(la, lb)) {
      throw InputError(src, field,
                       fmt::format("edge {} is {:.9g} m long, edge {} {:.9g} m; a seam joins "
                                   "edges of equal length",
                                   a, la, b, lb));
    }
    if ((A.faces[0] >= 0) != (B.faces[0] >= 0)) {
      throw InputError(
          src, field,
          fmt::format("face {} lies left of edge {}, face {} right of edge {}: "
                      "joined u -> v to v -> u the sheet would turn over (a "
                      "Moebius band); reverse one edge",
                      std::max(A.faces[0], A.faces[1]), a, std::max(B.faces[0], B.faces[1]), b));
    }
    if (p.vertices_folded_m.empty()) continue;
    for (int k = 0; k < 2; ++k) {
      const int va = A.vertices[k], vb = B.vertices[1 - k];
      const double gap = (p.vertices_folded_m[va] - p.vertices_folded_m[vb]).norm();
      if (gap > tol.seam_gap * size) {
        throw InputError(src, field,
                         fmt::format("folded, vertex {} of edge {} lies {:.3g} m from vertex {} "
                                     "of edge {} that it joins (limit {:.3g} m)",
                                     va, a, gap, vb, b, tol.seam_gap * size));
      }
    }
  }
}

}  // namespace

void validate_pattern(CreasePattern& p, const std::string& src, const PatternTolerances& tol) {
  check_indices(p, src);
  derive_edge_faces(p, src);
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    check_assignment(p.edges[e], e, src);
    check_fold_angle(p.edges[e], e, src);
  }
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    check_face_shape(p, f, tol, src);
    if (!p.vertices_folded_m.empty()) check_planar(p, f, tol, src);
  }
  Eigen::AlignedBox2d box;
  for (const Vec2& v : p.vertices_flat_m) box.extend(v);
  const auto hit =
      find_edge_crossing(p.vertices_flat_m, p.edges, tol.touch * box.diagonal().norm());
  if (hit) {
    const auto& a = p.edges[(*hit)[0]].vertices;
    const auto& b = p.edges[(*hit)[1]].vertices;
    throw InputError(src, at("edges_vertices", (*hit)[1]),
                     fmt::format("edge {}-{} crosses or overlaps edge {} ({}-{}) away from a "
                                 "shared vertex",
                                 b[0], b[1], (*hit)[0], a[0], a[1]));
  }
  check_seams(p, box.diagonal().norm(), tol, src);
}

double measured_fold_angle(const CreasePattern& p, int e) {
  const PatternEdge& edge = p.edges[e];
  const Vec3 nl = folded_normal(p, edge.faces[0]), nr = folded_normal(p, edge.faces[1]);
  return fold_angle_between(p, nl, nr, edge.vertices);
}

double measured_seam_fold_angle(const CreasePattern& p, int k) {
  const PatternEdge &A = p.edges[p.seams[k][0]], &B = p.edges[p.seams[k][1]];
  // Along a.u -> a.v the face left of its edge runs forwards: a's face if it is left of a,
  // else b's (then both lie right of their edges and b's runs b.v -> b.u = a.u -> a.v).
  const int fa = std::max(A.faces[0], A.faces[1]), fb = std::max(B.faces[0], B.faces[1]);
  const bool a_left = A.faces[0] >= 0;
  const Vec3 nl = folded_normal(p, a_left ? fa : fb), nr = folded_normal(p, a_left ? fb : fa);
  return fold_angle_between(p, nl, nr, A.vertices);
}

}  // namespace finseg
