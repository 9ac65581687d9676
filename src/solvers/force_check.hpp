// The force Jacobian the implicit and static solvers build (compute_forces' dF/dq and dF/dv,
// and the gas's rank-one terms) checked against central differences of the forces at a state.
// A force that jumps (Newton cannot cross it: the implicit solver's steps then crawl) shows as
// a difference that grows as the step shrinks; a wrong Jacobian as one that stays; curvature
// as one that shrinks (docs/solvers.md, "Contact: why the implicit solver crawled").
#pragma once

#include <Eigen/Core>
#include <vector>

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// What the difference between an entry of the Jacobian and its central differences does as
/// the step shrinks tenfold.
enum class ForceMismatchKind { Jump, Inexact, Curvature };

/// One entry of the force Jacobian that central differences disagree with.
struct ForceMismatch {
  int body = -1;          ///< the body the force acts on
  int dof = 0;            ///< 0-2 force, 3-5 moment (world axes)
  int perturbed = -1;     ///< the body moved
  int perturbed_dof = 0;  ///< 0-2 translation, 3-5 rotation (world axes)
  bool velocity = false;  ///< d/dv (else d/d pose)
  double jacobian = 0;    ///< the solvers' entry
  double coarse = 0;      ///< central difference at the step h
  double fine = 0;        ///< central difference at h / 10
  ForceMismatchKind kind = ForceMismatchKind::Curvature;
};

/// Central difference of the generalized forces (compute_forces) along degree of freedom
/// `dof`, of step h: of the poses (m, rad) or, with `velocity`, of the velocities (m/s, rad/s).
Eigen::VectorXd force_difference(const Model& model, const State& state, int dof, double h,
                                 bool velocity);

/// The entries (forces, pose and velocity columns) where a central difference at step h (m,
/// rad, m/s, rad/s) or h / 10 differs from the Jacobian by more than `tolerance` of the entry's
/// size plus 1e-9 of the Jacobian's largest entry, at most one per pair of bodies and kind of
/// column (the largest), jumps first, then inexact entries, then curvature, largest first in
/// each. Costs eight force evaluations per degree of freedom.
std::vector<ForceMismatch> check_force_jacobian(const Model& model, const State& state, double h,
                                                double tolerance = 1e-3);

/// "jump", "inexact" or "curvature".
const char* to_string(ForceMismatchKind kind);

}  // namespace finseg
