// Closed-form force-element Jacobians against their oracle, the automatic differentiation
// of the same kernel (issue 12 item 3: agreement to 1e-10 relative), and the closed form of
// the rotational springs' derivative against central differences.
#include <gtest/gtest.h>

#include <cmath>

#include "elements/assemble.hpp"
#include "elements/drive_gauge.hpp"
#include "elements/element_jacobian.hpp"
#include "generators/sheet.hpp"
#include "generators/zigzag.hpp"
#include "generators/zigzag_conditions.hpp"
#include "solvers/dofs.hpp"

namespace finseg {
namespace element_jacobian_test {

// Largest entry of |closed form - autodiff| relative to the largest entry of the oracle.
double relative_gap(const Eigen::SparseMatrix<double>& closed,
                    const Eigen::SparseMatrix<double>& oracle) {
  const Eigen::MatrixXd c = closed, o = oracle;
  return (c - o).cwiseAbs().maxCoeff() / o.cwiseAbs().maxCoeff();
}

void expect_closed_form_matches_autodiff(const Model& m, const State& st) {
  for (const bool with_velocity : {true, false}) {
    BodyForces f_closed, f_auto;
    ForceJacobian closed, oracle;
    closed.with_velocity = oracle.with_velocity = with_velocity;
    oracle.autodiff = true;
    compute_forces(m, st, f_closed, &closed);
    compute_forces(m, st, f_auto, &oracle);
    EXPECT_LE(relative_gap(closed.dq, oracle.dq), 1e-10) << "dq, velocity " << with_velocity;
    if (with_velocity) {
      EXPECT_LE(relative_gap(closed.dv, oracle.dv), 1e-10) << "dv";
    }
    // The same energy to round-off: the autodiff scalar's products may round differently in the
    // last bit (seen on the pattern path's side frames: 2e-16 of the total).
    EXPECT_NEAR(f_closed.potential_energy, f_auto.potential_energy,
                1e-14 * std::abs(f_closed.potential_energy));
  }
}

// Deforms and moves every free body: rotations of `amplitude` rad, translations of
// amplitude * 5 mm, velocities of order 0.1 m/s and 1 rad/s.
void perturb(const Model& m, State& st, double amplitude) {
  Eigen::VectorXd dq(m.num_dofs), v(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) {
    const double scale = (i % 6) < 3 ? 5e-3 : 1.0;
    dq[i] = amplitude * scale * std::sin(1.3 * i + 0.2);
    v[i] = 0.1 * std::cos(0.7 * i) * ((i % 6) < 3 ? 1.0 : 10.0);
  }
  apply_pose_increment(m, st, dq);
  set_velocity(m, st, v);
}

SheetSpec damped_plate() {
  SheetSpec s;
  s.length = 0.1;
  s.width = 0.04;
  s.thickness = 1e-4;
  s.youngs_modulus = 4e9;
  s.poisson_ratio = 0.3;
  s.density = 800;
  s.cells_along = 5;
  s.cells_across = 3;
  s.clamp_start = true;
  s.damping_time = 1e-3;
  return s;
}

TEST(ElementJacobian, SheetAgreesWithAutodiffFromFlatToLargeRotations) {
  const Model m = build_sheet_model(damped_plate());
  // 0: the flat state (theta = 0 exactly); 0.05 and 1.2 rad on either side of the switch
  // from the series of the left-Jacobian coefficients to their closed forms.
  for (const double amplitude : {0.0, 1e-4, 0.05, 0.4, 1.2}) {
    State st = initial_state(m);
    perturb(m, st, amplitude);
    SCOPED_TRACE(amplitude);
    expect_closed_form_matches_autodiff(m, st);
  }
}

TEST(ElementJacobian, FoldedStripWithMeasuredCreaseLawsAgreesWithAutodiff) {
  for (const int condition : {1, 3}) {
    ZigzagSpec spec = paper_condition(condition);
    spec.segments_per_panel = 3;
    spec.segments_across = 2;
    spec.damping_time = 1e-3;
    const Model m = build_zigzag_model(spec);
    for (const double amplitude : {0.0, 0.02, 0.3}) {
      State st = initial_state(m);
      perturb(m, st, amplitude);
      SCOPED_TRACE(condition);
      SCOPED_TRACE(amplitude);
      expect_closed_form_matches_autodiff(m, st);
    }
  }
}

// The drive's gauge (a spring and damper from a point off the centroid to the moving target,
// isotropic or softer across its direction), damped and moving, on the damped plate.
TEST(ElementJacobian, DriveGaugeAgreesWithAutodiff) {
  Model m = build_sheet_model(damped_plate());
  DriveDef d;
  d.name = "pull";
  d.body = static_cast<int>(m.bodies.size()) - 1;
  d.point_B = Vec3(4e-3, -3e-3, 1e-4);
  d.start_W = m.bodies[d.body].p0_W + m.bodies[d.body].R0_WB * d.point_B;
  d.direction_W = Vec3(0.6, 0, 0.8);
  d.stiffness = 200;
  d.damping = 0.7;
  d.speed = 0.05;
  d.travel = 0.02;
  m.drives.push_back(d);
  for (const double lateral : {1.0, 0.3, 0.0}) {
    m.drives[0].lateral_ratio = lateral;
    for (const double amplitude : {0.0, 0.05, 0.4}) {
      State st = initial_state(m);
      st.drive_s.assign(1, 4e-3);
      perturb(m, st, amplitude);
      SCOPED_TRACE(amplitude);
      SCOPED_TRACE(lateral);
      expect_closed_form_matches_autodiff(m, st);
    }
  }
  // A pull-only gauge (a string) taut (the target 4 mm ahead) and slack (4 mm behind: the
  // point ahead of it), with its lateral part.
  m.drives[0].pull_only = true;
  m.drives[0].lateral_ratio = 0.3;
  for (const double s : {4e-3, -4e-3}) {
    State st = initial_state(m);
    st.drive_s.assign(1, s);
    perturb(m, st, 0.05);
    SCOPED_TRACE(s);
    const double along = drive_force(m, st, 0).dot(m.drives[0].direction_W);
    if (s > 0) {
      EXPECT_GT(along, 0);
    } else {
      EXPECT_NEAR(along, 0, 1e-12);
    }
    expect_closed_form_matches_autodiff(m, st);
  }
  // The string with a toe band of 1 N: taut, in the toe on both sides of zero and slack; the
  // tension along the direction is max(0, u) outside the band and (u + b)^2 / (4 b) in it, u
  // the two-way gauge's pull -k n.(x - X) - c n.(v - V).
  DriveDef& g = m.drives[0];
  g.toe_force = 1.0;
  int in_toe = 0;
  for (const double s : {8e-3, 3e-3, 1e-3, -1e-3, -3e-3, -8e-3}) {
    State st = initial_state(m);
    st.drive_s.assign(1, s);
    perturb(m, st, 0.05);
    SCOPED_TRACE(s);
    const Vec3 r = st.R_WB[g.body] * g.point_B;
    const Vec3 x = st.p_W[g.body] + r, v = st.v_W[g.body] + st.w_W[g.body].cross(r);
    const Vec3& n = g.direction_W;
    const double u =
        -g.stiffness * n.dot(x - g.start_W - s * n) - g.damping * n.dot(v - g.speed * n);
    const double b = g.toe_force;
    const double tension = u >= b ? u : u <= -b ? 0.0 : (u + b) * (u + b) / (4 * b);
    EXPECT_NEAR(drive_force(m, st, 0).dot(n), tension, 1e-12);
    expect_closed_form_matches_autodiff(m, st);
    in_toe += std::abs(u) < b;
  }
  EXPECT_EQ(in_toe, 4);  // the cases cover the band on both sides and both outsides
}

TEST(ElementJacobian, RotationalSpringDerivativeMatchesCentralDifferences) {
  const Vec3 k(0.7, 0.2, 1.3);
  const auto g = [&](const Vec3& th) {
    return Vec3(so3_left_jacobian_inv<double>(th).transpose() * k.cwiseProduct(th));
  };
  for (const double t : {1e-6, 0.05, 0.29, 0.31, 1.0, 2.5, 3.0}) {
    const Vec3 th = t * Vec3(0.48, -0.6, 0.64);  // unit direction
    const Mat3 G = rotational_spring_derivative(th, k);
    const double h = 1e-6;
    for (int c = 0; c < 3; ++c) {
      const Vec3 fd = (g(th + h * Vec3::Unit(c)) - g(th - h * Vec3::Unit(c))) / (2 * h);
      EXPECT_LE((fd - G.col(c)).norm(), 1e-8 * G.norm()) << "t " << t << " column " << c;
    }
  }
}

}  // namespace element_jacobian_test
}  // namespace finseg
