// Polygonal segments against closed forms: areas, centroids and second moments of triangles,
// rectangles and regular hexagons (engineering tables), prism inertia, the convexity check,
// the polygon distances of the contact rules, the narrow phase's closest-point offset and
// sample weights on triangles, quadrilaterals and pentagons, and a triangle and a pentagon
// resting on a plate under their own weight.
#include <gtest/gtest.h>

#include <cmath>

#include "collision/contact_laws.hpp"
#include "collision/narrowphase.hpp"
#include "core/error.hpp"
#include "core/so3.hpp"
#include "model/model.hpp"
#include "model/segment_shape.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace segment_shape_test {

Outline regular_polygon(int n, double circumradius, double phase = 0) {
  Outline v;
  for (int k = 0; k < n; ++k) {
    const double a = phase + 2 * kPi * k / n;
    v.emplace_back(circumradius * std::cos(a), circumradius * std::sin(a));
  }
  return v;
}

TEST(SegmentShape, TriangleAreaCentroidAndSecondMomentsMatchTheTables) {
  // Right triangle (0,0), (a,0), (0,b): A = ab/2, centroid (a/3, b/3), about the centroid
  // I_x = int y^2 = a b^3 / 36, I_y = a^3 b / 36, I_xy = int x y = -a^2 b^2 / 72.
  const double a = 0.03, b = 0.02;
  const Outline tri{Vec2(0, 0), Vec2(a, 0), Vec2(0, b)};
  EXPECT_NEAR(polygon_area(tri), a * b / 2, 1e-18);
  EXPECT_NEAR((polygon_centroid(tri) - Vec2(a / 3, b / 3)).norm(), 0, 1e-17);
  const Vec3 m = polygon_second_moments(translated(tri, -polygon_centroid(tri)));
  EXPECT_NEAR(m.x() / (a * a * a * b / 36), 1, 1e-12);
  EXPECT_NEAR(m.y() / (a * b * b * b / 36), 1, 1e-12);
  EXPECT_NEAR(m.z() / (-a * a * b * b / 72), 1, 1e-12);
}

TEST(SegmentShape, PrismInertiaIsTheBoxForARectangleAndTurnsWithIt) {
  const double a = 0.05, b = 0.02, t = 1e-3, mass = 0.3;
  BodyDef box;
  set_box(box, Vec3(a, b, t), mass);
  const Vec3 diag(b * b + t * t, a * a + t * t, a * a + b * b);
  EXPECT_NEAR((box.J_B - (mass / 12) * Mat3(diag.asDiagonal())).norm(), 0, 1e-18);
  // The same rectangle turned by 0.7 rad in its plane: R J R^T.
  const Mat3 R = so3_exp<double>(Vec3(0, 0, 0.7));
  Outline turned = rectangle_outline(a, b);
  for (Vec2& v : turned) v = R.topLeftCorner<2, 2>() * v;
  const Mat3 J = prism_inertia(turned, t, mass);
  EXPECT_NEAR((J - R * box.J_B * R.transpose()).norm(), 0, 1e-18);
}

TEST(SegmentShape, RegularHexagonPolarMomentMatchesTheTable) {
  // Regular hexagon of side s: A = 3 sqrt(3) s^2 / 2, polar moment 5 sqrt(3) s^4 / 8, so
  // J_zz = m 5 s^2 / 12, and J_xx = J_yy = m (5 s^2 / 24 + t^2 / 12).
  const double s = 0.01, t = 2e-4, mass = 1e-3;
  BodyDef hex;
  const Vec2 c = set_prism(hex, translated(regular_polygon(6, s, 0.3), Vec2(0.4, -0.2)), t, mass);
  EXPECT_NEAR((c - Vec2(0.4, -0.2)).norm(), 0, 1e-15);
  EXPECT_NEAR(segment_area(hex) / (1.5 * std::sqrt(3.0) * s * s), 1, 1e-13);
  EXPECT_NEAR(hex.J_B(2, 2) / (mass * 5 * s * s / 12), 1, 1e-12);
  EXPECT_NEAR(hex.J_B(0, 0) / (mass * (5 * s * s / 24 + t * t / 12)), 1, 1e-12);
  EXPECT_NEAR(hex.J_B(0, 1), 0, 1e-12 * hex.J_B(2, 2));
  EXPECT_NEAR(polygon_centroid(hex.outline_B).norm(), 0, 1e-17);
}

