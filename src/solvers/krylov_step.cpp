// Eigen's GMRES with a kept factorization as its preconditioner.
#include "solvers/krylov_step.hpp"

#include <unsupported/Eigen/IterativeSolvers>

namespace finseg {
namespace {

// The preconditioner interface Eigen's iterative solvers call: the factor is made elsewhere
// (kept from an earlier matrix), so analysing and factorising do nothing.
class KeptPreconditioner {
 public:
  KeptPreconditioner() = default;
  template <class MatrixType>
  explicit KeptPreconditioner(const MatrixType&) {}
  void use(const KeptNewtonMatrix& M) { M_ = &M; }
  template <class MatrixType>
  KeptPreconditioner& analyzePattern(const MatrixType&) {
    return *this;
  }
  template <class MatrixType>
  KeptPreconditioner& factorize(const MatrixType&) {
    return *this;
  }
  template <class MatrixType>
  KeptPreconditioner& compute(const MatrixType&) {
    return *this;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd x;
    if (M_ == nullptr || !M_->solve(b, x)) x = Eigen::VectorXd::Constant(b.size(), NAN);
    return x;
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

 private:
  const KeptNewtonMatrix* M_ = nullptr;
};

}  // namespace

bool krylov_solve(const Eigen::SparseMatrix<double>& A, const KeptNewtonMatrix& M,
                  const Eigen::VectorXd& b, const KrylovSettings& s, Eigen::VectorXd& x,
                  int* iterations) {
  if (!M.valid() || A.rows() != b.size()) return false;
  Eigen::GMRES<Eigen::SparseMatrix<double>, KeptPreconditioner> gmres;
  gmres.preconditioner().use(M);
  gmres.set_restart(s.max_iterations);
  gmres.setMaxIterations(s.max_iterations);
  gmres.setTolerance(s.tolerance);
  gmres.compute(A);
  x = gmres.solve(b);
  if (iterations != nullptr) *iterations = static_cast<int>(gmres.iterations());
  return gmres.info() == Eigen::Success && x.allFinite();
}

}  // namespace finseg
