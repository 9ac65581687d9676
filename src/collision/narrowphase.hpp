// Narrow phase between two thin plates (segments). Each plate is a rounded plate: its
// mid-surface polygon (convex) swept by a sphere of its half thickness r. The
// contact is sampled: a grid of points on the mid-surface of one plate (the source) is
// tested against the rounded plate of the other (the target). A point p lies in contact
// where its distance to the target polygon is below r_src + r_tgt; the normal points from
// the closest point of the polygon to p. The distance to a convex polygon is continuously
// differentiable outside it, so forces stay smooth while plates slide over edges, meet
// edge to edge or tilt, which the static solver's Newton iteration needs.
//
// Each sample carries a weight (trapezoidal rule over the plate, weights summing to 1) and
// each direction of a pair a share: the smaller plate's points carry the pair, equal plates
// share it half and half, so that a plate lying fully on another feels exactly the IMPACT
// force of eq. 18 at its penetration.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

// Eigen/Dense must come before the AutoDiff header that kinematics.hpp pulls in.
#include "core/types.hpp"

#include "collision/sunk_edge.hpp"
#include "elements/kinematics.hpp"
#include "model/model.hpp"

namespace finseg {

/// Shape of a segment: its mid-surface polygon (body frame), area and half thickness.
struct PlateShape {
  const Outline* outline = nullptr;
  double area = 0;  ///< m^2
  double r = 0;     ///< half thickness, m
};

inline PlateShape plate_shape(const BodyDef& b) {
  return {&b.outline_B, segment_area(b), 0.5 * b.thickness};
}

/// Feature of a convex polygon closest to an in-plane point outside it: edge i (from vertex i
/// to vertex i + 1) or vertex i; both -1 when the point is inside.
struct PolygonFeature {
  int edge = -1;
  int vertex = -1;
};

/// The feature of `poly` closest to the in-plane point (u, v), decided on doubles.
inline PolygonFeature closest_feature(const Outline& poly, double uu, double vv) {
  const std::size_t n = poly.size();
  double best = std::numeric_limits<double>::infinity();
  PolygonFeature f;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = poly[i], &b = poly[(i + 1) % n];
    const Vec2 e = b - a;
    const double len = e.norm();
    const double dn = (e.y() / len) * (uu - a.x()) + (-e.x() / len) * (vv - a.y());
    if (!(dn > 0)) continue;
    const double st = (e.x() / len) * (uu - a.x()) + (e.y() / len) * (vv - a.y());
    if (st >= 0 && st <= len) {
      if (dn < best) best = dn, f = {static_cast<int>(i), -1};
    } else {
      const std::size_t k = st < 0 ? i : (i + 1) % n;
      const double d = std::hypot(uu - poly[k].x(), vv - poly[k].y());
      if (d < best) best = d, f = {-1, static_cast<int>(k)};
    }
  }
  return f;
}

/// Unit outward normal of edge i of a counter-clockwise polygon.
inline Vec2 edge_normal(const Outline& poly, int i) {
  const Vec2 e = poly[(i + 1) % poly.size()] - poly[i];
  const double len = e.norm();
  return {e.y() / len, -e.x() / len};
}

/// Offset (du, dv) of the in-plane point (u, v) from feature f of the polygon (zero for
/// none): along the edge's outward normal, or from the vertex.
template <class T>
void feature_offset(const Outline& poly, const PolygonFeature& f, const T& u, const T& v, T& du,
                    T& dv) {
  if (f.edge >= 0) {
    const Vec2& a = poly[f.edge];
    const Vec2 nrm = edge_normal(poly, f.edge);
    const T dn = T(nrm.x()) * (u - T(a.x())) + T(nrm.y()) * (v - T(a.y()));
    du = dn * T(nrm.x());
    dv = dn * T(nrm.y());
  } else if (f.vertex >= 0) {
    du = u - T(poly[f.vertex].x());
    dv = v - T(poly[f.vertex].y());
  } else {
    du = dv = T(0);
  }
}

/// Offset (du, dv) of the in-plane point (u, v) from the closest point of the convex
/// polygon, zero inside. Beside an edge it is the offset along the edge's outward normal
/// (exact for edges along the axes); beyond a corner, the offset from the vertex.
template <class T>
void polygon_offset(const Outline& poly, const T& u, const T& v, T& du, T& dv) {
  feature_offset(poly, closest_feature(poly, value_of(u), value_of(v)), u, v, du, dv);
}