TEST(SegmentShape, ConvexityCheckNamesTheVertex) {
  EXPECT_EQ(convexity_problem(regular_polygon(5, 1), 1e-12), "");
  const Outline reflex{Vec2(0, 0), Vec2(2, 0), Vec2(1, 0.3), Vec2(2, 2), Vec2(0, 2)};
  EXPECT_NE(convexity_problem(reflex, 1e-12).find("vertex 2"), std::string::npos);
  Outline cw = regular_polygon(4, 1);
  std::reverse(cw.begin(), cw.end());
  EXPECT_NE(convexity_problem(cw, 1e-12), "");
  Outline star;  // a pentagram: turns left at every vertex but winds twice
  for (int k = 0; k < 5; ++k) star.push_back(regular_polygon(5, 1)[(2 * k) % 5]);
  EXPECT_NE(convexity_problem(star, 1e-12).find("winds"), std::string::npos);
  EXPECT_NE(convexity_problem({Vec2(0, 0), Vec2(1, 0)}, 1e-12).find("3"), std::string::npos);
  BodyDef b;
  set_box(b, Vec3(1, 1, 0.1), 1);
  b.outline_B = reflex;
  Model m;
  m.bodies = {b};
  m.finalize_dofs();
  EXPECT_THROW(validate(m), InputError);
}

TEST(SegmentShape, PolygonDistanceOfSeparateTouchingAndOverlappingPolygons) {
  const Outline sq = rectangle_outline(1, 1);
  EXPECT_NEAR(polygon_distance(sq, translated(sq, Vec2(1.5, 0))), 0.5, 1e-15);
  EXPECT_NEAR(polygon_distance(sq, translated(sq, Vec2(1.3, 1.4))), std::hypot(0.3, 0.4), 1e-15);
  EXPECT_EQ(polygon_distance(sq, translated(sq, Vec2(1, 0.2))), 0.0);  // shared edge
  EXPECT_EQ(polygon_distance(sq, translated(sq, Vec2(1, 1))), 0.0);    // shared corner
  // A triangle whose tip pierces the square's edge without any vertex inside the other.
  const Outline tri{Vec2(-0.1, 0.6), Vec2(0.1, 0.6), Vec2(0, 0.4)};
  EXPECT_EQ(polygon_distance(sq, tri), 0.0);
  const Outline thin{Vec2(-2, 0.45), Vec2(2, 0.45), Vec2(2, 0.55), Vec2(-2, 0.55)};
  EXPECT_EQ(polygon_distance(sq, thin), 0.0);  // crossing edges, no vertex inside
}

TEST(SegmentShape, ClosestPointOffsetOfATriangleAndItsDerivative) {
  const Outline tri{Vec2(0, 0), Vec2(0.02, 0), Vec2(0, 0.01)};
  double du, dv;
  polygon_offset(tri, 0.005, 0.002, du, dv);  // inside
  EXPECT_EQ(du, 0.0);
  EXPECT_EQ(dv, 0.0);
  // Beside the hypotenuse x/0.02 + y/0.01 = 1: offset along its outward normal.
  const Vec2 n = Vec2(0.01, 0.02).normalized();
  const Vec2 foot(0.01, 0.005), p = foot + 3e-3 * n;
  polygon_offset(tri, p.x(), p.y(), du, dv);
  EXPECT_NEAR((Vec2(du, dv) - 3e-3 * n).norm(), 0, 1e-17);
  // Beyond the vertex (0.02, 0): offset from the vertex.
  polygon_offset(tri, 0.025, -0.001, du, dv);
  EXPECT_NEAR((Vec2(du, dv) - Vec2(0.005, -0.001)).norm(), 0, 1e-17);
  // Derivative by autodiff equals the central difference of the distance.
  using AD = AutoDiff<2>;
  const double x = 0.012, y = 0.009, h = 1e-8;
  AD adu, adv;
  polygon_offset(tri, AD(x, 2, 0), AD(y, 2, 1), adu, adv);
  const AD dist = sqrt(adu * adu + adv * adv);
  auto distance = [&](double px, double py) {
    double a, b;
    polygon_offset(tri, px, py, a, b);
    return std::hypot(a, b);
  };
  EXPECT_NEAR(dist.derivatives()[0], (distance(x + h, y) - distance(x - h, y)) / (2 * h), 1e-7);
  EXPECT_NEAR(dist.derivatives()[1], (distance(x, y + h) - distance(x, y - h)) / (2 * h), 1e-7);
}

