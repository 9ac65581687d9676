// Contact dynamics through the solvers, against independent references: Hertz impact in
// closed form, restitution of each damping law from a 1-DOF impact integrated here (RK4),
// the incline (stick below tan(phi) = mu_s, slide above with g (sin phi - mu_d cos phi)),
// a stack of sheets (penetrations from the weights above), folded panels pressed together.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "collision/contact_forces.hpp"
#include "collision/contact_laws.hpp"
#include "contact_test_util.hpp"
#include "solvers/solver.hpp"

namespace finseg {
namespace contact_dynamics_test {

constexpr double kG = 9.81;
constexpr double kThick = 2e-4;  // plate thickness, m

using test::plate;

// --- 1-DOF references, written from the laws' published formulas --------------------------

enum class Law { Impact, HC, LN, Flores };

struct Impact1 {
  Law law = Law::Impact;
  double m = 1e-3, K = 1e9, e = 1.5, c = 0, d = 1e-5, cr = 1, v0 = 0.1;
  double force(double x, double xd) const {  // x: penetration, xd: its rate
    if (x <= 0) return 0;
    double f = K * std::pow(x, e);
    switch (law) {
      case Law::Impact: {
        const double s = std::min(x / d, 1.0);
        f += c * s * s * (3 - 2 * s) * xd;
        break;
      }
      case Law::HC:
        f *= 1 + 1.5 * (1 - cr) * xd / v0;
        break;
      case Law::LN:
        f *= 1 + 0.75 * (1 - cr * cr) * xd / v0;
        break;
      case Law::Flores:
        f *= 1 + 8 * (1 - cr) / (5 * cr) * xd / v0;
        break;
    }
    return std::max(f, 0.0);
  }
  // Integrates m x'' = -F from x = 0, x' = v0 until x < 0 again (RK4); returns
  // {restitution, max penetration, duration}.
  std::array<double, 3> run() const {
    const double T = 3.2181 * std::pow(m / K, 0.4) * std::pow(v0, -0.2);
    const double h = T / 20000;
    double x = 0, v = v0, t = 0, xmax = 0;
    auto acc = [&](double xx, double vv) { return -force(xx, vv) / m; };
    while (true) {
      const double k1x = v, k1v = acc(x, v);
      const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
      const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
      const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
      const double xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
      const double vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      if (xn < 0) {
        const double frac = x / (x - xn);
        return {-(v + frac * (vn - v)) / v0, xmax, t + frac * h};
      }
      x = xn;
      v = vn;
      t += h;
      xmax = std::max(xmax, x);
    }
  }
};

// A plate of 1 g dropped flat at v0 onto a clamped larger plate (no gravity), run with the
// explicit solver; returns {restitution, max penetration, contact duration}.
std::array<double, 3> drop(const Impact1& ref) {
  Model m;
  m.bodies.push_back(
      plate("ground", 1, Vec3(0.1, 0.1, kThick), Vec3::Zero(), Mat3::Identity(), true));
  m.bodies.push_back(plate("plate", ref.m, Vec3(0.02, 0.02, kThick), Vec3(0, 0, kThick)));
  ContactDef& c = m.contact;
  c.enabled = true;
  c.stiffness = ref.K;
  c.exponent = ref.e;
  c.damping = ref.c;
  c.damping_depth = ref.d;
  c.restitution = ref.cr;
  c.damping_law = ref.law == Law::Impact ? ContactDamping::Impact
                  : ref.law == Law::HC   ? ContactDamping::HuntCrossley
                  : ref.law == Law::LN   ? ContactDamping::LankaraniNikravesh
                                         : ContactDamping::Flores;
  m.finalize_dofs();
  State s = initial_state(m);
  s.v_W[1] = Vec3(0, 0, -ref.v0);
  const double T = 3.2181 * std::pow(ref.m / ref.K, 0.4) * std::pow(ref.v0, -0.2);
  SolverSettings set;
  set.kind = SolverKind::Explicit;
  set.dt = T / 4000;
  set.t_end = 2.5 * T;
  set.output_interval = set.dt;
  double t_prev = 0, gap_prev = 0, t_in = -1, t_out = -1, min_gap = 1;
  bool first = true;
  const SolverStats st = run_solver(m, s, set, [&](const State& x, const BodyForces&) {
    const double gap = x.p_W[1].z() - kThick;  // < 0: penetration
    if (!first && t_in < 0 && gap_prev >= 0 && gap < 0)
      t_in = t_prev + gap_prev / (gap_prev - gap) * (x.t - t_prev);
    if (!first && t_in >= 0 && t_out < 0 && gap_prev < 0 && gap >= 0)
      t_out = t_prev + gap_prev / (gap_prev - gap) * (x.t - t_prev);
    min_gap = std::min(min_gap, gap);
    t_prev = x.t;
    gap_prev = gap;
    first = false;
  });
  EXPECT_EQ(st.status, "ok") << st.message;
  EXPECT_GE(t_out, 0) << "no rebound";
  EXPECT_NEAR(s.p_W[1].x(), 0, 1e-12);  // stays flat and centred
  EXPECT_NEAR(s.w_W[1].norm(), 0, 1e-9);
  return {s.v_W[1].z() / ref.v0, -min_gap, t_out - t_in};
}

TEST(ContactDynamics, UndampedHertzImpactMatchesClosedForm) {
  Impact1 ref;  // e = 1.5, no damping
  const auto r = drop(ref);
  const double dmax = std::pow(5 * ref.m * ref.v0 * ref.v0 / (4 * ref.K), 0.4);
  const double dur = 3.2181 * std::pow(ref.m / ref.K, 0.4) * std::pow(ref.v0, -0.2);
  RecordProperty("penetration_error", fmt::format("{:.2e}", r[1] / dmax - 1));
  RecordProperty("duration_error", fmt::format("{:.2e}", r[2] / dur - 1));
  EXPECT_NEAR(r[1] / dmax, 1.0, 0.01);
  EXPECT_NEAR(r[2] / dur, 1.0, 0.01);
  EXPECT_NEAR(r[0], 1.0, 0.01);  // elastic
}

void check_restitution(Law law, double cr, double c_max) {
  Impact1 ref;
  ref.law = law;
  ref.cr = cr;
  ref.c = c_max;
  const auto expect = ref.run();
  const auto got = drop(ref);
  std::printf("law %d cr %.2f: 1-DOF e = %.4f, simulated e = %.4f\n", static_cast<int>(law), cr,
              expect[0], got[0]);
  EXPECT_NEAR(got[0] / expect[0], 1.0, 0.01);
  EXPECT_NEAR(got[1] / expect[1], 1.0, 0.01);
}

TEST(ContactDynamics, ImpactDampingRestitutionMatchesOneDofImpact) {
  // c_max comparable to critical damping of the linearised contact.
  check_restitution(Law::Impact, 1, 3.0);
  check_restitution(Law::Impact, 1, 60.0);  // ~0.3 of critical at the deepest point
}
TEST(ContactDynamics, HuntCrossleyRestitutionMatchesOneDofImpact) {
  check_restitution(Law::HC, 0.5, 0);
  check_restitution(Law::HC, 0.9, 0);
}
TEST(ContactDynamics, LankaraniNikraveshRestitutionMatchesOneDofImpact) {
  check_restitution(Law::LN, 0.5, 0);
  check_restitution(Law::LN, 0.9, 0);
}
TEST(ContactDynamics, FloresRestitutionMatchesOneDofImpactAndNominal) {
  for (double cr : {0.3, 0.5, 0.9}) {
    check_restitution(Law::Flores, cr, 0);
  }
  // At low restitution Flores stays closest to the nominal coefficient; Hunt-Crossley and
  // Lankarani-Nikravesh (derived for cr near 1) bounce much more than asked.
  Impact1 ref;
  ref.cr = 0.5;
  ref.law = Law::Flores;
  const double flores = ref.run()[0];
  ref.law = Law::HC;
  const double hc = ref.run()[0];
  ref.law = Law::LN;
  const double ln = ref.run()[0];
  EXPECT_LT(std::abs(flores - 0.5), std::abs(hc - 0.5));
  EXPECT_LT(std::abs(flores - 0.5), std::abs(ln - 0.5));
  EXPECT_GT(hc, 0.6);
  EXPECT_GT(ln, 0.7);
}

// --- Incline ------------------------------------------------------------------------------

struct InclineResult {
  double creep_speed;  // mean speed along the slope over the measuring window, m/s
  double accel;        // mean acceleration along the slope over the window, m/s^2
  double creep;        // displacement along the slope over the window, m
};

// A 1 g plate resting on a clamped plate tilted by phi; measured between t1 and t2.
InclineResult incline(double phi, FrictionModel fm, SolverKind kind, double t1, double t2) {
  const double m = 1e-3;
  const Mat3 R = Eigen::AngleAxisd(-phi, Vec3::UnitY()).toRotationMatrix();  // x: up-slope
  const Vec3 down = -(R * Vec3::UnitX());
  const Vec3 n = R * Vec3::UnitZ();
  Model mod;
  mod.gravity_W = Vec3(0, 0, -kG);
  mod.bodies.push_back(plate("incline", 1, Vec3(0.4, 0.1, kThick), Vec3::Zero(), R, true));
  const ContactSuggestion sug = suggest_contact(m, kG, 1e-5);
  ContactDef& c = mod.contact;
  c.enabled = true;
  c.stiffness = sug.stiffness;
  c.damping = sug.damping;
  c.damping_depth = sug.damping_depth;
  c.friction = fm;
  c.mu_static = 0.5;
  c.mu_dynamic = 0.3;
  c.stiction_speed = 1e-4;
  c.friction_speed = 1e-3;
  c.tangential_stiffness = sug.tangential_stiffness;
  c.tangential_damping = sug.tangential_damping;
  const double delta0 = std::pow(m * kG * std::cos(phi) / c.stiffness, 1 / c.exponent);
  mod.bodies.push_back(plate("block", m, Vec3(0.02, 0.02, kThick), n * (kThick - delta0), R));
  mod.finalize_dofs();
  State s = initial_state(mod);
  SolverSettings set;
  set.kind = kind;
  set.t_end = t2;
  set.output_interval = t2 - t1;
  if (kind == SolverKind::Explicit) set.dt = 0.1 * sug.period;
  set.dt_max = 1e-2;
  Vec3 p1 = Vec3::Zero(), v1 = Vec3::Zero();
  double ta = -1;
  const SolverStats st = run_solver(mod, s, set, [&](const State& x, const BodyForces&) {
    if (ta < 0 && x.t >= t1 - 1e-9) {
      ta = x.t;
      p1 = x.p_W[1];
      v1 = x.v_W[1];
    }
  });
  EXPECT_EQ(st.status, "ok") << st.message;
  EXPECT_GT(ta, 0);
  const double dt = s.t - ta;
  const double dist = down.dot(s.p_W[1] - p1);
  return {dist / dt, down.dot(s.v_W[1] - v1) / dt, dist};
}

TEST(ContactDynamics, ContinuousFrictionSlidesWithDynamicCoefficient) {
  const double phi = 35 * kDegToRad;
  const InclineResult r = incline(phi, FrictionModel::Continuous, SolverKind::Explicit, 0.05, 0.1);
  const double a = kG * (std::sin(phi) - 0.3 * std::cos(phi));
  RecordProperty("acceleration_error", fmt::format("{:.2e}", r.accel / a - 1));
  EXPECT_NEAR(r.accel / a, 1.0, 0.01);
}

TEST(ContactDynamics, AnchorFrictionSlidesWithDynamicCoefficient) {
  const double phi = 35 * kDegToRad;
  const InclineResult r = incline(phi, FrictionModel::Anchor, SolverKind::Explicit, 0.05, 0.1);
  const double a = kG * (std::sin(phi) - 0.3 * std::cos(phi));
  RecordProperty("acceleration_error", fmt::format("{:.2e}", r.accel / a - 1));
  EXPECT_NEAR(r.accel / a, 1.0, 0.01);
}

TEST(ContactDynamics, ContinuousFrictionCreepsAtTheSpeedWhereMuEqualsTanPhi) {
  // Below tan(phi) = mu_s the continuous law creeps at the speed v with mu(v) = tan(phi);
  // on [0, v_s] mu = mu_s (3 x / 2 - x^3 / 2), x = v / v_s: solved here by bisection.
  const double phi = 20 * kDegToRad;
  double lo = 0, hi = 1;
  for (int i = 0; i < 100; ++i) {
    const double x = 0.5 * (lo + hi);
    (0.5 * (1.5 * x - 0.5 * x * x * x) < std::tan(phi) ? lo : hi) = x;
  }
  const double v_creep = lo * 1e-4;
  const InclineResult r = incline(phi, FrictionModel::Continuous, SolverKind::Implicit, 1, 3);
  RecordProperty("creep_speed_error", fmt::format("{:.2e}", r.creep_speed / v_creep - 1));
  EXPECT_NEAR(r.creep_speed / v_creep, 1.0, 0.01);
}

// A 1 g plate thrown at v0 along a clamped horizontal plate with continuous friction slows
// down at a = mu_d g (Coulomb) above the law's dynamic speed v_d. Backward Euler with constant
// steps h: v_k = v0 - k h a while positive, x = h sum v_k, i.e. with n = floor(v0 / (h a))
// x = h (n v0 - h a n (n + 1) / 2), which tends to Coulomb's v0^2 / (2 a) as h -> 0 (the
// stopping step adds nothing: the plate ends it at rest).
struct Thrown {
  double x = 0, x_be = 0, x_coulomb = 0, v_end = 0;
  SolverStats stats;
};

Thrown thrown_plate(double mu_s, double mu_d, double v_d = 1e-3) {
  const double m = 1e-3, v0 = 0.05, h = 2e-3;
  Model mod;
  mod.gravity_W = Vec3(0, 0, -kG);
  mod.bodies.push_back(
      plate("ground", 1, Vec3(0.4, 0.1, kThick), Vec3::Zero(), Mat3::Identity(), true));
  mod.contact = test::continuous_contact(suggest_contact(m, kG, 1e-5), mu_s, mu_d);
  ContactDef& c = mod.contact;
  c.stiction_speed = 1e-4;
  c.friction_speed = v_d;
  const double delta0 = std::pow(m * kG / c.stiffness, 1 / c.exponent);
  mod.bodies.push_back(plate("block", m, Vec3(0.02, 0.02, kThick), Vec3(0, 0, kThick - delta0)));
  mod.finalize_dofs();
  State s = initial_state(mod);
  s.v_W[1] = Vec3(v0, 0, 0);
  SolverSettings set;
  set.kind = SolverKind::Implicit;
  // (a whole number of steps: the closed form below takes every step h)
  set.t_end = h * std::ceil(2 * v0 / (mu_d * kG) / h);
  set.output_interval = set.t_end;
  set.dt = set.dt_max = h;
  set.atol = 1e-5;  // the local error h/2 |dv| = h^2 a / 2 = 5.9e-6 m: every step is h
  Thrown r;
  r.stats = run_solver(mod, s, set, [](const State&, const BodyForces&) {});
  const double a = mu_d * kG;
  const double n = std::floor(v0 / (h * a));
  r.x_be = h * (n * v0 - h * a * n * (n + 1) / 2);
  r.x_coulomb = v0 * v0 / (2 * a);
  r.x = s.p_W[1].x();
  r.v_end = s.v_W[1].norm();
  return r;
}

// mu_s = mu_d: the law has no falling branch. The step in which the plate stops starts on the
// law's plateau, where Newton's tangent has no slope along the slip: the full correction
// throws the slip velocity across zero onto the opposite plateau and back (a 2-cycle); without
// the implicit solver's backtracking that step failed and was cut by 4 (docs/solvers.md,
// "Contact: why the implicit solver crawled").
TEST(ContactDynamics, ImplicitPlateThrownAlongAPlateStopsAtCoulombsDistance) {
  const Thrown r = thrown_plate(0.3, 0.3);
  ASSERT_EQ(r.stats.status, "ok") << r.stats.message;
  RecordProperty("stop_distance_error", fmt::format("{:.2e}", r.x / r.x_be - 1));
  RecordProperty("coulomb_distance_ratio", fmt::format("{:.4f}", r.x / r.x_coulomb));
  EXPECT_NEAR(r.x / r.x_be, 1.0, 2e-3);
  EXPECT_LT(r.v_end, 1e-4);              // at rest, up to the creep of the regularisation
  EXPECT_EQ(r.stats.rejected_steps, 0);  // one stop, one unknown speed: Newton must converge
}

// mu_s = 0.3 > mu_d = 0.25 with a steep falling (Stribeck) branch, v_d = 1.2 v_s: a negative
// damping up to F_n |mu'| = 37 N s / m, so that Newton's matrix of the exact law is indefinite
// for steps longer than m / (F_n |mu'|) = 2.7e-5 s (here h = 2e-3 s). With the falling factor
// taken at the last accepted step's slip speed (docs/contact.md, "Friction") the stop costs no
// refused step and the distance is backward Euler's at a = mu_d g. (This one-point stop also
// passes with the exact law, Newton's backtracking finding its root; the lag matters where
// many points slide on the branch at once, the lab cone's crawl.)
TEST(ContactDynamics, ImplicitPlateStopsThroughTheFallingBranchWithoutRefusedSteps) {
  const Thrown r = thrown_plate(0.3, 0.25, 1.2e-4);
  ASSERT_EQ(r.stats.status, "ok") << r.stats.message;
  RecordProperty("stop_distance_error", fmt::format("{:.2e}", r.x / r.x_be - 1));
  EXPECT_NEAR(r.x / r.x_be, 1.0, 2e-3);
  EXPECT_LT(r.v_end, 1e-4);
  EXPECT_EQ(r.stats.rejected_steps, 0);
}

TEST(ContactDynamics, AnchorFrictionHoldsWithoutCreep) {
  const double phi = 20 * kDegToRad;
  const InclineResult r = incline(phi, FrictionModel::Anchor, SolverKind::Implicit, 1, 10);
  RecordProperty("creep_m", fmt::format("{:.3e}", r.creep));
  std::printf("anchor creep over 9 s: %.3e m\n", r.creep);
  // Elastic anchor deflection is m g sin(phi) / k_t ~ 2e-8 m; creep over 9 s must stay far
  // below it (the continuous law creeps ~0.5 mm in the same time).
  EXPECT_LT(std::abs(r.creep), 1e-10);
}

// --- Set down inside the friction cone ---------------------------------------------------

// A 1 g plate set down at rest on a clamped plate tilted by phi, anchor friction with
// mu_s = 0.5, mu_d = 0.4 (the values). The normal contact is critically damped at the
// rest penetration (suggest_contact with load factor 1 at depth 0.5 um), so that a plate set
// down off its rest penetration settles without bouncing off (a bounce unloads the contact,
// and a plate that slips on a slope steeper than atan(mu_d) rightly slides on).
struct SetDown {
  double phi = 0;
  double penetration = 1;  // initial penetration / rest penetration
  SolverKind kind = SolverKind::Implicit;
  double t_end = 1;
};

struct SetDownResult {
  SolverStats stats;
  double travel = 0;             // down the slope from where it was set, m
  double late_travel = 0;        // down the slope over the last half of the run, m
  double accel = 0;              // mean acceleration down the slope over the last half, m/s^2
  double spring_deflection = 0;  // m g sin(phi) / k_t, m
};

SetDownResult set_down(const SetDown& c) {
  const double m = 1e-3;
  const Mat3 R = Eigen::AngleAxisd(-c.phi, Vec3::UnitY()).toRotationMatrix();  // x: up-slope
  const Vec3 down = -(R * Vec3::UnitX());
  const Vec3 n = R * Vec3::UnitZ();
  const ContactSuggestion sug = suggest_contact(m, kG, 5e-7, 1.5, 1.0);
  Model mod;
  mod.gravity_W = Vec3(0, 0, -kG);
  mod.contact = test::anchor_contact(sug, 0.5, 0.4);
  mod.bodies.push_back(plate("incline", 1, Vec3(0.4, 0.1, kThick), Vec3::Zero(), R, true));
  const double delta0 =
      std::pow(m * kG * std::cos(c.phi) / sug.stiffness, 1 / mod.contact.exponent);
  const Vec3 p0 = n * (kThick - c.penetration * delta0);
  mod.bodies.push_back(plate("block", m, Vec3(0.02, 0.02, kThick), p0, R));
  mod.finalize_dofs();
  State s = initial_state(mod);
  SolverSettings set;
  set.kind = c.kind;
  set.t_end = c.t_end;
  set.output_interval = 0.5 * c.t_end;
  // Explicit: the damped rocking modes of the plate on its nine contact points need a step
  // of a twentieth of the contact period.
  set.dt = c.kind == SolverKind::Explicit ? 0.05 * sug.period : 0;
  set.dt_max = 1e-2;
  Vec3 p_half = p0, v_half = Vec3::Zero();
  double t_half = -1;
  SetDownResult r;
  r.stats = run_solver(mod, s, set, [&](const State& x, const BodyForces&) {
    if (t_half < 0 && x.t > 0.25 * c.t_end) t_half = x.t, p_half = x.p_W[1], v_half = x.v_W[1];
  });
  r.travel = down.dot(s.p_W[1] - p0);
  r.late_travel = down.dot(s.p_W[1] - p_half);
  r.accel = down.dot(s.v_W[1] - v_half) / (s.t - t_half);
  r.spring_deflection = m * kG * std::sin(c.phi) / sug.tangential_stiffness;
  return r;
}

const double kCone = std::atan(0.5);  // atan(mu_s)

// Inside the cone a plate set down at rest sticks, set down at its rest penetration (fresh) or
// off it (settled): it moves only by the elastic deflection of the anchor springs,
// m g sin(phi) / k_t (0.1 um), and then not at all. Formerly the new contact points started
// out sliding (anchors placed with the continuous law's force of the first step, which in the
// explicit solver is already past v_s) and the plate slid off at 23-26 deg: 1.55 m in 1 s.
TEST(ContactDynamics, PlateSetDownInsideTheConeSticks) {
  for (SolverKind kind : {SolverKind::Explicit, SolverKind::Implicit}) {
    for (double phi : {23 * kDegToRad, 0.98 * kCone}) {
      for (double pen : {1.0, 0.5, 2.0}) {
        if (pen != 1.0 && phi != 0.98 * kCone) continue;
        const SetDownResult r = set_down({phi, pen, kind});
        const std::string what = fmt::format("{} at {:.2f} deg, penetration x{}",
                                             kind == SolverKind::Explicit ? "explicit" : "implicit",
                                             phi / kDegToRad, pen);
        ASSERT_EQ(r.stats.status, "ok") << what << ": " << r.stats.message;
        EXPECT_LT(std::abs(r.travel), 1e-6) << what;
        EXPECT_NEAR(r.travel / r.spring_deflection, 1.0, 0.02) << what;
        EXPECT_LT(std::abs(r.late_travel), 1e-12) << what;
      }
    }
  }
}

// Dropped onto the incline (from touching it, penetration 0, to a gap of 20 rest
// penetrations), the plate's points come into contact mid-run, after the run's first commit,
// without history; it lands, rocks on its damped contact, comes to rest and stays, on a slope
// below atan(mu_d). Not yet right: between atan(mu_d) and atan(mu_s) a landing plate slides
// off in both solvers (measured at 0.9 and 0.98 atan(mu_s): 0.19 and 0.53 m in 1 s), while a
// set-down one sticks (PlateSetDownInsideTheConeSticks). Suspected: the landing's rebound takes
// the normal force near zero, the points slip, and sliding with mu_d < tan(phi) never stops.
TEST(ContactDynamics, PlateDroppedBelowTheSlidingAngleComesToRestAndStays) {
  const double phi = 0.95 * std::atan(0.4);
  for (SolverKind kind : {SolverKind::Explicit, SolverKind::Implicit}) {
    for (double pen : {0.0, -1.0, -20.0}) {
      const SetDownResult r = set_down({phi, pen, kind});
      const std::string what =
          fmt::format("{}, dropped from {} rest penetrations",
                      kind == SolverKind::Explicit ? "explicit" : "implicit", -pen);
      ASSERT_EQ(r.stats.status, "ok") << what << ": " << r.stats.message;
      EXPECT_LT(std::abs(r.travel), 1e-4) << what;  // the landing's slip, then nothing
      EXPECT_LT(std::abs(r.late_travel), 1e-12) << what;
    }
  }
}

// Above the cone it slides with g (sin phi - mu_d cos phi), in both dynamic solvers.
TEST(ContactDynamics, PlateSetDownAboveTheConeSlidesWithDynamicCoefficient) {
  for (SolverKind kind : {SolverKind::Explicit, SolverKind::Implicit}) {
    for (double phi : {1.03 * kCone, 35 * kDegToRad}) {
      const SetDownResult r = set_down({phi, 1.0, kind, 0.2});
      const double a = kG * (std::sin(phi) - 0.4 * std::cos(phi));
      const std::string what =
          fmt::format("{} at {:.2f} deg", kind == SolverKind::Explicit ? "explicit" : "implicit",
                      phi / kDegToRad);
      ASSERT_EQ(r.stats.status, "ok") << what << ": " << r.stats.message;
      EXPECT_NEAR(r.accel / a, 1.0, 0.01) << what;
    }
  }
}

// The static solver (where an equilibrium exists): inside the cone the plate holds with the
// anchor springs' deflection m g sin(phi) / k_t (to 2e-4: the friction acts half a thickness
// below the centroid, and the couple pitches the plate); above it there is no equilibrium, and the
// run says so. Formerly the static solver found none even at 20 deg: new contact points had
// no anchor in their first solve (no friction at zero velocity), and the tunnelling check
// compared penetrations with the sheet thickness, zero in a model built by hand.
TEST(ContactDynamics, StaticSolverHoldsAPlateInsideTheCone) {
  for (double phi : {0.4 * kCone, 23 * kDegToRad, 0.98 * kCone}) {
    const SetDownResult r = set_down({phi, 1.0, SolverKind::Static});
    ASSERT_EQ(r.stats.status, "ok") << phi / kDegToRad << " deg: " << r.stats.message;
    EXPECT_NEAR(r.travel / r.spring_deflection, 1.0, 1e-3) << phi / kDegToRad << " deg";
  }
  const SetDownResult above = set_down({1.03 * kCone, 1.0, SolverKind::Static});
  EXPECT_EQ(above.stats.status, "diverged");
  EXPECT_NE(above.stats.message.find("slips"), std::string::npos) << above.stats.message;
}

// --- Stack -------------------------------------------------------------------------------

TEST(ContactDynamics, StackOfTenSheetsRestsWithPenetrationsOfTheWeightAbove) {
  const int n = 10;
  const double m = 1e-3;
  Model mod;
  mod.gravity_W = Vec3(0, 0, -kG);
  mod.bodies.push_back(
      plate("table", 1, Vec3(0.1, 0.1, kThick), Vec3::Zero(), Mat3::Identity(), true));
  for (int i = 1; i <= n; ++i)
    mod.bodies.push_back(
        plate(fmt::format("sheet{}", i), m, Vec3(0.03, 0.02, kThick), Vec3(0, 0, i * kThick)));
  const ContactSuggestion sug = suggest_contact(m, kG, 1e-5);
  mod.contact = test::anchor_contact(sug, 0.4, 0.3);
  const ContactDef& c = mod.contact;
  mod.finalize_dofs();
  State s = initial_state(mod);
  SolverSettings set;
  set.kind = SolverKind::Implicit;
  set.t_end = 0.5;
  set.output_interval = 0.05;
  double worst = -1;
  const SolverStats st = run_solver(mod, s, set, [&](const State& x, const BodyForces&) {
    for (int i = 1; i <= n; ++i) worst = std::max(worst, x.p_W[i - 1].z() - x.p_W[i].z());
  });
  ASSERT_EQ(st.status, "ok") << st.message;
  EXPECT_LT(worst, 0);  // sheets never pass through each other
  for (int i = 1; i <= n; ++i) {
    const int above = n - i + 1;  // sheets carried by contact i-1 / i
    const double delta = std::pow(above * m * kG / c.stiffness, 1 / c.exponent);
    const double gap = s.p_W[i].z() - s.p_W[i - 1].z();
    EXPECT_NEAR((kThick - gap) / delta, 1.0, 0.01) << "sheet " << i;
    EXPECT_LT(std::hypot(s.p_W[i].x(), s.p_W[i].y()), 1e-9) << "drift of sheet " << i;
    EXPECT_LT(s.v_W[i].norm(), 1e-6);
  }
}

// --- Folded panels ------------------------------------------------------------------------

TEST(ContactDynamics, FoldedPanelsPressedTogetherNeverPassThrough) {
  // Panel 0: segments 0..3 along +x at z = 0 (clamped). Panel 1: segments 4..7 folded back
  // over it at a small gap, joined to panel 0 by an element at the crease; a load presses
  // panel 1 down with 100 times its weight.
  const double L = 0.01, W = 0.01, t = 1e-4, gap = 1.2e-4, mass = 8e-6;
  Model mod;
  const Mat3 flip = Eigen::AngleAxisd(kPi, Vec3::UnitY()).toRotationMatrix();
  for (int i = 0; i < 8; ++i) {
    const bool top = i >= 4;
    BodyDef b = plate(fmt::format("s{}", i), mass, Vec3(L, W, t),
                      top ? Vec3((7 - i + 0.5) * L, 0, gap) : Vec3((i + 0.5) * L, 0, 0),
                      top ? flip : Mat3::Identity(), !top);
    b.panel = top ? 1 : 0;
    b.centroid_M = Vec2((i + 0.5) * L, 0.5 * W);
    mod.bodies.push_back(b);
  }
  for (int i = 0; i < 7; ++i) {
    ElementDef e;
    e.outer = i;
    e.inner = i + 1;
    e.K << 1e3, 1e3, 1e3, 1e-2, 1e-2, 1e-2;
    e.C = 1e-3 * e.K;
    const Vec3 P =
        i == 3 ? Vec3(4 * L, 0, 0.5 * gap) : 0.5 * (mod.bodies[i].p0_W + mod.bodies[i + 1].p0_W);
    e.c_outer_B = mod.bodies[i].R0_WB.transpose() * (P - mod.bodies[i].p0_W);
    e.c_inner_B = mod.bodies[i + 1].R0_WB.transpose() * (P - mod.bodies[i + 1].p0_W);
    e.R_inner_E = mod.bodies[i + 1].R0_WB.transpose();
    e.R_outer_F = mod.bodies[i].R0_WB.transpose();
    mod.elements.push_back(e);
  }
  mod.gravity_W = Vec3(0, 0, -kG);
  for (int i = 4; i < 8; ++i)
    mod.loads.push_back({i, Vec3::Zero(), Vec3(0, 0, -100 * mass * kG), Vec3::Zero(), false});
  mod.contact = test::continuous_contact(suggest_contact(mass, kG, 1e-5), 0.4, 0.3);
  mod.finalize_dofs();
  State s = initial_state(mod);
  SolverSettings set;
  set.kind = SolverKind::Implicit;
  set.t_end = 0.2;
  set.output_interval = 0.01;
  double lowest = 1, deepest = 0;
  const SolverStats st = run_solver(mod, s, set, [&](const State& x, const BodyForces&) {
    for (int i = 4; i < 8; ++i)
      for (double cx : {-0.5 * L, 0.5 * L})
        for (double cy : {-0.5 * W, 0.5 * W})
          lowest = std::min(lowest, (x.p_W[i] + x.R_WB[i] * Vec3(cx, cy, 0)).z());
    deepest = std::max(deepest, contact_summary(mod, x).max_penetration);
  });
  ASSERT_EQ(st.status, "ok") << st.message;
  const ContactSummary sum = contact_summary(mod, s);
  EXPECT_GE(sum.active, 12);   // three facing pairs of four corners at least
  EXPECT_GT(lowest, 0.5 * t);  // mid-surfaces stay apart by most of the thickness
  EXPECT_LT(deepest, 0.25 * t);
  // Pressed panel: total normal force carries the loads on the three free facing segments.
  EXPECT_GT(sum.total_normal_force, 3 * 100 * mass * kG);
}

}  // namespace contact_dynamics_test
}  // namespace finseg