/// d(du, dv) / d(u, v) of polygon_offset at feature f: n n^T beside edge n, the identity
/// beyond a vertex, zero inside.
inline Eigen::Matrix2d polygon_offset_slope(const Outline& poly, const PolygonFeature& f) {
  if (f.edge >= 0) {
    const Vec2 nrm = edge_normal(poly, f.edge);
    return nrm * nrm.transpose();
  }
  if (f.vertex >= 0) return Eigen::Matrix2d::Identity();
  return Eigen::Matrix2d::Zero();
}

/// One sample point of a plate: position in the body frame (mid-surface) and weight.
struct PlateSample {
  Vec3 r_B = Vec3::Zero();
  double weight = 0;
};

/// Samples over the mid-surface polygon, vertices and sides included, weights summing to 1:
/// a parallelogram (a rectangle) carries the n x n grid with trapezoidal weights (exact for
/// bilinear functions); any other polygon is fanned into triangles from its first vertex,
/// each carrying its lattice of n points per side, a point weighted by a third of the area of
/// the lattice triangles around it (exact for linear functions: the samples' centroid is the
/// polygon's). n >= 2.
std::vector<PlateSample> plate_samples(const PlateShape& s, int n);

/// Shares of the two directions of a pair (points of a on b, points of b on a): the plate
/// of smaller area carries the pair; plates of equal area (within 1e-6) share it.
struct DirectionShares {
  double a_on_b = 0, b_on_a = 0;
};
DirectionShares direction_shares(const PlateShape& a, const PlateShape& b);

/// A sample point of the source plate against the target plate, for scalar T.
template <class T>
struct PointContact {
  Vec3T<T> n_W;  ///< unit normal from the target towards the source point
  Vec3T<T> x_W;  ///< contact point: middle of the overlap of the two rounded surfaces, m
  T depth;       ///< r_src + r_tgt - distance, m (> 0: in contact)
  T height;      ///< signed distance of p_W from the target mid-plane, m
  T dist;        ///< distance from the target polygon (side * height over its face), m
  T du, dv;      ///< in-plane offset from the target polygon (target frame; 0 over the face)
  PolygonFeature feature;  ///< the polygon's closest feature (none: over the face)
};

/// Contact of the source point p_W (on a plate of half thickness r_src) with the target
/// rounded plate. `side` (+1 / -1) is the face of the target the point is on; above the
/// polygon it keeps a point that has sunk past the target's mid-plane pushing back towards its
/// own side. `sunk`: the point was past the mid-plane already at the last commit of the
/// history; beside the polygon its distance then joins that push continuously to the rim's
/// (collision/sunk_edge.hpp; `dist` is that distance, `n_W` its direction of steepest
/// growth); else beside the polygon only the rim counts, whatever the side.
template <class T>
PointContact<T> point_on_plate(const BodyKin<T>& tgt, const PlateShape& st, const Vec3T<T>& p_W,
                               double r_src, int side, bool sunk = false) {
  using std::sqrt;
  const Vec3T<T> ex = tgt.R_WB.col(0), ey = tgt.R_WB.col(1), ez = tgt.R_WB.col(2);
  const Vec3T<T> d = p_W - tgt.p_W;
  const T u = ex.dot(d), v = ey.dot(d), h = ez.dot(d);
  PointContact<T> c;
  c.feature = closest_feature(*st.outline, value_of(u), value_of(v));
  T du, dv;
  feature_offset(*st.outline, c.feature, u, v, du, dv);
  c.height = h;
  c.du = du;
  c.dv = dv;
  T dist;
  if (value_of(du) == 0 && value_of(dv) == 0) {
    dist = T(static_cast<double>(side)) * h;
    c.n_W = T(static_cast<double>(side)) * ez;
  } else if (sunk && side * value_of(h) < 0) {
    const T delta = sqrt(du * du + dv * dv);
    const SunkEdgeDistance<T> s = sunk_edge_distance(delta, h, r_src + st.r);
    dist = s.f;
    const Vec3T<T> g = (s.f_delta / delta) * (du * ex + dv * ey) + s.f_h * ez;
    c.n_W = g / sqrt(g.dot(g));
  } else {
    dist = sqrt(du * du + dv * dv + h * h);
    c.n_W = (du * ex + dv * ey + h * ez) / dist;
  }
  c.dist = dist;
  c.depth = T(r_src + st.r) - dist;
  c.x_W = p_W - c.n_W * ((dist + T(r_src - st.r)) / T(2));
  return c;
}

}  // namespace finseg
