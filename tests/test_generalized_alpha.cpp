// The generalized-alpha implicit scheme against references from outside the project: the
// compound pendulum's period (complete elliptic integral of the first kind), Chung &
// Hulbert's (1993) linear analysis (their recurrence, amplification matrix and algorithmic
// damping ratio), and the cantilever's Euler-Bernoulli frequency.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <boost/math/special_functions/ellint_1.hpp>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "elastica_reference.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/generalized_alpha.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace generalized_alpha_test {

// Fixed anchor (body 0) and one moving body (body 1) joined by one bushing.
Model two_body_model(const BodyDef& moving, const ElementDef& joint, const Vec3& gravity,
                     double length) {
  BodyDef anchor;
  anchor.name = "anchor";
  set_box(anchor, Vec3::Constant(moving.thickness), moving.mass);
  anchor.fixed = true;
  Model m;
  m.bodies = {anchor, moving};
  m.elements = {joint};
  m.elements[0].inner = 1;
  m.elements[0].outer = 0;
  m.gravity_W = gravity;
  m.sheet.length = length;
  m.finalize_dofs();
  return m;
}

// A rod (L x w x t box) hinged at one end by a bushing stiff in every direction but the
// hinge axis (world y), released at rest theta0 from hanging straight down.
struct Pendulum {
  static constexpr double L = 0.2, w = 0.02, t = 0.002, mass = 0.01, g = 9.81;
  Model model;

  explicit Pendulum(double theta0) {
    BodyDef rod;
    rod.name = "rod";
    set_box(rod, Vec3(L, w, t), mass);
    // Body x points from the pivot to the free end: R_y(pi/2 - theta0).
    rod.R0_WB = Eigen::AngleAxisd(kPi / 2 - theta0, Vec3::UnitY()).toRotationMatrix();
    rod.p0_W = rod.R0_WB * Vec3(L / 2, 0, 0);
    ElementDef hinge;
    hinge.name = "hinge";
    hinge.c_inner_B = Vec3(-L / 2, 0, 0);
    hinge.R_inner_E = rod.R0_WB.transpose();
    hinge.K << 1e7, 1e7, 1e7, 1e3, 0, 1e3;  // pivot stretch < 1e-6 of L
    model = two_body_model(rod, hinge, Vec3(0, 0, -g), L);
  }

  // Closed form: T = 4 sqrt(I / (m g d)) K(sin(theta0 / 2)), I about the pivot, d = L / 2.
  double period(double theta0) const {
    const double d = L / 2;
    const double I = model.bodies[1].J_B(1, 1) + mass * d * d;
    return 4 * std::sqrt(I / (mass * g * d)) * boost::math::ellint_1(std::sin(theta0 / 2));
  }
};

struct Swing {
  std::vector<double> up_crossings;  ///< times the angle passes 0 upwards, s
  std::vector<double> peaks;         ///< |angle| at each turning point, rad
  SolverStats stats;
};

// Outputs every T/400: the crossing times come from linear interpolation, which is third
// order at a zero of the angle (the angular acceleration vanishes there).
Swing swing(double theta0, double periods, ImplicitScheme scheme, double rho_inf, double rtol) {
  const Pendulum p(theta0);
  State state = initial_state(p.model);
  SolverSettings s;
  s.kind = SolverKind::Implicit;
  s.scheme = scheme;
  s.rho_inf = rho_inf;
  s.t_end = periods * p.period(theta0);
  s.output_interval = p.period(theta0) / 400;
  s.rtol = rtol;
  s.atol = 1e-12;
  Swing r;
  double t_prev = 0, th_prev = theta0, w_prev = 0;
  r.stats = run_solver(p.model, state, s, [&](const State& x, const BodyForces&) {
    const Vec3 axis = x.R_WB[1].col(0);
    const double th = std::atan2(axis.x(), -axis.z()), w = x.w_W[1].y();
    if (th_prev < 0 && th >= 0) {
      r.up_crossings.push_back(t_prev + (x.t - t_prev) * (-th_prev) / (th - th_prev));
    }
    if (x.t > 0 && w_prev * w < 0) r.peaks.push_back(std::max(std::abs(th), std::abs(th_prev)));
    t_prev = x.t;
    th_prev = th;
    w_prev = w;
  });
  EXPECT_EQ(r.stats.status, "ok") << r.stats.message;
  return r;
}