// Mean of f over the polygon by the contact samples.
template <class F>
double sample_mean(const Outline& v, int n, F f) {
  const PlateShape s{&v, polygon_area(v), 1e-4};
  double sum = 0, weights = 0;
  for (const PlateSample& p : plate_samples(s, n)) {
    sum += p.weight * f(p.r_B.x(), p.r_B.y());
    weights += p.weight;
  }
  EXPECT_NEAR(weights, 1, 1e-14);
  return sum;
}

TEST(SegmentShape, SamplesAverageOverTrianglesQuadrilateralsAndPentagons) {
  // Means of x^2 over the polygon: the second moment over the area (exact above). The
  // samples converge at second order (trapezoidal rule on each bilinear map).
  const Outline shapes[] = {
      Outline{Vec2(0, 0), Vec2(0.03, 0), Vec2(0, 0.02)},
      Outline{Vec2(0, 0), Vec2(0.03, 0.005), Vec2(0.025, 0.02), Vec2(-0.004, 0.018)},
      regular_polygon(5, 0.01, 0.2)};
  for (const Outline& v : shapes) {
    const double exact = polygon_second_moments(v).x() / polygon_area(v);
    const Vec2 c = polygon_centroid(v);
    double last = 0;
    for (int n : {3, 6, 12}) {
      const double err =
          std::abs(sample_mean(v, n, [](double x, double) { return x * x; }) - exact);
      const double cx = sample_mean(v, n, [](double x, double) { return x; });
      EXPECT_LT(std::abs(cx - c.x()), 0.5 / (n * n) * outline_radius(v)) << v.size() << " " << n;
      if (n > 3) {
        EXPECT_LT(err, 0.35 * last) << v.size() << " sides, n = " << n;
      }
      last = err;
    }
  }
}

// A convex plate lying on a large fixed plate under gravity comes to rest where the contact
// carries its weight: K delta^e = m g (the face law of docs/contact.md), for any polygon.
TEST(SegmentShape, TriangleAndPentagonRestOnAPlateWhereContactCarriesTheirWeight) {
  for (const Outline& shape :
       {Outline{Vec2(0, 0), Vec2(0.03, 0), Vec2(0.01, 0.025)}, regular_polygon(5, 0.012, 0.1)}) {
    Model m;
    BodyDef base;
    base.name = "base";
    set_box(base, Vec3(0.2, 0.2, 1e-3), 1.0);
    base.fixed = true;
    BodyDef top;
    top.name = "top";
    set_prism(top, shape, 1e-3, 2e-3);
    top.p0_W = Vec3(0.01, -0.005, 1e-3);
    top.R0_WB = so3_exp<double>(Vec3(0, 0, 0.5));
    m.bodies = {base, top};
    m.gravity_W = Vec3(0, 0, -9.81);
    const double mass = 2e-3, g = 9.81;
    const ContactSuggestion sug = suggest_contact(mass, g, 1e-5);
    m.contact.enabled = true;
    m.contact.stiffness = sug.stiffness;
    m.contact.damping = sug.damping;
    m.contact.damping_depth = sug.damping_depth;
    m.finalize_dofs();
    State s = initial_state(m);
    SolverSettings settings;
    settings.kind = SolverKind::Implicit;
    settings.t_end = 0.5;
    settings.output_interval = 0.1;
    const SolverStats st = run_solver(m, s, settings, nullptr);
    ASSERT_EQ(st.status, "ok") << st.message;
    const double delta = std::pow(mass * g / sug.stiffness, 1 / m.contact.exponent);
    EXPECT_NEAR(s.p_W[1].z(), 1e-3 - delta, 1e-3 * delta) << shape.size() << " sides";
    EXPECT_NEAR(s.R_WB[1].col(2).z(), 1, 1e-9);
  }
}

}  // namespace segment_shape_test
}  // namespace finseg
