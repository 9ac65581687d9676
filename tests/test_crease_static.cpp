// Crease laws in static equilibrium: the flap test (F L = M(theta), paper eq. 20) with a
// measured law, and two rigid panels pulled open by their ends (closed form).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/so3.hpp"
#include "elements/assemble.hpp"
#include "elements/bushing.hpp"
#include "elements/crease_law.hpp"
#include "elements/crease_laws/measured.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace {

Mat3 rot_y(double a) {
  return so3_exp<double>(Vec3(0, a, 0));
}

BodyDef plate(const std::string& name, double a) {
  BodyDef b;
  b.name = name;
  b.size = Vec3(a, 0.04, 1e-4);
  b.mass = 1e-3;
  b.J_B = box_inertia(b.mass, b.size);
  return b;
}

// Measured curve: a cubic in the opening angle (deg), increasing over 10..170 deg.
double M_ref(double deg) {
  const double u = deg / 100;
  return 2e-4 + 1.5e-3 * u - 4e-4 * u * u + 2.5e-4 * u * u * u;
}

TEST(CreaseStatic, FlapTestBalancesForceTimesLever) {
  CreaseData d;
  d.source = "flap";
  CreaseCurve c;
  for (double deg : {10.0, 40.0, 75.0, 110.0, 140.0, 170.0}) {
    c.angle_deg.push_back(deg);
    c.moment.push_back(M_ref(deg));
  }
  d.curves = {c};
  const auto law = std::make_shared<MeasuredCreaseLaw>(d, MeasuredLawOptions{});

  const double a = 0.05, lever = 0.04;
  // Start unloaded at rest: the zero of the measured curve (its linear continuation
  // below 10 deg, about -14 deg opening, i.e. folded a little past flat shut).
  const double fold0 = law->rest_angle(ElementHistory{}, 0);
  for (double F : {0.01, 0.03, 0.06}) {
    Model m;
    m.bodies = {plate("fixed", a), plate("flap", a)};
    m.bodies[0].p0_W = Vec3(-a / 2, 0, 0);
    m.bodies[0].fixed = true;
    m.bodies[1].R0_WB = rot_y(fold0);
    m.bodies[1].p0_W = rot_y(fold0) * Vec3(a / 2, 0, 0);
    ElementDef e;
    e.outer = 0;
    e.inner = 1;
    e.c_outer_B = Vec3(a / 2, 0, 0);
    e.c_inner_B = Vec3(-a / 2, 0, 0);
    e.K << 1e5, 1e5, 1e5, 50, 0, 50;  // very stiff except about the crease line
    e.crease = 0;
    m.elements.push_back(e);
    m.creases.push_back({law, fold0});
    // Pull perpendicular to the flap, outward (opening), at lever L from the crease line:
    // a follower force along the flap's +z at x_B = L - a/2.
    m.loads.push_back({1, Vec3(lever - a / 2, 0, 0), Vec3(0, 0, F), Vec3::Zero(), true});
    m.finalize_dofs();
    State st = initial_state(m);
    SolverSettings set;
    set.kind = SolverKind::Static;
    set.load_steps = 20;
    const SolverStats stats = run_solver(m, st, set, [](const State&, const BodyForces&) {});
    ASSERT_EQ(stats.status, "ok") << stats.message;
    const double alpha = fold_angle<double>(st.R_WB[1], st.R_WB[0], st.history[0].fold_angle);
    const double theta_deg = (kPi - alpha) / kDegToRad;
    EXPECT_GT(theta_deg, 10.0);  // inside the measured range
    EXPECT_LT(theta_deg, 170.0);
    EXPECT_NEAR(F * lever / M_ref(theta_deg), 1.0, 1e-6) << "F " << F << " theta " << theta_deg;
    std::printf("flap test: F = %.3f N, theta = %.3f deg, F L / M(theta) - 1 = %.2e\n", F,
                theta_deg, F * lever / M_ref(theta_deg) - 1);
  }
}

