// Undamped free vibration of a cantilever released from a large static deflection:
// the explicit solver conserves energy up to a bounded, non-drifting error; the implicit
// (backward Euler) solver never gains energy; generalized-alpha with rho_inf = 1 keeps it
// without drift.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "elastica_reference.hpp"
#include "validation_cantilever.hpp"

namespace finseg {
namespace validation_energy_test {

// L / t = 100 keeps the explicit step (set by the stretching springs) affordable.
CantileverSpec strip(int segments = 16) {
  CantileverSpec s = validation::slender_strip(segments);
  s.thickness = 1e-3;
  s.tip_force = Vec3(0, 0, -2 * bending_rigidity(s) / (s.length * s.length));  // alpha = 2
  return s;
}

double first_period(const CantileverSpec& s) {
  return 2 * std::numbers::pi /
         reference::cantilever_omega(1, s.length, bending_rigidity(s),
                                     s.density * s.width * s.thickness);
}

// Total energy (kinetic + elastic) at every output of a free run released from the
// static deflection under the tip load.
std::vector<double> released_energy(SolverKind kind, double periods,
                                    ImplicitScheme scheme = ImplicitScheme::BackwardEuler,
                                    int segments = 16) {
  const CantileverSpec s = strip(segments);
  const Model model = build_cantilever_model(s);
  State state = validation::solve_static(model);
  state.load_scale = 0;  // release: the load is gone, nothing damps
  state.t = 0;
  SolverSettings settings;
  settings.kind = kind;
  settings.scheme = scheme;
  settings.rho_inf = 1;
  settings.t_end = periods * first_period(s);
  settings.output_interval = settings.t_end / 300;
  settings.rtol = 1e-3;
  std::vector<double> energy;
  const SolverStats stats =
      run_solver(model, state, settings, [&](const State& x, const BodyForces& f) {
        energy.push_back(kinetic_energy(model, x) + f.potential_energy);
      });
  EXPECT_EQ(stats.status, "ok") << stats.message;
  return energy;
}

double mean(std::vector<double>::const_iterator a, std::vector<double>::const_iterator b) {
  return std::accumulate(a, b, 0.0) / static_cast<double>(b - a);
}

TEST(EnergyConservation, ExplicitErrorBoundedWithoutDrift) {
  const std::vector<double> e = released_energy(SolverKind::Explicit, 3);
  ASSERT_GT(e.size(), 290u);
  const double e0 = e.front();
  double worst = 0;
  for (double x : e) worst = std::max(worst, std::abs(x - e0) / e0);
  const size_t third = e.size() / 3;
  const double drift = (mean(e.end() - third, e.end()) - mean(e.begin(), e.begin() + third)) / e0;
  std::printf("explicit: worst energy error %.3e E0, drift first->last third %.3e E0\n", worst,
              drift);
  // Verlet's energy error is O((omega dt)^2) in the excited modes and does not accumulate.
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(std::abs(drift), 1e-5);
}

TEST(EnergyConservation, ImplicitNeverGainsEnergy) {
  const std::vector<double> e = released_energy(SolverKind::Implicit, 1);
  ASSERT_GT(e.size(), 290u);
  for (size_t i = 1; i < e.size(); ++i) {
    EXPECT_LE(e[i], e[i - 1] * (1 + 1e-12)) << "output " << i;
  }
  std::printf("implicit: energy after one period %.4f E0\n", e.back() / e.front());
  // Backward Euler dissipates, but a run this accurate keeps most of the energy.
  EXPECT_GT(e.back(), 0.5 * e.front());
}

// Generalized-alpha without numerical dissipation (rho_inf = 1) on the same nonlinear
// release: the energy error stays bounded by the local error control and does not drift.
TEST(EnergyConservation, GeneralizedAlphaBoundedWithoutDrift) {
  const std::vector<double> e =
      released_energy(SolverKind::Implicit, 1.5, ImplicitScheme::GeneralizedAlpha, 8);
  ASSERT_GT(e.size(), 290u);
  const double e0 = e.front();
  double worst = 0;
  for (double x : e) worst = std::max(worst, std::abs(x - e0) / e0);
  const size_t third = e.size() / 3;
  const double drift = (mean(e.end() - third, e.end()) - mean(e.begin(), e.begin() + third)) / e0;
  std::printf("generalized-alpha rho_inf 1: worst energy error %.3e E0, drift %.3e E0\n", worst,
              drift);
  EXPECT_LT(worst, 5e-4);
  EXPECT_LT(std::abs(drift), 2e-4);
}

}  // namespace validation_energy_test
}  // namespace finseg
