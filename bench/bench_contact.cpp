// Contact detection cost against the number of segments: stacks of sheets (10 layers of a
// square grid of 5 mm segments, each sheet resting on the one below with small random
// offsets and tilts), so that the number of touching pairs grows like n. Reports the
// fitted complexity (expected: n log n from the broad phase's sort, or better). Also the
// contact forces alone and with their Jacobian (poses and velocities), closed form against
// the automatic differentiation it replaced, on the same stacks sliding with continuous
// friction.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "collision/contact_forces.hpp"
#include "elements/assembler.hpp"

namespace finseg {
namespace {

struct Scene {
  Model model;
  State state;
};

Scene make_scene(int n) {
  Scene sc;
  const int layers = 10;
  const int side = std::max(1, static_cast<int>(std::lround(std::sqrt(n / double(layers)))));
  const double L = 5e-3, t = 1e-4, pitch = 1.1 * L;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> jitter(-0.2e-3, 0.2e-3), tilt(-0.01, 0.01);
  int made = 0;
  for (int k = 0; k < layers && made < n; ++k)
    for (int i = 0; i < side && made < n; ++i)
      for (int j = 0; j < side + 1 && made < n; ++j, ++made) {
        BodyDef b;
        set_box(b, Vec3(L, L, t), 2e-6);
        b.J_B = Mat3::Identity() * 1e-12;
        b.fixed = k == 0;
        b.panel = k;
        sc.model.bodies.push_back(b);
        sc.state.p_W.push_back(
            Vec3(i * pitch + jitter(rng), j * pitch + jitter(rng), k * 0.97 * t));
        sc.state.R_WB.push_back(
            Eigen::AngleAxisd(tilt(rng), Vec3(tilt(rng), tilt(rng), 1).normalized())
                .toRotationMatrix());
        sc.state.v_W.push_back(Vec3::Zero());
        sc.state.w_W.push_back(Vec3::Zero());
      }
  sc.model.contact.enabled = true;
  sc.model.contact.stiffness = 1e5;
  sc.model.finalize_dofs();
  return sc;
}

void BM_ContactDetection(benchmark::State& st) {
  const Scene sc = make_scene(static_cast<int>(st.range(0)));
  int active = 0;
  for (auto _ : st) {
    const ContactSummary s = contact_summary(sc.model, sc.state);
    active = s.active;
    benchmark::DoNotOptimize(active);
  }
  st.counters["contact_points"] = active;
  st.SetComplexityN(st.range(0));
}
BENCHMARK(BM_ContactDetection)
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Arg(3000)
    ->Arg(30000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oNLogN);

// The stacks with continuous friction, every free plate moving a little (m/s, rad/s).
Scene sliding_scene(int n) {
  Scene sc = make_scene(n);
  sc.model.contact.friction = FrictionModel::Continuous;
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> v(-1e-3, 1e-3), w(-0.1, 0.1);
  for (std::size_t i = 0; i < sc.model.bodies.size(); ++i) {
    if (sc.model.bodies[i].fixed) continue;
    sc.state.v_W[i] = Vec3(v(rng), v(rng), v(rng));
    sc.state.w_W[i] = Vec3(w(rng), w(rng), w(rng));
  }
  return sc;
}

// jacobian: 0 forces only, 1 closed form, 2 automatic differentiation; range(1): 1 with the
// velocity columns (implicit solver), 0 poses only (static solver).
void contact_forces_bench(benchmark::State& st, int jacobian) {
  const Scene sc = sliding_scene(static_cast<int>(st.range(0)));
  BodyForces f;
  ForceJacobian jac;
  jac.autodiff = jacobian == 2;
  jac.with_velocity = st.range(1) != 0;
  for (auto _ : st) {
    f.f_W.assign(sc.model.bodies.size(), Vec3::Zero());
    f.tau_W.assign(sc.model.bodies.size(), Vec3::Zero());
    Assembler as(sc.model, sc.state, f, jacobian > 0 ? &jac : nullptr);
    add_contact_forces(sc.model, sc.state, as);
    benchmark::DoNotOptimize(f.f_W.data());
  }
  st.counters["contact_points"] = contact_summary(sc.model, sc.state).active;
}
void BM_ContactForces(benchmark::State& st) {
  contact_forces_bench(st, 0);
}
void BM_ContactForcesJacobianClosedForm(benchmark::State& st) {
  contact_forces_bench(st, 1);
}
void BM_ContactForcesJacobianAutodiff(benchmark::State& st) {
  contact_forces_bench(st, 2);
}
BENCHMARK(BM_ContactForces)->Args({1000, 1})->Args({10000, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ContactForcesJacobianClosedForm)
    ->ArgsProduct({{1000, 10000}, {1, 0}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ContactForcesJacobianAutodiff)
    ->ArgsProduct({{1000, 10000}, {1, 0}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace finseg

BENCHMARK_MAIN();