// Two rigid panels of length a joined by a linear crease (stiffness k, rest fold angle
// 2 psi0); one free end pinned, the other pulled along the line joining the ends. Virtual
// work on U = k/2 (2 psi - 2 psi0)^2 with end distance d = 2 a cos psi gives
//   F = 2 k (psi0 - psi) / (a sin psi).
TEST(CreaseStatic, TwoPanelsPulledOpenFollowClosedForm) {
  const double a = 0.06, k = 0.01, psi0 = 60 * kDegToRad, psi_end = 4 * kDegToRad;
  Model m;
  m.bodies = {plate("ground", 0.01), plate("panel1", a), plate("panel2", a)};
  m.bodies[0].fixed = true;
  m.bodies[1].R0_WB = rot_y(-psi0);  // x axis at psi0 above the pulling line
  m.bodies[1].p0_W = rot_y(-psi0) * Vec3(a / 2, 0, 0);
  m.bodies[2].R0_WB = rot_y(psi0);
  m.bodies[2].p0_W = rot_y(-psi0) * Vec3(a, 0, 0) + rot_y(psi0) * Vec3(a / 2, 0, 0);
  ElementDef pin;  // ground - panel 1 at the origin: rotation about y free
  pin.outer = 0;
  pin.inner = 1;
  pin.c_outer_B = Vec3::Zero();
  pin.c_inner_B = Vec3(-a / 2, 0, 0);
  pin.R_inner_E = rot_y(psi0);  // E coincides with F (= world) initially
  pin.K << 1e6, 1e6, 1e6, 1e3, 0, 1e3;
  pin.name = "pin";
  ElementDef crease;
  crease.outer = 1;
  crease.inner = 2;
  crease.c_outer_B = Vec3(a / 2, 0, 0);
  crease.c_inner_B = Vec3(-a / 2, 0, 0);
  crease.K << 1e6, 1e6, 1e6, 1e3, 0, 1e3;
  crease.crease = 0;
  crease.name = "crease";
  m.elements = {pin, crease};
  m.creases.push_back({std::make_shared<LinearCreaseLaw>(k, 2 * psi0), 2 * psi0});
  DriveDef drive;
  drive.name = "pull";
  drive.body = 2;
  drive.point_B = Vec3(a / 2, 0, 0);
  drive.start_W = Vec3(2 * a * std::cos(psi0), 0, 0);
  drive.direction_W = Vec3::UnitX();
  drive.stiffness = 1e6;
  drive.travel = 2 * a * (std::cos(psi_end) - std::cos(psi0));
  drive.step = drive.travel / 80;
  m.drives.push_back(drive);
  m.finalize_dofs();

  State st = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  set.tolerance = 1e-12;
  int checked = 0;
  double worst = 0;
  const SolverStats stats = run_solver(m, st, set, [&](const State& s, const BodyForces&) {
    const Vec3 x1 = s.R_WB[1].col(0);
    const double psi = std::atan2(x1.z(), x1.x());
    const Vec3 end = s.p_W[2] + s.R_WB[2] * Vec3(a / 2, 0, 0);
    const Vec3 pin_pt = s.p_W[1] + s.R_WB[1] * Vec3(-a / 2, 0, 0);
    EXPECT_NEAR((end - pin_pt).norm() / (2 * a * std::cos(psi)), 1.0, 1e-4);
    const double F = drive_force(m, s, 0).x();
    if (psi0 - psi < 1e-3) return;  // the start: zero force, nothing to compare
    const double F_ref = 2 * k * (psi0 - psi) / (a * std::sin(psi));
    worst = std::max(worst, std::abs(F / F_ref - 1));
    EXPECT_NEAR(F / F_ref, 1.0, 5e-3) << "psi " << psi / kDegToRad << " deg";
    ++checked;
  });
  ASSERT_EQ(stats.status, "ok") << stats.message;
  EXPECT_GE(checked, 79);
  EXPECT_NEAR(st.drive_s[0], drive.travel, 1e-15);
  RecordProperty("worst_relative_force_error", std::to_string(worst));
  std::printf("two panels: %d states, worst |F/F_ref - 1| = %.3g\n", checked, worst);
}

}  // namespace
}  // namespace finseg
