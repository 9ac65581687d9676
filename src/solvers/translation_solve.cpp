// A rotation step taken as a straight line in the pose coordinates opens every joint by its
// second-order mismatch (about theta^2 l / 2): the stiff in-plane springs then carry forces
// many orders above the load (measured: 1e5 times the tip load of the alpha = 2 cantilever
// after the first full step), and a line search on any merit creeps. Balancing the
// translations for the new rotations removes that mismatch before the merit is judged.
#include "solvers/translation_solve.hpp"

#include <vector>

#include "solvers/dofs.hpp"
#include "solvers/linear_solve.hpp"

namespace finseg {
namespace {

// Index of each translational DOF in the translation block (-1 for rotations).
std::vector<int> translation_positions(const Model& model, int& count) {
  std::vector<int> pos(static_cast<std::size_t>(model.num_dofs), -1);
  count = 0;
  for (const int d : model.dof_of_body) {
    if (d < 0) continue;
    for (int k = 0; k < 3; ++k) pos[static_cast<std::size_t>(d + k)] = count++;
  }
  return pos;
}

}  // namespace

bool solve_translations(const Model& model, State& state, BodyForces& f, SolverStats& stats) {
  ForceJacobian jac;
  jac.with_velocity = false;
  compute_forces(model, state, f, &jac);
  ++stats.force_evaluations;
  ++stats.jacobian_evaluations;
  int m = 0;
  const std::vector<int> pos = translation_positions(model, m);
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < jac.dq.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(jac.dq, c); it; ++it) {
      const int r = pos[static_cast<std::size_t>(it.row())];
      const int k = pos[static_cast<std::size_t>(it.col())];
      if (r >= 0 && k >= 0) entries.emplace_back(r, k, -it.value());
    }
  }
  Eigen::SparseMatrix<double> K_tt(m, m);
  K_tt.setFromTriplets(entries.begin(), entries.end());
  const Eigen::VectorXd g = generalized_forces(model, f);
  Eigen::VectorXd g_t(m), dp;
  for (int i = 0; i < model.num_dofs; ++i) {
    if (pos[static_cast<std::size_t>(i)] >= 0) g_t[pos[static_cast<std::size_t>(i)]] = g[i];
  }
  // A conservative model's translation block is symmetric (the skew part of its stiffness is
  // in the rotation blocks only, elements/assemble.hpp): straight to CHOLMOD.
  const bool solved = conservative_stiffness(model)
                          ? sparse_solve(SymmetricMatrix::symmetric_part_of(K_tt), g_t, dp)
                          : sparse_solve(K_tt, g_t, dp);
  if (!solved || !dp.allFinite()) return false;
  Eigen::VectorXd dq = Eigen::VectorXd::Zero(model.num_dofs);
  for (int i = 0; i < model.num_dofs; ++i) {
    if (pos[static_cast<std::size_t>(i)] >= 0) dq[i] = dp[pos[static_cast<std::size_t>(i)]];
  }
  apply_pose_increment(model, state, dq);
  compute_forces(model, state, f);
  ++stats.force_evaluations;
  return true;
}

}  // namespace finseg
