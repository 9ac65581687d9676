#include "solvers/linear_solve.hpp"

#include <Eigen/SparseLU>

namespace finseg {

bool sparse_solve(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                  Eigen::VectorXd& x) {
  Eigen::SparseMatrix<double> Ac = A;
  Ac.makeCompressed();
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(Ac);
  if (lu.info() != Eigen::Success) return false;
  x = lu.solve(b);
  return lu.info() == Eigen::Success && x.allFinite();
}

}  // namespace finseg
