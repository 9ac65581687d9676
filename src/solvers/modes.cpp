// Small-vibration analysis: natural frequencies from K x = w^2 M x, and the highest
// frequency that bounds the explicit step.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "solvers/dofs.hpp"
#include "solvers/integrators.hpp"
#include "solvers/modes.hpp"

namespace finseg {
namespace {

Eigen::SparseMatrix<double> stiffness_matrix(const Model& model, const State& state) {
  BodyForces f;
  ForceJacobian jac;
  compute_forces(model, state, f, &jac);
  Eigen::SparseMatrix<double> K = -jac.dq;
  return Eigen::SparseMatrix<double>(0.5 * (K + Eigen::SparseMatrix<double>(K.transpose())));
}

// Dense generalized eigensolver of K x = w^2 M x (eigenvalues ascending).
Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modal_solve(const Model& model,
                                                                      const State& state,
                                                                      int options) {
  if (model.num_dofs > 6000) {
    throw InputError(model.source, "modes", "dense modal analysis is limited to 1000 segments");
  }
  const Eigen::MatrixXd K = stiffness_matrix(model, state);
  const Eigen::MatrixXd M = mass_matrix(model, state);
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(K, M, options);
}

double hz_of(double eigenvalue) {
  return std::sqrt(std::max(0.0, eigenvalue)) / (2 * kPi);
}

}  // namespace

std::vector<double> natural_frequencies(const Model& model, const State& state, int count) {
  if (model.num_dofs == 0) return {};
  const auto es = modal_solve(model, state, Eigen::EigenvaluesOnly);
  std::vector<double> hz;
  for (int i = 0; i < es.eigenvalues().size() && static_cast<int>(hz.size()) < count; ++i) {
    hz.push_back(hz_of(es.eigenvalues()[i]));
  }
  return hz;
}

std::vector<Mode> natural_modes(const Model& model, const State& state, int count) {
  if (model.num_dofs == 0) return {};
  const auto es = modal_solve(model, state, Eigen::ComputeEigenvectors);
  std::vector<Mode> modes;
  for (int i = 0; i < es.eigenvalues().size() && static_cast<int>(modes.size()) < count; ++i) {
    modes.push_back({hz_of(es.eigenvalues()[i]), es.eigenvectors().col(i)});
  }
  return modes;
}

double highest_frequency(const Model& model, const State& state) {
  if (model.num_dofs == 0) return 0;
  const Eigen::SparseMatrix<double> K = stiffness_matrix(model, state);
  const Eigen::SparseMatrix<double> M = mass_matrix(model, state);
  // Power iteration on M^-1 K (M is block diagonal, so its inverse is cheap and exact).
  Eigen::SparseMatrix<double> Minv(model.num_dofs, model.num_dofs);
  {
    std::vector<Eigen::Triplet<double>> t;
    for (int d = 0; d < model.num_dofs; d += 6) {
      const Mat3 Jinv = Eigen::MatrixXd(M.block(d + 3, d + 3, 3, 3)).inverse();
      for (int r = 0; r < 3; ++r) {
        t.emplace_back(d + r, d + r, 1.0 / M.coeff(d + r, d + r));
        for (int c = 0; c < 3; ++c) t.emplace_back(d + 3 + r, d + 3 + c, Jinv(r, c));
      }
    }
    Minv.setFromTriplets(t.begin(), t.end());
  }
  Eigen::VectorXd x(model.num_dofs);
  for (int i = 0; i < x.size(); ++i) x[i] = 1.0 + 0.37 * std::sin(1.7 * i);  // deterministic
  double lambda = 0;
  for (int it = 0; it < 200; ++it) {
    const Eigen::VectorXd y = Minv * (K * x);
    const double n = y.norm();
    if (!(n > 0)) return 0;
    const double next = x.dot(K * x) / x.dot(M * x);
    x = y / n;
    if (it > 20 && std::abs(next - lambda) < 1e-4 * std::abs(next)) {
      lambda = next;
      break;
    }
    lambda = next;
  }
  // Power iteration approaches from below: keep a margin.
  return 1.1 * std::sqrt(std::max(lambda, 0.0));
}

}  // namespace finseg
