// Sparse linear solves for the Newton iterations (Eigen's SparseLU with COLAMD ordering; the
// ordering and the factor storage are kept between solves of one sparsity pattern).
#pragma once

#include <Eigen/SparseCore>

namespace finseg {

/// Solves A x = b; returns false if A is singular (e.g. an unrestrained mechanism).
bool sparse_solve(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                  Eigen::VectorXd& x);

}  // namespace finseg
