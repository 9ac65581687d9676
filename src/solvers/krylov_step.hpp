// A Newton step by GMRES on the present iteration matrix, preconditioned by a kept
// factorization: where a kept matrix has gone stale (it no longer contracts), its factor may
// still be a good preconditioner of the new matrix, and a few Krylov iterations (each a sparse
// product and two triangular solves) cost less than the new factorization a modified Newton
// iteration would make (docs/solvers.md, "Krylov steps on a kept factor").
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "solvers/volume_stiffness.hpp"

namespace finseg {

/// GMRES settings of a Krylov step: it stands for an exact Newton step only when it converges
/// well within `max_iterations`, to `tolerance` of the preconditioned residual.
struct KrylovSettings {
  int max_iterations = 10;
  double tolerance = 1e-3;
};

/// Solves A x = b by GMRES (Eigen's, without restart) left-preconditioned by the kept factor
/// `M`; true, with x, when the preconditioned residual fell below `s.tolerance` relative to
/// its start within `s.max_iterations` (their number in `iterations` when given).
bool krylov_solve(const Eigen::SparseMatrix<double>& A, const KeptNewtonMatrix& M,
                  const Eigen::VectorXd& b, const KrylovSettings& s, Eigen::VectorXd& x,
                  int* iterations = nullptr);

}  // namespace finseg
