// Contact geometry, laws and Jacobians, without a solver: the rounded-plate distance against
// hand-computed points, the broad phase against brute force, the laws against their closed forms,
// the autodiff Jacobian against central differences, and the pair rules.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <random>

#include "collision/broadphase.hpp"
#include "collision/contact_forces.hpp"
#include "collision/contact_laws.hpp"
#include "collision/narrowphase.hpp"
#include "core/error.hpp"
#include "elements/assembler.hpp"
#include "generators/zigzag.hpp"

namespace finseg {
namespace contact_geometry_test {

BodyKin<double> kin(const Vec3& p, const Mat3& R = Mat3::Identity()) {
  return {p, R, Vec3::Zero(), Vec3::Zero()};
}

Mat3 rot_z(double a) {
  return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix();
}

// A rectangular plate shape of half sizes hx, hy and half thickness r, with its outline.
struct Rect {
  double hx, hy, r;
  Outline outline;
  PlateShape shape;
  Rect(double hx_, double hy_, double r_)
      : hx(hx_), hy(hy_), r(r_), outline(rectangle_outline(2 * hx_, 2 * hy_)) {
    shape = {&outline, 4 * hx * hy, r};
  }
  Rect(const Rect&) = delete;
};

// A segment of the given box size (z: thickness).
BodyDef box(const Vec3& size) {
  BodyDef b;
  set_box(b, size, 1.0);
  return b;
}

// Target plate turned about z and lifted: the point tests run in its frame.
BodyKin<double> target() {
  return kin(Vec3(0.01, -0.02, 0.003), rot_z(0.4));
}
Vec3 in_target(const Vec3& local) {
  const BodyKin<double> t = target();
  return t.p_W + t.R_WB * local;
}

TEST(RoundedPlate, PointOverTheFaceTouchesAlongTheNormal) {
  const Rect st(0.01, 0.005, 5e-5);
  const double r_src = 4e-5, h = 6e-5;
  const PointContact<double> c =
      point_on_plate(target(), st.shape, in_target({0.003, -0.004, h}), r_src, 1);
  EXPECT_NEAR(c.depth, r_src + st.r - h, 1e-16);
  EXPECT_NEAR((c.n_W - target().R_WB.col(2)).norm(), 0, 1e-14);
  // Contact point: half way between the two surfaces (at heights st.r and h - r_src).
  EXPECT_NEAR((c.x_W - in_target({0.003, -0.004, 0.5 * (st.r + h - r_src)})).norm(), 0, 1e-16);
  // Sunk past the mid-plane on the remembered side: still pushed back up, deeper.
  const PointContact<double> sunk =
      point_on_plate(target(), st.shape, in_target({0.003, -0.004, -1e-5}), r_src, 1);
  EXPECT_NEAR(sunk.depth, r_src + st.r + 1e-5, 1e-16);
  EXPECT_GT(sunk.n_W.dot(target().R_WB.col(2)), 0.999999);
}

TEST(RoundedPlate, PointsBesideAnEdgeAndBeyondACornerTouchTheRoundedRim) {
  const Rect st(0.01, 0.005, 5e-5);
  const double r_src = 5e-5;
  // Beside the edge x = +hx: distance to the edge line in the x-z plane.
  const double a = 3e-5, b = 4e-5;  // distance 5e-5
  const PointContact<double> e =
      point_on_plate(target(), st.shape, in_target({st.hx + a, 0.001, b}), r_src, 1);
  EXPECT_NEAR(e.depth, r_src + st.r - 5e-5, 1e-16);
  EXPECT_NEAR((e.n_W - target().R_WB * Vec3(0.6, 0, 0.8)).norm(), 0, 1e-12);
  // Beyond the corner (+hx, -hy): distance to the corner point.
  const Vec3 off(2e-5, -2e-5, 1e-5);  // distance 3e-5
  const PointContact<double> k =
      point_on_plate(target(), st.shape, in_target(Vec3(st.hx, -st.hy, 0) + off), r_src, 1);
  EXPECT_NEAR(k.depth, r_src + st.r - 3e-5, 1e-16);
  EXPECT_NEAR((k.n_W - target().R_WB * off / 3e-5).norm(), 0, 1e-12);
  // The depth is continuous across the edge and so is its slope (distance to a convex set).
  const double h = 6e-5, eps = 1e-9;
  auto depth_at = [&](double x) {
    return point_on_plate(target(), st.shape, in_target({x, 0, h}), r_src, 1).depth;
  };
  EXPECT_NEAR(depth_at(st.hx - eps) - depth_at(st.hx + eps), eps * eps / (2 * h), 1e-18);
  const double slope_in = (depth_at(st.hx - eps) - depth_at(st.hx - 3 * eps)) / (2 * eps);
  const double slope_out = (depth_at(st.hx + 3 * eps) - depth_at(st.hx + eps)) / (2 * eps);
  EXPECT_NEAR(slope_in, 0, 1e-6);
  EXPECT_NEAR(slope_out, 0, 1e-3);  // -x/dist with x of a few eps: nearly flat
}

// A point that had sunk past the mid-plane (below it, side +1) at the last commit slides off
// the face across an edge: over the face it is pushed back up from r_src + r + |h| deep;
// beside the edge the rim alone would see it r_src + r - |h| deep and push it on down, a jump
// of twice its force. collision/sunk_edge.hpp joins the two with a continuous depth and normal.
TEST(RoundedPlate, SunkPointBesideAnEdgeJoinsThePushOverTheFace) {
  const Rect st(0.01, 0.005, 5e-5);
  const double r_src = 5e-5, reach = r_src + st.r, h = -3e-5;
  const Vec3 up = target().R_WB.col(2);
  auto at = [&](double dx, double z, bool sunk = true) {
    return point_on_plate(target(), st.shape, in_target({st.hx + dx, 0.001, z}), r_src, 1, sunk);
  };
  const double eps = 1e-12;
  const PointContact<double> in = at(-eps, h), out = at(eps, h);
  EXPECT_NEAR(in.depth, reach - h, 1e-16);
  // Not sunk at the last commit (it crossed the mid-plane beside the plate: round the rim),
  // only the rim counts.
  EXPECT_NEAR(at(eps, h, false).depth, reach - std::abs(h), 1e-15);
  EXPECT_NEAR(out.depth, in.depth, 1e-15);
  EXPECT_LT((out.n_W - in.n_W).norm(), 1e-6);
  EXPECT_GT(out.n_W.dot(up), 0.999999);
  // Farther out the depth falls and the push turns outwards, all the way to zero at the rim.
  double last = in.depth;
  for (double dx : {0.1 * reach, 0.3 * reach, 0.6 * reach, 0.9 * reach}) {
    const PointContact<double> c = at(dx, h);
    EXPECT_LT(c.depth, last) << dx;
    EXPECT_GT(c.n_W.dot(target().R_WB.col(0)), 0) << dx;
    last = c.depth;
  }
  // From the two half thicknesses out it is the rim's distance: no contact.
  for (double dx : {reach, 2 * reach}) {
    EXPECT_NEAR(at(dx, h).depth, reach - std::hypot(dx, h), 1e-16) << dx;
    EXPECT_LT(at(dx, h).depth, 0);
  }
  // Across the mid-plane beside the edge (sunk below, on its side above) depth and normal
  // are continuous too.
  for (double dx : {0.2 * reach, 0.7 * reach}) {
    const PointContact<double> below = at(dx, -eps), above = at(dx, eps);
    EXPECT_NEAR(below.depth, above.depth, 1e-15) << dx;
    EXPECT_LT((below.n_W - above.n_W).norm(), 1e-6) << dx;
  }
}

TEST(RoundedPlate, SamplesIntegrateBilinearFunctionsExactly) {
  // Trapezoidal rule: exact for bilinear integrands. Mean of (x + hx)(y + hy) / (4 hx hy)
  // over the rectangle is 1/4; the mean of x y is 0.
  const Rect s(0.02, 0.005, 1e-4);
  for (int n : {2, 3, 5}) {
    const std::vector<PlateSample> samples = plate_samples(s.shape, n);
    ASSERT_EQ(samples.size(), static_cast<std::size_t>(n * n));
    double sum = 0, bilinear = 0, xy = 0;
    for (const PlateSample& p : samples) {
      sum += p.weight;
      bilinear += p.weight * (p.r_B.x() + s.hx) * (p.r_B.y() + s.hy) / (4 * s.hx * s.hy);
      xy += p.weight * p.r_B.x() * p.r_B.y();
      EXPECT_LE(std::abs(p.r_B.x()), s.hx + 1e-18);
      EXPECT_LE(std::abs(p.r_B.y()), s.hy + 1e-18);
    }
    EXPECT_NEAR(sum, 1, 1e-15) << n;
    EXPECT_NEAR(bilinear, 0.25, 1e-15) << n;
    EXPECT_NEAR(xy, 0, 1e-20) << n;
  }
}

TEST(RoundedPlate, TheSmallerPlateCarriesThePairAndEqualPlatesShareIt) {
  const Rect big(0.05, 0.05, 5e-5), small(0.01, 0.02, 5e-5), turned(0.02, 0.01, 1e-4);
  const DirectionShares d1 = direction_shares(small.shape, big.shape);
  EXPECT_EQ(d1.a_on_b, 1.0);
  EXPECT_EQ(d1.b_on_a, 0.0);
  const DirectionShares d2 = direction_shares(big.shape, small.shape);
  EXPECT_EQ(d2.a_on_b, 0.0);
  EXPECT_EQ(d2.b_on_a, 1.0);
  const DirectionShares d3 = direction_shares(small.shape, turned.shape);
  EXPECT_EQ(d3.a_on_b, 0.5);
  EXPECT_EQ(d3.b_on_a, 0.5);
}

TEST(ContactBroadphase, GridFindsExactlyTheOverlappingBoxes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(0, 0.2), ang(-kPi, kPi);
  std::vector<Aabb> boxes;
  for (int i = 0; i < 400; ++i) {
    const Mat3 R = Eigen::AngleAxisd(ang(rng), Vec3(ang(rng), ang(rng), ang(rng)).normalized())
                       .toRotationMatrix();
    boxes.push_back(
        plate_aabb(Vec3(pos(rng), pos(rng), 0.1 * pos(rng)), R, box(Vec3(0.01, 0.02, 1e-4)), 0));
  }
  // A clamped plate much larger than the rest, and a few mid-sized ones.
  boxes.push_back(plate_aabb(Vec3(0.1, 0.1, 0), Mat3::Identity(), box(Vec3(0.3, 0.25, 1e-4)), 0));
  for (int i = 0; i < 5; ++i)
    boxes.push_back(plate_aabb(Vec3(pos(rng), pos(rng), 0.01), rot_z(ang(rng)),
                               box(Vec3(0.08, 0.04, 1e-4)), 0));
  const int n = static_cast<int>(boxes.size());
  std::vector<std::pair<int, int>> brute;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      bool overlap = true;
      for (int k = 0; k < 3; ++k)
        overlap = overlap && boxes[i].lo[k] <= boxes[j].hi[k] && boxes[j].lo[k] <= boxes[i].hi[k];
      if (overlap) brute.emplace_back(i, j);
    }
  BroadPhase sap;
  const auto found = sap.find_pairs(boxes);
  EXPECT_GT(brute.size(), 50u);
  EXPECT_EQ(found, brute);
}

TEST(ContactLaws, StepAndFrictionCoefficientMatchTheirDefinitions) {
  EXPECT_DOUBLE_EQ(step3(-1.0, 0, 2, 1, 5), 2.0);
  EXPECT_DOUBLE_EQ(step3(2.0, 0, 2, 1, 5), 5.0);
  EXPECT_DOUBLE_EQ(step3(0.5, 0, 2, 1, 5), 3.5);
  EXPECT_NEAR(step3(0.25, 0, 0, 1, 1), 0.25 * 0.25 * (3 - 0.5), 1e-15);
  ContactDef c;
  c.mu_static = 0.5;
  c.mu_dynamic = 0.3;
  c.stiction_speed = 1e-3;
  c.friction_speed = 3e-3;
  EXPECT_DOUBLE_EQ(friction_coefficient(c, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(friction_coefficient(c, 1e-3), 0.5);
  EXPECT_DOUBLE_EQ(friction_coefficient(c, 2e-3), 0.4);
  EXPECT_DOUBLE_EQ(friction_coefficient(c, 1.0), 0.3);
  // Odd cubic through 0: mu(v_s / 2) = mu_s * s^2 (3 - 2 s) * 2 - mu_s with s = 3/4.
  EXPECT_NEAR(friction_coefficient(c, 0.5e-3), 0.5 * (2 * 0.5625 * 1.5 - 1), 1e-15);
  // The force law is continuous through its small-speed branch.
  const Vec3 slow(1e-7, 0, 0), slower(0.99e-7, 0, 0);
  const double f1 = continuous_friction(c, 2.0, slow).x();
  const double f2 = continuous_friction(c, 2.0, Vec3(1.001e-6, 0, 0)).x();
  EXPECT_NEAR(f1, -2.0 * friction_coefficient(c, 1e-7), 1e-12);
  EXPECT_NEAR(f2, -2.0 * friction_coefficient(c, 1.001e-6), 1e-12);
  EXPECT_NEAR(continuous_friction(c, 2.0, slower).x(), -2.0 * friction_coefficient(c, 0.99e-7),
              1e-12);
}

// The continuous law with its falling branch taken at a lagged speed (the slip speed of the
// last accepted step): at its own speed it is Adams' law (mu = rising x weakening, since a
// STEP is affine in its end values); at a fixed lag the force never falls as the speed grows
// (no negative damping), where Adams' law falls by mu_s - mu_d over [v_s, v_d]; and its
// closed-form slope is the derivative of the force.
TEST(ContactLaws, LaggedFallingBranchIsTheLawAtItsOwnSpeedAndNeverFalls) {
  ContactDef c;
  c.mu_static = 0.5;
  c.mu_dynamic = 0.3;
  c.stiction_speed = 1e-3;
  c.friction_speed = 3e-3;
  const double fn = 2.0;
  const Vec3 dir = Vec3(3, -4, 0) / 5;
  for (double v = 0; v <= 5e-3; v += 1e-4) {
    const Vec3 v_t = v * dir;
    EXPECT_NEAR(continuous_friction(c, fn, v_t, v).norm(), continuous_friction(c, fn, v_t).norm(),
                1e-14)
        << v;
  }
  EXPECT_LT(continuous_friction(c, fn, Vec3(2.5e-3, 0, 0)).norm(),
            continuous_friction(c, fn, Vec3(1.5e-3, 0, 0)).norm());  // the branch falls
  for (const double lag : {0.0, 0.5e-3, 1.5e-3, 2e-3, 4e-3}) {
    double previous = 0;
    for (double v = 0; v <= 5e-3; v += 1e-4) {
      const double f = continuous_friction(c, fn, Vec3(v * dir), lag).norm();
      EXPECT_GE(f, previous - 1e-15) << lag << " " << v;
      previous = f;
    }
    // Slopes against central differences, on both sides of v_s and off the axis.
    for (const double v : {0.3e-3, 0.9e-3, 1.2e-3, 2.5e-3}) {
      const Vec3 v_t = v * dir + Vec3(0, 0, 0.1e-3);
      const FrictionSlopes sl = continuous_friction_slopes(c, fn, v_t, lag);
      EXPECT_LT((sl.f - continuous_friction(c, fn, v_t, lag)).norm(), 1e-15);
      const double h = 1e-9;
      for (int k = 0; k < 3; ++k) {
        const Vec3 e = h * Vec3::Unit(k);
        const Vec3 col = (continuous_friction(c, fn, Vec3(v_t + e), lag) -
                          continuous_friction(c, fn, Vec3(v_t - e), lag)) /
                         (2 * h);
        EXPECT_LT((sl.d_vt.col(k) - col).norm(), 1e-6 * sl.d_vt.norm()) << lag << " " << v;
      }
      const Vec3 d_fn = (continuous_friction(c, fn + 1e-6, v_t, lag) -
                         continuous_friction(c, fn - 1e-6, v_t, lag)) /
                        2e-6;
      EXPECT_LT((sl.d_fn - d_fn).norm(), 1e-8) << lag << " " << v;
    }
  }
}

TEST(ContactLaws, NormalForceIsImpactAndNeverAttractive) {
  ContactDef c;
  c.stiffness = 2e5;
  c.exponent = 1.5;
  c.damping = 3.0;
  c.damping_depth = 1e-5;
  const double d = 4e-6;
  const double s = 0.4, step = s * s * (3 - 2 * s);
  EXPECT_NEAR(normal_force(c, d, 0.01, 0), 2e5 * std::pow(d, 1.5) + 3.0 * step * 0.01, 1e-15);
  EXPECT_NEAR(normal_force(c, 2e-5, 0.01, 0), 2e5 * std::pow(2e-5, 1.5) + 0.03, 1e-15);
  EXPECT_EQ(normal_force(c, d, -10.0, 0), 0.0);  // fast separation: no pull
  EXPECT_EQ(normal_force(c, -1e-6, 1.0, 0), 0.0);
  c.damping_law = ContactDamping::HuntCrossley;
  c.restitution = 0.6;
  EXPECT_NEAR(normal_force(c, d, 0.1, 0.5), 2e5 * std::pow(d, 1.5) * (1 + 1.5 * 0.4 * 0.1 / 0.5),
              1e-15);
  c.damping_law = ContactDamping::LankaraniNikravesh;
  EXPECT_NEAR(normal_force(c, d, 0.1, 0.5),
              2e5 * std::pow(d, 1.5) * (1 + 0.75 * (1 - 0.36) * 0.1 / 0.5), 1e-15);
  c.damping_law = ContactDamping::Flores;
  EXPECT_NEAR(normal_force(c, d, 0.1, 0.5),
              2e5 * std::pow(d, 1.5) * (1 + 8 * 0.4 / (5 * 0.6) * 0.1 / 0.5), 1e-15);
}

TEST(ContactLaws, SuggestionCarriesTheChosenMultipleOfTheWeight) {
  const double m = 1.6e-5, g = 9.81, depth = 1e-5;
  const ContactSuggestion s = suggest_contact(m, g, depth, 1.5, 100, 1.0);
  EXPECT_NEAR(s.stiffness * std::pow(depth, 1.5), 100 * m * g, 1e-15);
  const double k_lin = 1.5 * 100 * m * g / depth;
  EXPECT_NEAR(s.damping, 2 * std::sqrt(k_lin * m), 1e-15);
  EXPECT_NEAR(s.period, 2 * kPi / std::sqrt(k_lin / m), 1e-15);
  EXPECT_THROW(suggest_contact(-1, g, depth), InputError);
  EXPECT_THROW(suggest_contact(m, g, 0), InputError);
  EXPECT_THROW(suggest_contact(m, g, depth, 0.5), InputError);
}

// A small model with two free plates (and optionally a fixed one), dofs set by hand.
struct TwoPlates {
  Model model;
  State state;
  explicit TwoPlates(FrictionModel friction) {
    for (int i = 0; i < 2; ++i) {
      BodyDef b;
      b.name = fmt::format("p{}", i);
      b.mass = 1e-3;
      set_box(b, Vec3(0.02 + 0.01 * i, 0.01, 2e-4), b.mass);
      b.J_B = Mat3::Identity() * 1e-8;
      model.bodies.push_back(b);
    }
    model.dof_of_body = {0, 6};
    model.num_dofs = 12;
    ContactDef& c = model.contact;
    c.enabled = true;
    c.stiffness = 1e6;
    c.exponent = 1.5;
    c.damping = 5;
    c.damping_depth = 5e-5;
    c.friction = friction;
    c.mu_static = 0.5;
    c.mu_dynamic = 0.4;
    c.stiction_speed = 1e-3;
    c.friction_speed = 5e-3;
    c.tangential_stiffness = 300;
    c.tangential_damping = 0.1;
    state.p_W = {Vec3(0, 0, 0), Vec3(0.002, 0.001, 1.9e-4)};
    state.R_WB = {
        Mat3::Identity(),
        Eigen::AngleAxisd(0.01, Vec3(0.3, 1, 0.2).normalized()).toRotationMatrix() * rot_z(0.3)};
    state.v_W = {Vec3(0.001, -0.002, 0.01), Vec3(-0.003, 0.0005, -0.02)};
    state.w_W = {Vec3(0.1, -0.2, 0.3), Vec3(0.05, 0.1, -0.2)};
    state.drive_s = {};
  }
};

Eigen::VectorXd contact_gforce(const Model& m, const State& s) {
  BodyForces f;
  f.f_W.assign(m.bodies.size(), Vec3::Zero());
  f.tau_W.assign(m.bodies.size(), Vec3::Zero());
  Assembler as(m, s, f, nullptr);
  add_contact_forces(m, s, as);
  Eigen::VectorXd g(m.num_dofs);
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    if (m.dof_of_body[i] < 0) continue;
    g.segment<3>(m.dof_of_body[i]) = f.f_W[i];
    g.segment<3>(m.dof_of_body[i] + 3) = f.tau_W[i];
  }
  return g;
}

// The contact Jacobian of the two plates against central differences of their forces.
void expect_jacobian_matches_differences(const TwoPlates& tp) {
  const ContactSummary sum = contact_summary(tp.model, tp.state);
  ASSERT_GE(sum.active, 1);
  BodyForces f;
  f.f_W.assign(2, Vec3::Zero());
  f.tau_W.assign(2, Vec3::Zero());
  ForceJacobian jac;
  Assembler as(tp.model, tp.state, f, &jac);
  add_contact_forces(tp.model, tp.state, as);
  Eigen::SparseMatrix<double> dq, dv;
  jac.dq_blocks.to_sparse(12, dq);
  jac.dv_blocks.to_sparse(12, dv);
  const Eigen::MatrixXd Jq(dq), Jv(dv);
  const Eigen::VectorXd g0 = contact_gforce(tp.model, tp.state);
  EXPECT_GT(g0.norm(), 0);
  for (int col = 0; col < 12; ++col) {
    const int body = col / 6, c = col % 6;
    for (int which = 0; which < 2; ++which) {  // 0: pose, 1: velocity
      const double h = which == 0 ? 1e-9 : 1e-7;
      Eigen::VectorXd gp, gm;
      for (int sgn = -1; sgn <= 1; sgn += 2) {
        State s = tp.state;
        if (which == 0) {
          if (c < 3) {
            s.p_W[body][c] += sgn * h;
          } else {
            Vec3 dphi = Vec3::Zero();
            dphi[c - 3] = sgn * h;
            s.R_WB[body] = so3_exp<double>(dphi) * s.R_WB[body];
          }
        } else {
          (c < 3 ? s.v_W[body][c] : s.w_W[body][c - 3]) += sgn * h;
        }
        (sgn < 0 ? gm : gp) = contact_gforce(tp.model, s);
      }
      const Eigen::VectorXd fd = (gp - gm) / (2 * h);
      const Eigen::VectorXd ad = which == 0 ? Jq.col(col) : Jv.col(col);
      const double scale = std::max(1.0, fd.norm());
      EXPECT_LT((fd - ad).norm(), 1e-5 * scale)
          << "column " << col << (which == 0 ? " (pose)" : " (velocity)") << "\nfd "
          << fd.transpose() << "\nad " << ad.transpose();
    }
  }
}

void check_jacobian(FrictionModel friction, bool with_anchor) {
  TwoPlates tp(friction);
  if (with_anchor) {
    commit_contact_history(tp.model, tp.state);
    ASSERT_FALSE(tp.state.contact.anchors.empty());
    tp.state.p_W[1] += Vec3(2e-5, -1e-5, 0);  // load the anchor springs
  }
  expect_jacobian_matches_differences(tp);
}

TEST(ContactJacobian, MatchesCentralDifferencesFrictionless) {
  check_jacobian(FrictionModel::None, false);
}
TEST(ContactJacobian, MatchesCentralDifferencesContinuousFriction) {
  check_jacobian(FrictionModel::Continuous, false);
}
TEST(ContactJacobian, MatchesCentralDifferencesAnchorFriction) {
  check_jacobian(FrictionModel::Anchor, true);
}

// The smaller plate's edge, 3e-5 m inside the larger plate's edge, committed touching from
// above and then sunk 3e-5 m below the larger plate's mid-plane; then drawn 6e-5 m back (3e-5
// m beside the edge), 5e-5 m below and turned a little: its edge samples are sunk beside the
// polygon (collision/sunk_edge.hpp), deeper than the two half thicknesses, which only a sunk
// point can be.
TEST(ContactJacobian, MatchesCentralDifferencesSunkBesideAnEdge) {
  TwoPlates tp(FrictionModel::Continuous);
  const double reach = 2e-4;  // the plates' half thicknesses summed
  tp.state.p_W = {Vec3(0, 0, 1.5e-4), Vec3(0.01 + 0.015 - 3e-5, 0, 0)};
  tp.state.R_WB = {Mat3::Identity(), Mat3::Identity()};
  commit_contact_history(tp.model, tp.state);
  ASSERT_FALSE(tp.state.contact.anchors.empty());
  tp.state.p_W[0].z() = -3e-5;
  commit_contact_history(tp.model, tp.state);
  ASSERT_FALSE(tp.state.contact.anchors.empty());
  tp.state.p_W[0] = Vec3(-6e-5, 0, -5e-5);
  tp.state.R_WB = {Eigen::AngleAxisd(2e-3, Vec3(0.3, 1, 0.2).normalized()).toRotationMatrix(),
                   Eigen::AngleAxisd(1e-3, Vec3(1, -0.4, 0.5).normalized()).toRotationMatrix()};
  const ContactSummary sum = contact_summary(tp.model, tp.state);
  ASSERT_GE(sum.active, 1);
  EXPECT_GT(sum.max_penetration, reach);
  expect_jacobian_matches_differences(tp);
}

TEST(ContactForces, ForcesBalanceAndPushThePlatesApart) {
  TwoPlates tp(FrictionModel::Continuous);
  BodyForces f;
  f.f_W.assign(2, Vec3::Zero());
  f.tau_W.assign(2, Vec3::Zero());
  Assembler as(tp.model, tp.state, f, nullptr);
  add_contact_forces(tp.model, tp.state, as);
  EXPECT_NEAR((f.f_W[0] + f.f_W[1]).norm(), 0, 1e-12 * f.f_W[0].norm());
  // Angular momentum: total moment about the origin vanishes.
  const Vec3 m =
      f.tau_W[0] + tp.state.p_W[0].cross(f.f_W[0]) + f.tau_W[1] + tp.state.p_W[1].cross(f.f_W[1]);
  EXPECT_LT(m.norm(), 1e-12 * f.f_W[0].norm());
  EXPECT_GT(f.f_W[1].z(), 0);  // upper plate pushed up
  // The per-pair report carries the same resultant.
  const ContactSummary sum = contact_summary(tp.model, tp.state);
  ASSERT_EQ(sum.pairs.size(), 1u);
  EXPECT_EQ(sum.pairs[0].a, 0);
  EXPECT_EQ(sum.pairs[0].b, 1);
  EXPECT_EQ(sum.pairs[0].points, sum.active);
  EXPECT_LT((sum.pairs[0].f_b_W - f.f_W[1]).norm(), 1e-12 * f.f_W[1].norm());
}

// Chain of 2 x 3 segments cut from one sheet, joined by force elements, panel 0 and 1
// folded flat onto each other across the crease between columns 0 and 1... (hand-built).
Model folded_strip(double gap) {
  Model m;
  const double L = 0.01, W = 0.01, t = 1e-4;
  // Panel 0: segments 0..3 along +x at z = 0, s from 0 to 4L. Panel 1: segments 4..7 folded
  // back over it at height gap, s from 4L to 8L (segment 4 next to the crease at x = 4L).
  for (int i = 0; i < 8; ++i) {
    BodyDef b;
    b.name = fmt::format("s{}", i);
    b.mass = 1e-4;
    set_box(b, Vec3(L, W, t), b.mass);
    b.J_B = Mat3::Identity() * 1e-9;
    b.panel = i < 4 ? 0 : 1;
    b.centroid_M = Vec2((i + 0.5) * L, 0.5 * W);
    if (i < 4) {
      b.p0_W = Vec3((i + 0.5) * L, 0, 0);
    } else {
      b.p0_W = Vec3((7 - i + 0.5) * L, 0, gap);
      b.R0_WB = Eigen::AngleAxisd(kPi, Vec3::UnitY()).toRotationMatrix();
    }
    m.bodies.push_back(b);
  }
  for (int i = 0; i < 7; ++i) {
    ElementDef e;
    e.inner = i + 1;
    e.outer = i;
    m.elements.push_back(e);
  }
  m.contact.enabled = true;
  m.contact.stiffness = 1e5;
  m.contact.exponent = 1.5;
  m.contact.damping_depth = 1e-5;
  return m;
}

TEST(ContactRules, FoldedPanelsTouchButJoinedAndSameSheetNeighboursDoNot) {
  Model m = folded_strip(0.9e-4);
  m.dof_of_body.assign(8, -1);
  for (int i = 0; i < 8; ++i) m.dof_of_body[i] = 6 * i;
  State s;
  for (const BodyDef& b : m.bodies) {
    s.p_W.push_back(b.p0_W);
    s.R_WB.push_back(b.R0_WB);
    s.v_W.push_back(Vec3::Zero());
    s.w_W.push_back(Vec3::Zero());
  }
  const ContactSummary sum = contact_summary(m, s);
  // Facing pairs across the fold: (0,7), (1,6), (2,5), (3,4); (3,4) are joined and share the
  // crease edge, so only three facing pairs touch, with all 9 samples of both equal plates.
  // Pairs offset by one segment, (0,6), (1,7), (1,5), (2,6), (2,4), (3,5), touch along the
  // seam above the shared edge line (3 samples of each plate). Coplanar neighbours in a
  // panel never touch.
  ASSERT_EQ(m.contact.samples_per_edge, 3);
  EXPECT_EQ(sum.active, 3 * 18 + 6 * 6);
  EXPECT_EQ(sum.pairs.size(), 9u);
  EXPECT_NEAR(sum.max_penetration, 1e-5, 1e-12);
  for (const Vec3& p : sum.points_W) EXPECT_LT(p.x(), 3 * 0.01 + 1e-9);
}

}  // namespace contact_geometry_test
}  // namespace finseg

