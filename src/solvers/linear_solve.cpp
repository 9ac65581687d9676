#include "solvers/linear_solve.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace finseg {
namespace {

using SparseLU = Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>>;

// Newton iterations solve long runs of systems with one sparsity pattern: the fill-reducing
// ordering is kept while the pattern stays, and the factor's storage is reused.
struct FactorCache {
  SparseLU lu;
  Eigen::VectorXi outer, inner;
  bool analysed = false;

  bool same_pattern(const Eigen::SparseMatrix<double>& A) const {
    if (!analysed || outer.size() != A.outerSize() + 1 || inner.size() != A.nonZeros()) {
      return false;
    }
    return std::equal(outer.data(), outer.data() + outer.size(), A.outerIndexPtr()) &&
           std::equal(inner.data(), inner.data() + inner.size(), A.innerIndexPtr());
  }
  void remember_pattern(const Eigen::SparseMatrix<double>& A) {
    outer = Eigen::Map<const Eigen::VectorXi>(A.outerIndexPtr(), A.outerSize() + 1);
    inner = Eigen::Map<const Eigen::VectorXi>(A.innerIndexPtr(), A.nonZeros());
    analysed = true;
  }
};

}  // namespace

bool sparse_solve(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                  Eigen::VectorXd& x) {
  thread_local FactorCache cache;
  Eigen::SparseMatrix<double> Ac = A;
  Ac.makeCompressed();
  // Eigen's SparseLU never returns on subnormal entries (a modulus of 1e-320 Pa made them):
  // they are zero for every purpose here. A non-finite entry has no solution.
  for (double* v = Ac.valuePtr(); v != Ac.valuePtr() + Ac.nonZeros(); ++v) {
    if (!std::isfinite(*v)) return false;
    if (std::abs(*v) < std::numeric_limits<double>::min()) *v = 0;
  }
  if (!b.allFinite()) return false;
  if (!cache.same_pattern(Ac)) {
    cache.lu.analyzePattern(Ac);
    cache.remember_pattern(Ac);
  }
  cache.lu.factorize(Ac);
  if (cache.lu.info() != Eigen::Success) return false;
  x = cache.lu.solve(b);
  return cache.lu.info() == Eigen::Success && x.allFinite();
}

}  // namespace finseg