// The tolerance of both swing tests. The period's error is of the order of the local error
// summed over the steps: at 150 degrees and rho_inf 0.8 it is -1.31e-3 at rtol 1e-5 and
// -3.95e-4 at 3e-6 (1 503 and 1 989 steps). Before the steps were spread evenly to the output
// times (docs/solvers.md, "Step control"), the slivers left before them took 2 706 steps at
// 1e-5 (-6.6e-5).
constexpr double kSwingRtol = 3e-6;

TEST(GeneralizedAlphaPendulum, PeriodWithinTenthOfAPercentAt30To150Degrees) {
  for (double deg : {30.0, 90.0, 150.0}) {
    const double th0 = deg * kPi / 180, T = Pendulum(th0).period(th0);
    for (double rho : {1.0, 0.8}) {
      const Swing r = swing(th0, 1.8, ImplicitScheme::GeneralizedAlpha, rho, kSwingRtol);
      ASSERT_EQ(r.up_crossings.size(), 2u) << deg << " deg";
      const double Tm = r.up_crossings[1] - r.up_crossings[0];
      ASSERT_GE(r.peaks.size(), 3u);
      const double amp = r.peaks.back() / th0;
      std::printf(
          "%3.0f deg rho_inf %.1f: period %.7f s, closed form %.7f s (%+.2e), amplitude "
          "after %zu half swings %.6f theta0, %ld steps\n",
          deg, rho, Tm, T, Tm / T - 1, r.peaks.size(), amp, r.stats.steps);
      EXPECT_NEAR(Tm / T, 1.0, 1e-3) << deg << " deg, rho_inf " << rho;
      // The resolved pendulum motion keeps its amplitude (second order, dissipation O(h^3)).
      EXPECT_NEAR(amp, 1.0, 1e-3) << deg << " deg, rho_inf " << rho;
    }
  }
}

// Backward Euler at the same tolerance misses both: the reason for the second-order scheme.
TEST(GeneralizedAlphaPendulum, BackwardEulerAtSameToleranceIsShortAndDecays) {
  const double th0 = kPi / 2, T = Pendulum(th0).period(th0);
  const Swing r = swing(th0, 1.8, ImplicitScheme::BackwardEuler, 0, kSwingRtol);
  ASSERT_EQ(r.up_crossings.size(), 2u);
  const double Tm = r.up_crossings[1] - r.up_crossings[0];
  std::printf("backward Euler 90 deg: period %+.2e, amplitude %.4f theta0\n", Tm / T - 1,
              r.peaks.back() / th0);
  EXPECT_LT(Tm / T, 1 - 1e-3);
  EXPECT_LT(r.peaks.back() / th0, 0.99);
}

// Chung & Hulbert (1993), their eqs. for the undamped oscillator x'' + w^2 x = 0:
//   (1 - am) a_{n+1} + am a_n = -w^2 ((1 - af) x_{n+1} + af x_n),
//   x_{n+1} = x_n + h v_n + h^2 ((1/2 - b) a_n + b a_{n+1}),
//   v_{n+1} = v_n + h ((1 - g) a_n + g a_{n+1}).
// Written here as the map (x, h v, h^2 a)_n -> (x, h v, h^2 a)_{n+1}, Omega = w h
// (Omega = infinity allowed: the first equation divided by Omega^2).
Eigen::Matrix3d amplification(const AlphaParameters& p, double Omega) {
  const double s = 1 / (Omega * Omega), am = p.alpha_m, af = p.alpha_f, b = p.beta, g = p.gamma;
  // Unknowns (x1, hv1, h2a1) in L y_{n+1} = R y_n.
  Eigen::Matrix3d L, R;
  L << 1 - af, 0, s * (1 - am),  //
      1, 0, -b,                  //
      0, 1, -g;
  R << -af, 0, -s * am,  //
      1, 1, 0.5 - b,     //
      0, 1, 1 - g;
  return L.inverse() * R;
}

struct LinearRun {
  std::vector<double> x;  ///< displacement at every step, m
};

// A body on a linear translational spring (no gravity, no rotation), fixed step h.
LinearRun oscillate(double rho_inf, double Omega, int steps) {
  constexpr double k = 100, mass = 0.01, x0 = 1e-3;
  BodyDef b;
  b.name = "mass";
  set_box(b, Vec3(0.01, 0.01, 0.001), mass);
  ElementDef spring;
  spring.name = "spring";
  spring.K << k, k, k, 0, 0, 0;
  const Model model = two_body_model(b, spring, Vec3::Zero(), 0.01);
  State state = initial_state(model);
  state.p_W[1].x() = x0;
  const double h = Omega / std::sqrt(k / mass);
  SolverSettings s;
  s.kind = SolverKind::Implicit;
  s.scheme = ImplicitScheme::GeneralizedAlpha;
  s.rho_inf = rho_inf;
  s.dt = s.dt_max = s.output_interval = h;
  s.t_end = steps * h;
  s.rtol = 1e3;  // no error control: the fixed step of the linear analysis
  s.atol = 1e-13;
  LinearRun r;
  const SolverStats stats = run_solver(
      model, state, s, [&](const State& x, const BodyForces&) { r.x.push_back(x.p_W[1].x()); });
  EXPECT_EQ(stats.status, "ok") << stats.message;
  EXPECT_EQ(stats.steps, steps);
  return r;
}

