// Newton's matrix for gas in chambers. The Jacobian of a chamber's pressure forces at fixed
// pressure, p d2V/dq2 (the follower part), against central differences of the forces: a box
// of six free plates joined at their edges by bushings, under a prescribed pressure, in a
// deformed state (every plate moved and turned), so that the gap strips and corner patches
// between the faces all take part. The gas's stiffness -dp/dV against differences of the gas
// laws, its rank-one terms solved by Sherman-Morrison-Woodbury against the dense system, and a
// lid on soft springs lifted by a quasi-static gas against the closed form of the gas law.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "elements/assemble.hpp"
#include "elements/chamber_gas.hpp"
#include "jacobian_test_util.hpp"
#include "pressure_test_util.hpp"
#include "solvers/dofs.hpp"
#include "solvers/solver.hpp"
#include "solvers/volume_stiffness.hpp"

namespace finseg {
namespace gas_jacobian_test {

Model pressed_box(double pressure) {
  Model m;
  ChamberDef c;
  c.name = "box";
  c.gas = GasModel::Prescribed;
  c.prescribed.pressure = pressure;
  c.faces = test::add_box(m, 0.1, 0.08, 0.06, false, 0.02);
  test::join_box_edges(m, c.faces, 2e3, 0.2);
  test::add_chamber_and_finish(m, c, 0.1);
  return m;
}

// Every plate moved by up to 3 mm and turned by up to 0.1 rad (fixed pattern of signs).
State deformed(const Model& m) {
  State s = initial_state(m);
  Eigen::VectorXd dq(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) {
    const double u = std::sin(1.7 * i + 0.3);
    dq[i] = (i % 6 < 3 ? 3e-3 : 0.1) * u;
  }
  apply_pose_increment(m, s, dq);
  return s;
}

Eigen::MatrixXd jacobian(const Model& m, const State& s) {
  return test::pose_jacobian(m, s);
}

Eigen::MatrixXd differences(const Model& m, const State& s) {
  return test::fd_pose_jacobian(m, s, 1e-6);
}

TEST(ChamberJacobian, PressureForcesAtFixedPressureMatchCentralDifferences) {
  const double p = 1e5;  // Pa: the pressure terms a good share of the bushings' stiffness
  const Model m = pressed_box(p), bare = pressed_box(0);
  const State s = deformed(m);
  const Eigen::MatrixXd J = jacobian(m, s), fd = differences(m, s);
  const Eigen::MatrixXd pressure_part = J - jacobian(bare, s);
  const double scale = J.cwiseAbs().maxCoeff();
  // The pressure's part is a large share of the whole, and the whole matches.
  EXPECT_GT(pressure_part.cwiseAbs().maxCoeff(), 0.2 * scale);
  EXPECT_LT((J - fd).cwiseAbs().maxCoeff(), 1e-6 * scale)
      << "largest entry " << scale << ", pressure part " << pressure_part.cwiseAbs().maxCoeff();
}

constexpr double kR = 287.05, kGamma = 1.4, kT = 293.15;

ChamberDef air(GasModel gas) {
  ChamberDef c;
  c.name = "air";
  c.gas = gas;
  c.gas_constant = kR;
  c.gamma = kGamma;
  c.temperature = kT;
  c.initial_pressure = 1e5;
  c.initial_volume = 1e-3;
  c.inflow = {{0, 1}, {2e-3, 2e-3}, {400, 400}};  // s, kg/s, K
  return c;
}

TEST(ChamberJacobian, PressureSlopeMatchesDifferencesOfTheGasLaws) {
  ChamberGas last;
  last.t = 0.1;
  last.volume = 1e-3;
  last.mass = 1.2e-3;
  last.pressure = 1.1e5;
  last.energy = last.pressure * last.volume / (kGamma - 1);
  last.temperature = last.pressure * last.volume / (last.mass * kR);
  const double t = 0.1005, V = 1.03e-3, h = 1e-9;
  for (const auto& [gas, quasi] : {std::pair{GasModel::Isothermal, false},
                                   {GasModel::Adiabatic, false},
                                   {GasModel::Isothermal, true}}) {
    const ChamberDef c = air(gas);
    const auto p = [&](double v) { return gas_after(c, last, t, v, 0.5, quasi).pressure; };
    const double fd = (p(V + h) - p(V - h)) / (2 * h);
    const double slope = gas_pressure_slope(c, last, t, V, 0.5, quasi);
    EXPECT_LT(slope, 0);
    EXPECT_NEAR(slope / fd, 1, 1e-6) << static_cast<int>(gas) << " quasi-static " << quasi;
  }
  EXPECT_EQ(gas_pressure_slope(pressed_box(1e3).chambers[0], last, t, V, 1, false), 0);
}

TEST(ChamberJacobian, WoodburySolveEqualsTheDenseUpdatedSystem) {
  // A sparse, unsymmetric, diagonally dominant A and two rank-one terms.
  const int n = 40;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 4 + std::sin(i));
    if (i + 1 < n) t.emplace_back(i, i + 1, 0.5 * std::cos(3 * i));
    if (i + 7 < n) t.emplace_back(i + 7, i, -0.3);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  VolumeStiffness terms;
  for (int k = 0; k < 2; ++k) {
    Eigen::VectorXd a(n);
    for (int i = 0; i < n; ++i) a[i] = std::sin(0.37 * (k + 1) * i + k);
    terms.a.push_back(a);
    terms.k.push_back(k == 0 ? 2.5 : 0.7);
  }
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b[i] = std::cos(0.2 * i);
  const double s = 0.8;
  Eigen::MatrixXd dense = Eigen::MatrixXd(A);
  for (int k = 0; k < 2; ++k) dense += s * terms.k[k] * terms.a[k] * terms.a[k].transpose();
  const Eigen::VectorXd expected = dense.fullPivLu().solve(b);
  Eigen::VectorXd x;
  ASSERT_TRUE(solve_with_volume_stiffness(A, s, terms, b, x));
  EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>(), 1e-12 * expected.lpNorm<Eigen::Infinity>());
}

