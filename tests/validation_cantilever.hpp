// Shared set-up of the validation tests: the slender cantilever strip, its tip probe and a
// static solve. Only finseg's public API; the references live in elastica_reference.hpp.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "generators/cantilever.hpp"
#include "solvers/dofs.hpp"
#include "solvers/solver.hpp"

namespace finseg::validation {

/// Slender strip (L / t = 1000): shear and stretching are below 1e-7 of the bending
/// deflection, so the shear-free elastica is the reference.
inline CantileverSpec slender_strip(int segments) {
  CantileverSpec s;
  s.length = 0.1;
  s.width = 0.02;
  s.thickness = 1e-4;
  s.youngs_modulus = 4e9;
  s.poisson_ratio = 0.3;
  s.density = 800;
  s.segments = segments;
  return s;
}

/// World position of the named point probe.
inline Vec3 probe_position(const Model& model, const State& state, const std::string& name) {
  for (const ProbeDef& p : model.probes) {
    if (p.name == name && p.kind == ProbeKind::Point) {
      return state.p_W[p.body] + state.R_WB[p.body] * p.point_B;
    }
  }
  ADD_FAILURE() << "no point probe named " << name;
  return Vec3::Constant(NAN);
}

/// Largest speed of any body, m/s: centroid speeds and angular speeds times `length`.
inline double largest_speed(const State& state, double length) {
  double v = 0;
  for (const Vec3& x : state.v_W) v = std::max(v, x.norm());
  for (const Vec3& w : state.w_W) v = std::max(v, w.norm() * length);
  return v;
}

/// Static equilibrium of `model` under its full loads, from the flat initial state.
inline State solve_static(const Model& model, int load_steps = 1) {
  State state = initial_state(model);
  SolverSettings settings;
  settings.kind = SolverKind::Static;
  settings.load_steps = load_steps;
  const SolverStats stats = run_solver(model, state, settings, {});
  EXPECT_EQ(stats.status, "ok") << stats.message;
  return state;
}

/// Tip displacement of the static cantilever from its undeformed position (L, w/2, 0).
inline Vec3 static_tip_displacement(const CantileverSpec& spec, int load_steps = 1) {
  const Model model = build_cantilever_model(spec);
  const State state = solve_static(model, load_steps);
  return probe_position(model, state, "tip") - Vec3(spec.length, 0.5 * spec.width, 0);
}

}  // namespace finseg::validation
