#include "model/segment_shape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace finseg {
double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double s = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + s * d)).norm();
}

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = cross2d(b - a, c - a), o2 = cross2d(b - a, d - a);
  const double o3 = cross2d(d - c, a - c), o4 = cross2d(d - c, b - c);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

double polygon_area(const Outline& v) {
  double a = 0;
  for (std::size_t i = 0; i < v.size(); ++i) a += cross2d(v[i], v[(i + 1) % v.size()]);
  return 0.5 * a;
}

Vec2 polygon_centroid(const Outline& v) {
  // Relative to the vertices' mean: far from the origin the products would cancel.
  Vec2 o = Vec2::Zero();
  for (const Vec2& p : v) o += p;
  o /= static_cast<double>(v.size());
  Vec2 c = Vec2::Zero();
  double a = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2 p = v[i] - o, q = v[(i + 1) % v.size()] - o;
    const double w = cross2d(p, q);
    a += w;
    c += w * (p + q);
  }
  return o + c / (3 * a);
}

Vec3 polygon_second_moments(const Outline& v) {
  double xx = 0, yy = 0, xy = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2 &p = v[i], &q = v[(i + 1) % v.size()];
    const double w = cross2d(p, q);
    xx += w * (p.x() * p.x() + p.x() * q.x() + q.x() * q.x());
    yy += w * (p.y() * p.y() + p.y() * q.y() + q.y() * q.y());
    xy += w * (p.x() * q.y() + 2 * p.x() * p.y() + 2 * q.x() * q.y() + q.x() * p.y());
  }
  return Vec3(xx / 12, yy / 12, xy / 24);
}

Mat3 prism_inertia(const Outline& outline_B, double thickness, double mass) {
  // Per unit mass: in-plane second moments over the area, plus t^2/12 through the thickness.
  const double area = polygon_area(outline_B);
  const Vec3 s = polygon_second_moments(outline_B) / area;  // <x^2>, <y^2>, <xy>
  const double zz = thickness * thickness / 12;
  Mat3 J;
  J << s.y() + zz, -s.z(), 0, -s.z(), s.x() + zz, 0, 0, 0, s.x() + s.y();
  return mass * J;
}

Outline rectangle_outline(double lx, double ly) {
  const double hx = 0.5 * lx, hy = 0.5 * ly;
  return {Vec2(-hx, -hy), Vec2(hx, -hy), Vec2(hx, hy), Vec2(-hx, hy)};
}

Outline translated(const Outline& v, const Vec2& d) {
  Outline out = v;
  for (Vec2& p : out) p += d;
  return out;
}

double outline_radius(const Outline& v) {
  double r = 0;
  for (const Vec2& p : v) r = std::max(r, p.norm());
  return r;
}

std::string convexity_problem(const Outline& v, double tol) {
  const std::size_t n = v.size();
  if (n < 3) return fmt::format("has {} vertices; a segment needs at least 3", n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!v[i].allFinite()) return fmt::format("vertex {} is not finite", i);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 &a = v[i], &b = v[(i + 1) % n], &c = v[(i + 2) % n];
    if ((b - a).norm() <= tol) return fmt::format("vertices {} and {} coincide", i, (i + 1) % n);
    // Corner b: the turn must be to the left by more than tol (relative to the edges).
    if (cross2d(b - a, c - b) <= tol * ((b - a).norm() + (c - b).norm())) {
      return fmt::format("is not convex and counter-clockwise at vertex {}", (i + 1) % n);
    }
  }
  if (!(polygon_area(v) > 0)) return "is not counter-clockwise";
  // A star polygon turns left everywhere but winds more than once.
  double turning = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e0 = v[(i + 1) % n] - v[i], e1 = v[(i + 2) % n] - v[(i + 1) % n];
    turning += std::atan2(cross2d(e0, e1), e0.dot(e1));
  }
  if (turning > 2 * kPi + 1e-6) return "winds more than once (a star, not a convex polygon)";
  return {};
}

bool polygon_contains(const Outline& v, const Vec2& p, double tol) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e = v[(i + 1) % n] - v[i];
    if (cross2d(e, p - v[i]) < -tol * e.norm()) return false;
  }
  return true;
}

double polygon_distance(const Outline& a, const Outline& b) {
  for (const Vec2& p : a)
    if (polygon_contains(b, p, 0)) return 0;
  for (const Vec2& p : b)
    if (polygon_contains(a, p, 0)) return 0;
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 &a0 = a[i], &a1 = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec2 &b0 = b[j], &b1 = b[(j + 1) % b.size()];
      if (segments_cross(a0, a1, b0, b1)) return 0;
      d = std::min({d, point_segment_distance(a0, b0, b1), point_segment_distance(b0, a0, a1)});
    }
  }
  return d;
}

std::vector<Vec3> prism_corners_W(const Outline& outline_B, double thickness, const Vec3& p_W,
                                  const Mat3& R_WB) {
  std::vector<Vec3> c;
  c.reserve(2 * outline_B.size());
  for (const double z : {-0.5 * thickness, 0.5 * thickness}) {
    for (const Vec2& v : outline_B) c.push_back(p_W + R_WB * Vec3(v.x(), v.y(), z));
  }
  return c;
}

}  // namespace finseg