// A 10 cm cube whose lid (free, joined to the fixed walls by 8 bushings of stiffness k) is
// lifted by a quasi-static isothermal gas of mass m: 8 k d = p A with p = m R T / (V0 + A d),
// so A d^2 + V0 d - m R T A / (8 k) = 0, where V0 and A = dV/dd (constant: the walls are
// vertical) are the surface's own, measured by lifting the lid by hand (its bridging strips
// make A 6e-4 larger than the lid's 0.01 m^2). With soft bushings the gas is the stiffer
// spring (p A^2 / V = 84 N/m against 8 k = 40 N/m) and the lid rises by the cube's height.
TEST(ChamberJacobian, LidOnSoftSpringsRisesAsTheGasLawSays) {
  Model m;
  ChamberDef c = air(GasModel::Isothermal);
  c.initial_pressure = 0;
  c.faces = test::add_box(m, 0.1, 0.1, 0.1, true);
  const int lid = c.faces[0].body;  // the top face
  m.bodies[lid].fixed = false;
  const double k = 5, mass = 1e-5;
  // Stiff in rotation: the fanned bridging strips take the pressure unevenly between their
  // corners and would turn the lid about z (1.8e-3 rad with 10 N m/rad, changing V by 3e-4).
  test::join_box_edges(m, c.faces, k, 1e5);
  c.inflow = {{0, 1}, {mass, mass}, {kT, kT}};
  test::add_chamber_and_finish(m, c, 0.1);
  State st = initial_state(m);
  const double V0 = chamber_volume_now(m, st, 0);
  State lifted = st;
  lifted.p_W[lid].z() += 0.05;
  const double A = (chamber_volume_now(m, lifted, 0) - V0) / 0.05;
  SolverSettings set;
  set.kind = SolverKind::Static;
  const SolverStats stats = run_solver(m, st, set, {});
  ASSERT_EQ(stats.status, "ok") << stats.message;
  const double mRT = mass * kR * kT;
  const double d = (-V0 + std::sqrt(V0 * V0 + 4 * A * mRT * A / (8 * k))) / (2 * A);
  const double rise = st.p_W[lid].z() - m.bodies[lid].p0_W.z();
  EXPECT_NEAR(A / 0.01, 1, 1e-3);
  EXPECT_NEAR(rise / d, 1, 1e-6) << stats.newton_iterations << " Newton iterations";
  ::testing::Test::RecordProperty("newton_iterations", std::to_string(stats.newton_iterations));
}

}  // namespace gas_jacobian_test
}  // namespace finseg
