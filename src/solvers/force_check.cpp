#include "solvers/force_check.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "elements/assemble.hpp"
#include "solvers/dofs.hpp"
#include "solvers/volume_stiffness.hpp"

namespace finseg {
namespace {

// Per dof, the body that holds it.
std::vector<int> bodies_of_dofs(const Model& model) {
  std::vector<int> body(model.num_dofs, -1);
  for (std::size_t i = 0; i < model.bodies.size(); ++i) {
    const int first = model.dof_of_body[i];
    for (int k = 0; first >= 0 && k < 6; ++k) body[first + k] = static_cast<int>(i);
  }
  return body;
}

// Jumps first, then inexact entries, then curvature; the largest disagreement first in each.
bool listed_before(const ForceMismatch& a, const ForceMismatch& b) {
  const auto rank = [](ForceMismatchKind k) {
    return k == ForceMismatchKind::Jump ? 0 : k == ForceMismatchKind::Inexact ? 1 : 2;
  };
  if (rank(a.kind) != rank(b.kind)) return rank(a.kind) < rank(b.kind);
  return std::abs(a.fine - a.jacobian) > std::abs(b.fine - b.jacobian);
}

ForceMismatchKind kind_of(double coarse_gap, double fine_gap) {
  if (fine_gap > 3 * coarse_gap) return ForceMismatchKind::Jump;
  if (fine_gap < 0.3 * coarse_gap) return ForceMismatchKind::Curvature;
  return ForceMismatchKind::Inexact;
}

Eigen::VectorXd forces_at(const Model& model, const State& state) {
  BodyForces f;
  compute_forces(model, state, f);
  return generalized_forces(model, f);
}

}  // namespace

Eigen::VectorXd force_difference(const Model& model, const State& state, int dof, double h,
                                 bool velocity) {
  State a = state, b = state;
  Eigen::VectorXd e = Eigen::VectorXd::Zero(model.num_dofs);
  e[dof] = h;
  if (velocity) {
    const Eigen::VectorXd v = velocity_vector(model, state);
    set_velocity(model, a, v + e);
    set_velocity(model, b, v - e);
  } else {
    apply_pose_increment(model, a, e);
    apply_pose_increment(model, b, -e);
  }
  return (forces_at(model, a) - forces_at(model, b)) / (2 * h);
}

std::vector<ForceMismatch> check_force_jacobian(const Model& model, const State& state, double h,
                                                double tolerance) {
  BodyForces f;
  ForceJacobian jac;
  compute_forces(model, state, f, &jac);
  // The gas's pressure follows the volume: slope a a^T with a = dV/dq (volume_stiffness.hpp).
  const VolumeStiffness gas = volume_stiffness(model, state);
  const auto largest = [](const Eigen::SparseMatrix<double>& A) {
    return A.nonZeros() > 0 ? A.coeffs().cwiseAbs().maxCoeff() : 0.0;
  };
  const double scale = std::max(largest(jac.dq), largest(jac.dv));
  const std::vector<int> body_of = bodies_of_dofs(model);
  // The largest mismatch per (body, perturbed body, velocity).
  std::map<std::tuple<int, int, bool>, ForceMismatch> worst;
  for (const bool velocity : {false, true}) {
    for (int c = 0; c < model.num_dofs; ++c) {
      const Eigen::SparseMatrix<double>& D = velocity ? jac.dv : jac.dq;
      Eigen::VectorXd J = Eigen::VectorXd::Zero(model.num_dofs);
      if (D.cols() == model.num_dofs) J = D.col(c);
      if (!velocity) {
        for (std::size_t k = 0; k < gas.a.size(); ++k) J -= gas.k[k] * gas.a[k][c] * gas.a[k];
      }
      const Eigen::VectorXd coarse = force_difference(model, state, c, h, velocity);
      const Eigen::VectorXd fine = force_difference(model, state, c, 0.1 * h, velocity);
      for (int r = 0; r < model.num_dofs; ++r) {
        const double gap_c = std::abs(coarse[r] - J[r]), gap_f = std::abs(fine[r] - J[r]);
        const double allowed = tolerance * std::abs(J[r]) + 1e-9 * scale;
        if (std::max(gap_c, gap_f) <= allowed) continue;
        const int body = body_of[r], moved = body_of[c];
        const ForceMismatch m{body,
                              r - model.dof_of_body[body],
                              moved,
                              c - model.dof_of_body[moved],
                              velocity,
                              J[r],
                              coarse[r],
                              fine[r],
                              kind_of(gap_c, gap_f)};
        ForceMismatch& w = worst[{body, moved, velocity}];
        if (w.body < 0 || std::abs(m.fine - m.jacobian) > std::abs(w.fine - w.jacobian)) w = m;
      }
    }
  }
  std::vector<ForceMismatch> out;
  for (const auto& [key, m] : worst) out.push_back(m);
  std::sort(out.begin(), out.end(), listed_before);
  return out;
}

const char* to_string(ForceMismatchKind kind) {
  switch (kind) {
    case ForceMismatchKind::Jump:
      return "jump";
    case ForceMismatchKind::Inexact:
      return "inexact";
    default:
      return "curvature";
  }
}

}  // namespace finseg
