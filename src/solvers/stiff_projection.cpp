// A closed loop of facets (the wall of a cone) moved by a straight step in each facet's
// rotation opens every stiff joint round the loop at second order; rebalancing the
// translations alone (translation_solve) cannot close a loop. Newton on the stiffness with
// its soft directions held by a shift can: the stiff joints' misfit goes, the mechanism's
// position stays.
#include "solvers/stiff_projection.hpp"

#include <cmath>

#include "solvers/dofs.hpp"
#include "solvers/linear_solve.hpp"

namespace finseg {

bool project_on_stiff_directions(const Model& model, State& state, BodyForces& f,
                                 SolverStats& stats, double r_target,
                                 const std::function<double(const BodyForces&)>& residual) {
  double r_prev = INFINITY;
  for (int k = 0; k < kProjections; ++k) {
    ForceJacobian jac;
    jac.with_velocity = false;
    compute_forces(model, state, f, &jac);
    ++stats.force_evaluations;
    ++stats.jacobian_evaluations;
    const double r = residual(f);
    if (!(r < r_prev)) return false;
    if (r < r_target) return true;
    r_prev = r;
    const SymmetricMatrix S = SymmetricMatrix::symmetric_part_of(-jac.dq);
    Eigen::VectorXd dq;
    if (!sparse_solve(S.plus_diagonal(kStiffShift * S.shift_scale()), generalized_forces(model, f),
                      dq)) {
      return false;
    }
    apply_pose_increment(model, state, dq);
  }
  compute_forces(model, state, f);
  ++stats.force_evaluations;
  return std::isfinite(residual(f));
}

}  // namespace finseg