// Algorithmic damping ratio from the principal root lambda = exp(Omega_bar (-xi +- i)).
double damping_ratio(const Eigen::Matrix3d& A) {
  const Eigen::Vector3cd ev = A.eigenvalues();
  int k = 0;  // principal root: the complex one with positive imaginary part
  for (int i = 0; i < 3; ++i) {
    if (ev[i].imag() > ev[k].imag()) k = i;
  }
  return -std::log(std::abs(ev[k])) / std::arg(ev[k]);
}

TEST(GeneralizedAlphaLinear, SpectralRadiusAtInfinityIsRhoInf) {
  for (double rho : {0.0, 0.5, 0.8, 1.0}) {
    const Eigen::Matrix3d A = amplification(chung_hulbert(rho), INFINITY);
    const double radius = A.eigenvalues().cwiseAbs().maxCoeff();
    // A multiple root (triple at rho_inf = 0): computed eps^(1/3) apart.
    EXPECT_NEAR(radius, rho, 2e-5) << "rho_inf " << rho;
  }
  // rho_inf = 1: no dissipation at any frequency (the trapezoidal rule).
  for (double Omega : {0.1, 1.0, 10.0}) {
    EXPECT_NEAR(damping_ratio(amplification(chung_hulbert(1.0), Omega)), 0, 1e-12);
  }
}

// The rigid-body solver on a linear oscillator reproduces Chung & Hulbert's recurrence step by
// step, so its decay per period is exp(-2 pi xi) with their algorithmic damping ratio xi.
TEST(GeneralizedAlphaLinear, DecayFollowsChungHulbertDampingRatio) {
  constexpr int kSteps = 60;
  for (double rho : {1.0, 0.8, 0.5, 0.0}) {
    for (double Omega : {0.3, 1.0}) {
      const AlphaParameters p = chung_hulbert(rho);
      const Eigen::Matrix3d A = amplification(p, Omega);
      const LinearRun run = oscillate(rho, Omega, kSteps);
      ASSERT_EQ(run.x.size(), kSteps + 1u);
      Eigen::Vector3d y(run.x[0], 0, -Omega * Omega * run.x[0]);  // a_0 = vdot_0
      double worst = 0;
      for (int n = 1; n <= kSteps; ++n) {
        y = A * y;
        worst = std::max(worst, std::abs(run.x[n] - y[0]) / std::abs(run.x[0]));
      }
      // Prony: the principal root from a least-squares fit x_{n+1} = c1 x_n + c2 x_{n-1}
      // over the last steps (the spurious root has died out), xi = -ln r / arg.
      Eigen::MatrixXd X(kSteps - 20, 2);
      Eigen::VectorXd rhs(kSteps - 20);
      for (int n = 20; n < kSteps; ++n) {
        X.row(n - 20) << run.x[n], run.x[n - 1];
        rhs[n - 20] = run.x[n + 1];
      }
      const Eigen::Vector2d c = X.colPivHouseholderQr().solve(rhs);
      const double r = std::sqrt(-c[1]), arg = std::acos(c[0] / (2 * r));
      const double xi_measured = -std::log(r) / arg, xi = damping_ratio(A);
      std::printf(
          "rho_inf %.1f, h w %.1f: xi %.6f (Chung-Hulbert %.6f), decay per period "
          "%.6f, recurrence deviation %.1e x0\n",
          rho, Omega, xi_measured, xi, std::exp(-2 * kPi * xi_measured), worst);
      EXPECT_LT(worst, 1e-7) << "rho_inf " << rho << ", Omega " << Omega;
      EXPECT_NEAR(xi_measured, xi, 1e-4 + 1e-3 * xi) << "rho_inf " << rho << ", Omega " << Omega;
    }
  }
}

