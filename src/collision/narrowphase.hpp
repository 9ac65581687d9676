// Narrow phase between two thin plates (segments): mid-surface rectangles of half sizes
// (hx, hy) with a thickness 2 r. One plate is the reference, the other the incident plate.
// The incident rectangle, projected onto the reference plane, is clipped by the reference
// rectangle (Sutherland-Hodgman); every vertex of the overlap polygon is a potential
// contact point:
//   - Incident(k): corner k of the incident plate above the reference face,
//   - Reference(k): corner k of the reference plate under the incident face,
//   - Crossing(i, j): incident edge i crossing reference edge line j.
// A vertex whose incident mid-surface point lies closer than r_inc + r_ref to the reference
// mid-surface is in contact; its share of the contact is half the length of the two polygon
// edges next to it over the polygon's perimeter, times the overlap fraction (shares sum to
// at most 1, and stay continuous when vertices split, merge, appear or leave). The clipping runs on
// doubles and fixes the vertex identities; the geometry of each vertex is then evaluated for any
// scalar (forces and autodiff).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

// Eigen/Dense must come before the AutoDiff header that kinematics.hpp pulls in.
#include "core/types.hpp"

#include "elements/kinematics.hpp"

namespace finseg {

/// Shape of a segment: half sizes of the mid-surface rectangle and half thickness.
struct PlateShape {
  double hx = 0, hy = 0, r = 0;
};

inline PlateShape plate_shape(const Vec3& size) {
  return {0.5 * size.x(), 0.5 * size.y(), 0.5 * size.z()};
}

/// Corner k of a plate in its body frame: 0 (-,-), 1 (+,-), 2 (+,+), 3 (-,+).
inline Vec3 plate_corner(const PlateShape& s, int k) {
  const double x = (k == 1 || k == 2) ? s.hx : -s.hx;
  const double y = (k >= 2) ? s.hy : -s.hy;
  return {x, y, 0.0};
}

enum class VertexKind : std::uint8_t { Incident, Reference, Crossing };

/// Identity of one overlap-polygon vertex. Reference edge lines j: 0: x = +hx, 1: y = +hy,
/// 2: x = -hx, 3: y = -hy (reference frame). Incident edge i joins corners i and i+1.
struct PolygonVertex {
  VertexKind kind = VertexKind::Incident;
  std::uint8_t i = 0;  ///< corner (Incident, Reference) or incident edge (Crossing)
  std::uint8_t j = 0;  ///< reference edge line (Crossing)
  int id() const { return static_cast<int>(kind) * 16 + i * 4 + j; }  ///< 0..47
};

/// Overlap polygon of one pair, in order around it.
struct Manifold {
  bool ref_is_a = true;  ///< body a of the pair is the reference plate
  int count = 0;
  std::array<PolygonVertex, 8> poly{};
};

/// Chooses the reference plate and clips. `ref_hint`: 0 = a, 1 = b, -1 = choose (nearly
/// parallel plates: the larger one, then a; otherwise the plate whose normal is more aligned
/// with the line between the centroids). Returns false when the projections do not overlap.
bool clip_plates(const BodyKin<double>& A, const PlateShape& sa, const BodyKin<double>& B,
                 const PlateShape& sb, int ref_hint, Manifold& out);

/// One polygon vertex evaluated for scalar T.
template <class T>
struct VertexGeometry {
  Vec3T<T> p_inc;     ///< point on the incident mid-surface, m
  T height;           ///< signed distance of p_inc from the reference mid-plane along n_ref, m
  T u, v;             ///< position in the reference plane (reference frame x, y), m
  bool valid = true;  ///< false where the incident plane is too steep to intersect reliably
};

template <class T>
VertexGeometry<T> vertex_geometry(const BodyKin<T>& ref, const PlateShape& sr,
                                  const BodyKin<T>& inc, const PlateShape& si,
                                  const PolygonVertex& pv) {
  const Vec3T<T> ex = ref.R_WB.col(0), ey = ref.R_WB.col(1), n = ref.R_WB.col(2);
  VertexGeometry<T> g;
  switch (pv.kind) {
    case VertexKind::Incident:
      g.p_inc = inc.point_W(plate_corner(si, pv.i));
      break;
    case VertexKind::Crossing: {
      const Vec3T<T> p0 = inc.point_W(plate_corner(si, pv.i));
      const Vec3T<T> p1 = inc.point_W(plate_corner(si, (pv.i + 1) % 4));
      const Vec3T<T> axis = (pv.j % 2 == 0) ? ex : ey;
      const double sign = pv.j < 2 ? 1.0 : -1.0;
      const double h = (pv.j % 2 == 0) ? sr.hx : sr.hy;
      const T s0 = T(sign) * axis.dot(p0 - ref.p_W), s1 = T(sign) * axis.dot(p1 - ref.p_W);
      const T ds = s1 - s0;
      const T t = std::abs(value_of(ds)) > 0 ? (T(h) - s0) / ds : T(0);
      g.p_inc = p0 + t * (p1 - p0);
      break;
    }
    case VertexKind::Reference: {
      const Vec3T<T> q = ref.point_W(plate_corner(sr, pv.i));
      const Vec3T<T> ni = inc.R_WB.col(2);
      const T cosang = ni.dot(n);
      if (std::abs(value_of(cosang)) < 0.1) {
        g.valid = false;
        g.p_inc = q;
      } else {
        g.p_inc = q + (ni.dot(inc.p_W - q) / cosang) * n;
      }
      break;
    }
  }
  const Vec3T<T> d = g.p_inc - ref.p_W;
  g.height = n.dot(d);
  g.u = ex.dot(d);
  g.v = ey.dot(d);
  return g;
}

/// Shares of the polygon vertices in the contact. The polygon's vertices split it by
/// perimeter (each gets half the length of its two edges over the perimeter), times the
/// overlap fraction: polygon area over the incident plate's projected area (at most 1), so
/// that a plate barely overlapping an edge carries little and a plate fully on another, or
/// standing on it edge-on, carries the whole face stiffness. Returns false for a degenerate
/// polygon (zero perimeter).
template <class T>
bool vertex_shares(const VertexGeometry<T>* g, int count, const T& incident_projected_area,
                   double incident_area, T* share) {
  using std::abs;
  using std::sqrt;
  if (count < 2) return false;
  std::array<T, 8> len;
  T perimeter(0), twice_area(0);
  for (int k = 0; k < count; ++k) {
    const int l = (k + 1) % count;
    const T du = g[l].u - g[k].u, dv = g[l].v - g[k].v;
    const T l2 = du * du + dv * dv;
    len[k] = value_of(l2) > 1e-300 ? T(sqrt(l2)) : T(0);
    perimeter += len[k];
    twice_area += g[k].u * g[l].v - g[l].u * g[k].v;
  }
  if (!(value_of(perimeter) > 0)) return false;
  T fraction(1);
  if (value_of(incident_projected_area) > 1e-9 * incident_area) {
    const T area = (value_of(twice_area) < 0 ? T(-twice_area) : twice_area) / T(2);
    if (value_of(area) < value_of(incident_projected_area))
      fraction = area / incident_projected_area;
  }
  for (int k = 0; k < count; ++k)
    share[k] = fraction * (len[(k + count - 1) % count] + len[k]) / (T(2) * perimeter);
  return true;
}

/// Area of the incident rectangle projected onto the reference plane, m^2.
template <class T>
T projected_area(const BodyKin<T>& ref, const BodyKin<T>& inc, const PlateShape& si) {
  const T c = inc.R_WB.col(2).dot(ref.R_WB.col(2));
  return T(4 * si.hx * si.hy) * (value_of(c) < 0 ? T(-c) : c);
}

}  // namespace finseg
