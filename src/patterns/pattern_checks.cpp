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
}

double measured_fold_angle(const CreasePattern& p, int e) {
  const PatternEdge& edge = p.edges[e];
  auto normal = [&](int f) {
    Vec3 n = Vec3::Zero();  // Newell's method: robust for any planar polygon
    const std::vector<int>& loop = p.faces[f];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      n += p.vertices_folded_m[loop[i]].cross(p.vertices_folded_m[loop[(i + 1) % loop.size()]]);
    }
    return n.normalized();
  };
  const Vec3 nl = normal(edge.faces[0]), nr = normal(edge.faces[1]);
  const Vec3 d =
      (p.vertices_folded_m[edge.vertices[1]] - p.vertices_folded_m[edge.vertices[0]]).normalized();
  return std::atan2(nr.cross(nl).dot(d), nl.dot(nr));
}

}  // namespace finseg
