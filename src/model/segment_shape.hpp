// Shape of a segment: a convex polygon of the sheet's mid-surface (in the body frame,
// centroid at the origin) swept through the thickness. Exact area, centroid, second moments
// and prism inertia; the polygon in the world and on the flat sheet.
#pragma once

#include <string>
#include <vector>

#include "core/types.hpp"

namespace finseg {

/// Vertices of a convex polygon, counter-clockwise about +z, m.
using Outline = std::vector<Vec2>;

/// Most vertices a segment's polygon may have (the contact samples of a pair direction are
/// numbered in 12 bits, collision/contact_forces.cpp).
constexpr std::size_t kMaxOutlineVertices = 32;

/// Signed area (> 0 counter-clockwise), m^2.
double polygon_area(const Outline& v);

/// Area centroid, m.
Vec2 polygon_centroid(const Outline& v);

/// Second moments of area about the origin: (int x^2, int y^2, int x y) dA, m^4.
Vec3 polygon_second_moments(const Outline& v);

/// Inertia about the centroid (kg m^2), in the body frame, of a prism of mass `mass` whose
/// cross-section is `outline_B` (centred on its centroid) and whose height along z is
/// `thickness`, m.
Mat3 prism_inertia(const Outline& outline_B, double thickness, double mass);

/// Rectangle of edge lengths lx (along x) and ly centred at the origin, counter-clockwise
/// from (-lx/2, -ly/2).
Outline rectangle_outline(double lx, double ly);

/// The same outline moved by `d`.
Outline translated(const Outline& v, const Vec2& d);

/// Largest distance of a vertex from the origin, m.
double outline_radius(const Outline& v);

/// Empty when `v` is a convex polygon (at least 3 vertices, counter-clockwise, no two
/// consecutive vertices closer than `tol`, no reflex or straight corner within `tol`);
/// otherwise what is wrong, naming the vertex.
std::string convexity_problem(const Outline& v, double tol);

/// Distance from p to the segment [a, b], m.
double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b);

/// True when the segments [a, b] and [c, d] cross at a point inside both (touching or
/// collinear overlap is not crossing).
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// True when point p lies inside the convex polygon or within `tol` of it.
bool polygon_contains(const Outline& v, const Vec2& p, double tol);

/// Distance between two convex polygons (0 when they touch or overlap), m.
double polygon_distance(const Outline& a, const Outline& b);

/// Corners of the prism in the world: the bottom face (z = -t/2) then the top face, each
/// in the outline's order.
std::vector<Vec3> prism_corners_W(const Outline& outline_B, double thickness, const Vec3& p_W,
                                  const Mat3& R_WB);

}  // namespace finseg