// Lowest angular frequency (rad per sample) in a uniformly sampled free vibration, by
// Prony's linear prediction of order 2 * modes and the roots of its characteristic polynomial.
double prony_lowest_frequency(const std::vector<double>& x, int modes) {
  const int p = 2 * modes, rows = static_cast<int>(x.size()) - p;
  Eigen::MatrixXd X(rows, p);
  Eigen::VectorXd rhs(rows);
  for (int n = 0; n < rows; ++n) {
    for (int j = 0; j < p; ++j) X(n, j) = x[n + p - 1 - j];
    rhs[n] = x[n + p];
  }
  const Eigen::VectorXd c = X.colPivHouseholderQr().solve(rhs);
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(p, p);
  companion.row(0) = c.transpose();
  companion.bottomLeftCorner(p - 1, p - 1).setIdentity();
  double lowest = INFINITY;
  for (const auto& z : Eigen::VectorXcd(companion.eigenvalues())) {
    if (z.imag() > 1e-9) lowest = std::min(lowest, std::arg(z));
  }
  return lowest;
}

// Free vibration of the cantilever (L / t = 100, 16 segments) released from its small sag
// under its own weight: the first frequency in the tip motion (Prony, which separates the
// higher modes the released shape carries) against Euler-Bernoulli beam theory and against
// the model's own first eigenfrequency; with rho_inf = 1 the first mode keeps its amplitude.
TEST(GeneralizedAlphaCantilever, FreeVibrationFrequency) {
  CantileverSpec s = validation::slender_strip(16);
  s.thickness = 1e-3;
  s.gravity = true;  // q L^3 / EI = 0.024: linear
  const double EI = bending_rigidity(s);
  const Model model = build_cantilever_model(s);
  const double w_beam =
      reference::cantilever_omega(1, s.length, EI, s.density * s.width * s.thickness);
  const double w_model = 2 * kPi * natural_frequencies(model, initial_state(model), 1).at(0);
  const double T = 2 * kPi / w_beam, every = T / 100;
  for (double rho : {1.0, 0.8}) {
    State state = validation::solve_static(model);
    state.load_scale = 0;  // release: gravity off
    state.t = 0;
    SolverSettings set;
    set.kind = SolverKind::Implicit;
    set.scheme = ImplicitScheme::GeneralizedAlpha;
    set.rho_inf = rho;
    set.t_end = 3 * T;
    set.output_interval = every;
    set.rtol = 1e-4;
    std::vector<double> z;
    const SolverStats stats = run_solver(model, state, set, [&](const State& x, const BodyForces&) {
      z.push_back(validation::probe_position(model, x, "tip").z());
    });
    ASSERT_EQ(stats.status, "ok") << stats.message;
    const double w = prony_lowest_frequency(z, 8) / every;
    std::printf(
        "cantilever rho_inf %.1f: first frequency %.6f rad/s, beam theory %.6f (%+.2e), "
        "model eigenvalue %.6f (%+.2e), %ld steps\n",
        rho, w, w_beam, w / w_beam - 1, w_model, w / w_model - 1, stats.steps);
    EXPECT_NEAR(w / w_beam, 1, 1e-2) << rho;  // 16 segments: the discretisation's own error
    EXPECT_NEAR(w / w_model, 1, 1e-3) << rho;
  }
}

std::string scene_with_solver(const std::string& solver) {
  return "material: {youngs_modulus: 4e9, density: 800}\n"
         "sheet: {length: 0.1, width: 0.02, thickness: 1e-4}\n"
         "discretisation: {segments: 4}\n"
         "fixtures: {panels: [1]}\n"
         "solver: " +
         solver + "\n";
}

TEST(GeneralizedAlphaScene, SchemeAndRhoInfKeys) {
  const Scene a = parse_scene(scene_with_solver("{type: implicit}"), "a.yaml");
  EXPECT_EQ(a.solver.scheme, ImplicitScheme::BackwardEuler);
  const Scene b = parse_scene(
      scene_with_solver("{type: implicit, scheme: generalized_alpha, rho_inf: 0.5}"), "b.yaml");
  EXPECT_EQ(b.solver.scheme, ImplicitScheme::GeneralizedAlpha);
  EXPECT_EQ(b.solver.rho_inf, 0.5);
  for (const char* bad : {"{type: implicit, scheme: hht}", "{type: implicit, rho_inf: 1.5}",
                          "{type: implicit, rho_inf: -0.1}"}) {
    try {
      parse_scene(scene_with_solver(bad), "c.yaml");
      ADD_FAILURE() << bad << " was accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("c.yaml: solver."), std::string::npos) << what;
    }
  }
}

}  // namespace generalized_alpha_test
}  // namespace finseg