namespace finseg {
namespace contact_geometry_test {

// The paper's zigzag in its initial state (80 deg, panels 20 deg apart at the creases), one
// and two segments across: no false contact anywhere, although neighbouring segments share
// edges and corners, also across the creases.
TEST(ContactRules, GeneratedZigzagHasNoFalseContact) {
  for (int across : {1, 2}) {
    ZigzagSpec spec;
    spec.segments_across = across;
    Model m = build_zigzag_model(spec);
    m.contact.enabled = true;
    m.contact.stiffness = 3e7;
    const State s = initial_state(m);
    EXPECT_EQ(contact_summary(m, s).active, 0) << across << " across";
    // Folded much further (panels 2 deg apart) the faces near the creases do touch.
    spec.fold_angle = 89.9 * kDegToRad;
    Model tight = build_zigzag_model(spec);
    tight.contact = m.contact;
    const ContactSummary c = contact_summary(tight, initial_state(tight));
    EXPECT_GT(c.active, 0) << across << " across";
  }
}

}  // namespace contact_geometry_test
}  // namespace finseg

namespace finseg {
namespace contact_geometry_test {

// A plate tilted by 45 deg whose lowest edge hangs a height h above the middle of a flat
// plate: the narrow phase counts it in contact where h < r_a + r_b (depth r_a + r_b - h), so
// the broad phase must pair the two although their thickness boxes do not overlap for h above
// r + r cos 45 deg (the corner would otherwise enter the contact already that deep).
TEST(ContactBroadphase, TiltedCornerEntersTheContactWithZeroDepth) {
  const double L = 0.01, t = 1e-4, reach = t;
  const Mat3 R = Eigen::AngleAxisd(kPi / 4, Vec3::UnitY()).toRotationMatrix();
  Model m;
  for (int i = 0; i < 2; ++i) {
    BodyDef b;
    b.name = fmt::format("p{}", i);
    b.mass = 1e-4;
    set_box(b, Vec3(L, L, t), b.mass);
    b.J_B = Mat3::Identity() * 1e-9;
    m.bodies.push_back(b);
  }
  m.contact.enabled = true;
  m.contact.stiffness = 1e5;
  m.contact.exponent = 1.5;
  m.contact.damping_depth = 1e-5;
  for (const double h : {0.95 * reach, 0.8 * reach, 1.05 * reach}) {
    State s;
    // Lowest edge of the tilted plate (its body x = +L/2 edge) at height h over the origin.
    const Vec3 low_edge_B(0.5 * L, 0, 0);
    s.p_W = {Vec3::Zero(), Vec3(0, 0, h) - R * low_edge_B};
    s.R_WB = {Mat3::Identity(), R};
    s.v_W.assign(2, Vec3::Zero());
    s.w_W.assign(2, Vec3::Zero());
    const ContactSummary c = contact_summary(m, s);
    if (h < reach) {
      ASSERT_GT(c.active, 0) << "h = " << h;
      EXPECT_NEAR(c.max_penetration, reach - h, 1e-12) << "h = " << h;
    } else {
      EXPECT_EQ(c.active, 0) << "h = " << h;
    }
  }
}

}  // namespace contact_geometry_test
}  // namespace finseg
