// Closed-form contact Jacobian (collision/contact_jacobian.*) against its oracle, the
// automatic differentiation of the same kernel (issue 12 item 3: agreement to 1e-10
// relative), for every friction model and damping law, over the face, beside edges and
// corners (also sunk past the mid-plane), for triangles, in and beyond the damping blend zone,
// with sliding and sticking anchors, and with one plate clamped.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "collision/contact_forces.hpp"
#include "collision/narrowphase.hpp"
#include "elements/assembler.hpp"

namespace finseg {
namespace contact_jacobian_test {

Mat3 turn(double angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// Two plates: a (smaller, sampled on b unless equal) and b, with contact on.
struct Plates {
  Model model;
  State state;
  Plates(const Outline& outline_a, const Outline& outline_b, ContactDamping law,
         FrictionModel friction) {
    for (int i = 0; i < 2; ++i) {
      BodyDef b;
      b.name = fmt::format("p{}", i);
      set_prism(b, i == 0 ? outline_a : outline_b, 2e-4, 1e-3);
      model.bodies.push_back(b);
    }
    model.dof_of_body = {0, 6};
    model.num_dofs = 12;
    ContactDef& c = model.contact;
    c.enabled = true;
    c.stiffness = 1e6;
    c.exponent = 1.5;
    c.damping = 5;
    c.damping_depth = 5e-5;  // the penetrations below (~1e-5) are in the blend zone
    c.damping_law = law;
    c.restitution = 0.6;
    c.friction = friction;
    c.mu_static = 0.5;
    c.mu_dynamic = 0.4;
    c.stiction_speed = 1e-3;
    c.friction_speed = 5e-3;
    c.tangential_stiffness = 300;
    c.tangential_damping = 0.1;
    state.p_W = {Vec3::Zero(), Vec3(0.001, 0.0005, 1.9e-4)};
    state.R_WB = {Mat3::Identity(), turn(0.01, Vec3(0.3, 1, 0.2)) * turn(0.3, Vec3::UnitZ())};
    state.v_W = {Vec3(0.001, -0.002, 0.01), Vec3(-0.003, 0.0005, -0.02)};
    state.w_W = {Vec3(0.1, -0.2, 0.3), Vec3(0.05, 0.1, -0.2)};
  }
};

Outline rectangle(double lx, double ly) {
  return rectangle_outline(lx, ly);
}

// Contact forces and Jacobian, closed form (autodiff false) or the oracle.
struct Evaluation {
  BodyForces forces;
  Eigen::MatrixXd dq, dv;
};
Evaluation evaluate(const Model& m, const State& s, bool autodiff, bool with_velocity) {
  Evaluation e;
  e.forces.f_W.assign(m.bodies.size(), Vec3::Zero());
  e.forces.tau_W.assign(m.bodies.size(), Vec3::Zero());
  ForceJacobian jac;
  jac.autodiff = autodiff;
  jac.with_velocity = with_velocity;
  Assembler as(m, s, e.forces, &jac);
  add_contact_forces(m, s, as);
  Eigen::SparseMatrix<double> dq, dv;
  jac.dq_blocks.to_sparse(m.num_dofs, dq);
  e.dq = dq;
  if (with_velocity) {
    jac.dv_blocks.to_sparse(m.num_dofs, dv);
    e.dv = dv;
  }
  return e;
}

// Largest entry of |closed - oracle| relative to the oracle's largest entry (0 when both
// vanish).
double relative_gap(const Eigen::MatrixXd& closed, const Eigen::MatrixXd& oracle) {
  const double scale = oracle.cwiseAbs().maxCoeff();
  const double gap = (closed - oracle).cwiseAbs().maxCoeff();
  return scale > 0 ? gap / scale : gap;
}

// Closed form against the oracle with and without velocity columns; the forces agree too.
void expect_matches_oracle(const Model& m, const State& s) {
  const ContactSummary sum = contact_summary(m, s);
  ASSERT_GE(sum.active, 1) << "no contact: the case tests nothing";
  for (const bool with_velocity : {true, false}) {
    SCOPED_TRACE(with_velocity ? "with velocity" : "poses only");
    const Evaluation closed = evaluate(m, s, false, with_velocity);
    const Evaluation oracle = evaluate(m, s, true, with_velocity);
    ASSERT_GT(oracle.dq.cwiseAbs().maxCoeff(), 0);
    EXPECT_LE(relative_gap(closed.dq, oracle.dq), 1e-10) << "dq\nclosed\n"
                                                         << closed.dq << "\noracle\n"
                                                         << oracle.dq;
    if (with_velocity) {
      EXPECT_LE(relative_gap(closed.dv, oracle.dv), 1e-10) << "dv\nclosed\n"
                                                           << closed.dv << "\noracle\n"
                                                           << oracle.dv;
    }
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      const double f = oracle.forces.f_W[i].norm(), t = oracle.forces.tau_W[i].norm();
      EXPECT_LE((closed.forces.f_W[i] - oracle.forces.f_W[i]).norm(), 1e-14 * f);
      EXPECT_LE((closed.forces.tau_W[i] - oracle.forces.tau_W[i]).norm(), 1e-14 * t + 1e-300);
    }
  }
}

constexpr ContactDamping kLaws[] = {ContactDamping::Impact, ContactDamping::HuntCrossley,
                                    ContactDamping::LankaraniNikravesh, ContactDamping::Flores};
constexpr FrictionModel kFrictions[] = {FrictionModel::None, FrictionModel::Continuous,
                                        FrictionModel::Anchor};

std::string name(ContactDamping law, FrictionModel friction) {
  return fmt::format("law {} friction {}", static_cast<int>(law), static_cast<int>(friction));
}

// A smaller plate lying over the face of a larger one, tilted and sliding: every sample
// over the face (side-decided normal), all laws and frictions (anchors, where the model has
// them, committed and then loaded).
TEST(ContactJacobianClosedForm, FaceContactEveryLawAndFriction) {
  for (ContactDamping law : kLaws) {
    for (FrictionModel friction : kFrictions) {
      SCOPED_TRACE(name(law, friction));
      Plates p(rectangle(0.02, 0.01), rectangle(0.04, 0.03), law, friction);
      expect_matches_oracle(p.model, p.state);
      commit_contact_history(p.model, p.state);  // anchors, impact speeds of the laws
      p.state.p_W[1] += Vec3(2e-6, -1e-6, -1e-6);
      expect_matches_oracle(p.model, p.state);
    }
  }
}

// The smaller plate overhangs the larger one's edge and corner: samples beside an edge and
// beyond a vertex, where the normal turns round the rim.
TEST(ContactJacobianClosedForm, EdgeAndCornerContact) {
  for (ContactDamping law : {ContactDamping::Impact, ContactDamping::Flores}) {
    for (FrictionModel friction : kFrictions) {
      SCOPED_TRACE(name(law, friction));
      Plates p(rectangle(0.02, 0.01), rectangle(0.03, 0.02), law, friction);
      // a's corner sample (0.01, 0.005) lies 5e-5 beyond b's corner in x and y.
      p.state.p_W[1] = Vec3(0.01 - 0.015 - 5e-5, 0.005 - 0.01 - 5e-5, 1.8e-4);
      p.state.R_WB[1] = turn(2e-3, Vec3(1, -0.5, 0));
      const Vec3 corner_in_b =
          p.state.R_WB[1].transpose() * (Vec3(0.01, 0.005, 0) - p.state.p_W[1]);
      const PolygonFeature f =
          closest_feature(p.model.bodies[1].outline_B, corner_in_b.x(), corner_in_b.y());
      ASSERT_GE(f.vertex, 0) << "the corner sample is not beyond b's corner";
      expect_matches_oracle(p.model, p.state);
      commit_contact_history(p.model, p.state);
      p.state.p_W[1] += Vec3(-3e-6, 1e-6, -2e-6);
      expect_matches_oracle(p.model, p.state);
    }
  }
}

// a's edge sinks past b's mid-plane over b's face (committed there) and is then drawn back
// beside b's edge: samples sunk beside the polygon (collision/sunk_edge.hpp), their normal
// the gradient of the joining distance.
TEST(ContactJacobianClosedForm, SunkBesideAnEdge) {
  for (FrictionModel friction : kFrictions) {
    SCOPED_TRACE(name(ContactDamping::Impact, friction));
    Plates p(rectangle(0.02, 0.01), rectangle(0.03, 0.02), ContactDamping::Impact, friction);
    p.state.p_W = {Vec3(0, 0, 1.5e-4), Vec3(0.025 - 3e-5, 0, 0)};  // a's edge 3e-5 over b
    p.state.R_WB = {Mat3::Identity(), Mat3::Identity()};
    commit_contact_history(p.model, p.state);
    p.state.p_W[0].z() = -3e-5;  // sunk over the face
    commit_contact_history(p.model, p.state);
    p.state.p_W[0] = Vec3(-6e-5, 0, -5e-5);  // 3e-5 beside the edge, deeper
    p.state.R_WB = {turn(2e-3, Vec3(0.3, 1, 0.2)), Mat3::Identity()};
    ASSERT_GT(contact_summary(p.model, p.state).max_penetration, 2e-4) << "not sunk";
    expect_matches_oracle(p.model, p.state);
  }
}

// Equal plates share the pair: both directions sampled (points of b on a as well).
TEST(ContactJacobianClosedForm, EqualPlatesBothDirections) {
  for (FrictionModel friction : kFrictions) {
    SCOPED_TRACE(name(ContactDamping::HuntCrossley, friction));
    Plates p(rectangle(0.02, 0.01), rectangle(0.02, 0.01), ContactDamping::HuntCrossley, friction);
    p.state.p_W[1] = Vec3(0.004, 0.002, 1.85e-4);
    expect_matches_oracle(p.model, p.state);
  }
}

// Triangles (fanned samples, edges along no axis) on a pentagon.
TEST(ContactJacobianClosedForm, TriangleOnPentagon) {
  const Outline triangle = {Vec2(-0.006, -0.004), Vec2(0.007, -0.003), Vec2(-0.001, 0.007)};
  Outline pentagon;
  for (int k = 0; k < 5; ++k) {
    const double a = 2 * kPi * k / 5 + 0.2;
    pentagon.push_back(Vec2(0.009 * std::cos(a), 0.009 * std::sin(a)));
  }
  for (FrictionModel friction : kFrictions) {
    SCOPED_TRACE(name(ContactDamping::LankaraniNikravesh, friction));
    Plates p(triangle, pentagon, ContactDamping::LankaraniNikravesh, friction);
    p.state.p_W[1] = Vec3(0.003, -0.002, 1.85e-4);  // the triangle overhangs two sides
    expect_matches_oracle(p.model, p.state);
    commit_contact_history(p.model, p.state);
    p.state.p_W[1] += Vec3(1e-6, 2e-6, -1e-6);
    expect_matches_oracle(p.model, p.state);
  }
}

// Impact damping on either side of its blend depth d (STEP(delta, 0, 0, d, c_max)): inside
// the cubic, beyond it, and with the plates parting so fast that the damping cancels the
// force (F = 0, no slope).
TEST(ContactJacobianClosedForm, ImpactDampingBlendZone) {
  for (const double depth : {5e-5, 1.2e-5, 1e-6}) {
    SCOPED_TRACE(depth);
    Plates p(rectangle(0.02, 0.01), rectangle(0.04, 0.03), ContactDamping::Impact,
             FrictionModel::Continuous);
    p.model.contact.damping_depth = depth;
    p.state.R_WB[1] = turn(1e-3, Vec3(1, 1, 0));
    expect_matches_oracle(p.model, p.state);
  }
  Plates p(rectangle(0.02, 0.01), rectangle(0.04, 0.03), ContactDamping::Impact,
           FrictionModel::Continuous);
  p.state.R_WB[1] = turn(1e-3, Vec3(1, 1, 0));
  p.state.v_W[1] = Vec3(0, 0, 0.06);  // parting: the damping cancels some points' force
  p.state.w_W = {Vec3::Zero(), Vec3(0, 5, 0)};
  const ContactSummary sum = contact_summary(p.model, p.state);
  int without_force = 0;
  for (double f : sum.point_normal) without_force += f == 0;
  ASSERT_GT(without_force, 0);
  ASSERT_LT(without_force, sum.active);
  expect_matches_oracle(p.model, p.state);
}

// Continuous friction in each regime of mu(v): the series near v = 0 (v < 1e-3 v_s), the
// odd cubic up to v_s, the step down to mu_d, and mu_d beyond v_d.
TEST(ContactJacobianClosedForm, ContinuousFrictionEveryRegime) {
  for (const double slip : {3e-7, 5e-4, 2.5e-3, 2e-2}) {
    SCOPED_TRACE(slip);
    Plates p(rectangle(0.02, 0.01), rectangle(0.04, 0.03), ContactDamping::Flores,
             FrictionModel::Continuous);
    p.state.R_WB[1] = turn(1e-3, Vec3(1, 0, 0));
    p.state.v_W = {Vec3::Zero(), Vec3(0.6 * slip, -0.8 * slip, 0)};
    p.state.w_W = {Vec3::Zero(), Vec3::Zero()};
    expect_matches_oracle(p.model, p.state);
  }
}

// Anchors: sticking below the static limit, sticking with the spring capped, and sliding
// (the sum of spring and damper capped at mu_d F_n).
TEST(ContactJacobianClosedForm, AnchorsStickingCappedAndSliding) {
  for (const double shift : {1e-7, 1e-4}) {
    for (const bool sliding : {false, true}) {
      SCOPED_TRACE(fmt::format("shift {} sliding {}", shift, sliding));
      Plates p(rectangle(0.02, 0.01), rectangle(0.04, 0.03), ContactDamping::Impact,
               FrictionModel::Anchor);
      p.state.R_WB[1] = turn(1e-3, Vec3(1, 0, 0));
      p.state.v_W = p.state.w_W = {Vec3::Zero(), Vec3::Zero()};
      commit_contact_history(p.model, p.state);  // anchors at rest: springs unstretched
      ASSERT_FALSE(p.state.contact.anchors.empty());
      for (ContactAnchor& an : p.state.contact.anchors) an.sliding = sliding;
      p.state.p_W[1] += Vec3(shift, -0.5 * shift, 0);
      p.state.v_W[1] = Vec3(1e-3, 5e-4, -1e-3);  // damper and damping forces well below mu F_n
      p.state.w_W[1] = Vec3(0.02, -0.01, 0.03);
      // The large shift stretches every spring past its limit mu F_n (capped), the small
      // one leaves them below it.
      const ContactSummary sum = contact_summary(p.model, p.state);
      int at_limit = 0;
      for (int k = 0; k < sum.active; ++k) {
        at_limit +=
            sum.point_friction[k] >= 0.999 * p.model.contact.mu_dynamic * sum.point_normal[k];
      }
      EXPECT_EQ(at_limit, shift > 1e-5 ? sum.active : 0);
      expect_matches_oracle(p.model, p.state);
    }
  }
}

// One plate clamped: only the free plate's block.
TEST(ContactJacobianClosedForm, OnePlateClamped) {
  for (FrictionModel friction : kFrictions) {
    SCOPED_TRACE(name(ContactDamping::Impact, friction));
    Plates p(rectangle(0.02, 0.01), rectangle(0.04, 0.03), ContactDamping::Impact, friction);
    p.model.bodies[0].fixed = true;
    p.model.dof_of_body = {-1, 0};
    p.model.num_dofs = 6;
    expect_matches_oracle(p.model, p.state);
  }
}

}  // namespace contact_jacobian_test
}  // namespace finseg
