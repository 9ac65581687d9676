#include "solvers/linear_solve.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseLU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

namespace finseg {
namespace {

using SpMat = Eigen::SparseMatrix<double>;
using SparseLU = Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>>;

// kSymmetricAsymmetry: systems up to this asymmetry ratio ||A - A^T||_F / ||A||_F are
// symmetric up to the round-off of the assembly (measured below 1e-16 on symmetric tangents)
// and go to CHOLMOD. Not more: the left-trivialised rotation Jacobian has a skew part of the
// size of the out-of-balance torque, and refining on the symmetric part's factor, tried up to
// 1e-2, converged on few of the zigzag pulls' matrices (ratios 1e-10 to 1e-2; most fell back
// to LU after the wasted factorization, and the tests took about three times as long).
// Refinement stops when the componentwise backward error max_i |b - A x|_i / (|A| |x| + |b|)_i
// (Oettli-Prager) is below kTargetError, stops decreasing by half, or after kMaxRefinements
// steps; the solution is accepted (else LU decides) if it is below kBackwardError. The
// componentwise measure matters: a normwise one is dominated by the stiff in-plane springs
// and passes solutions whose bending part is wrong in the fourth digit.
constexpr double kTargetError = 4 * std::numeric_limits<double>::epsilon();
constexpr double kBackwardError = 1e-14;
constexpr int kMaxRefinements = 20;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Runs `analyse` and `factorize`, counting both in linear_solve_counters().
template <class Analyse, class Factorize>
void timed(bool analyse_first, Analyse analyse, Factorize factorize) {
  LinearSolveCounters& c = linear_solve_counters();
  auto t = Clock::now();
  if (analyse_first) {
    analyse();
    ++c.analyses;
    c.analyse_s += seconds_since(t);
    t = Clock::now();
  }
  factorize();
  ++c.factorizations;
  c.factor_s += seconds_since(t);
}

// Newton iterations solve long runs of systems with one sparsity pattern: the symbolic
// analysis (fill-reducing ordering) is kept while the pattern stays.
struct Pattern {
  Eigen::VectorXi outer, inner;
  bool set = false;

  bool same(const SpMat& A) const {
    if (!set || outer.size() != A.outerSize() + 1 || inner.size() != A.nonZeros()) return false;
    return std::equal(outer.data(), outer.data() + outer.size(), A.outerIndexPtr()) &&
           std::equal(inner.data(), inner.data() + inner.size(), A.innerIndexPtr());
  }
  void remember(const SpMat& A) {
    outer = Eigen::Map<const Eigen::VectorXi>(A.outerIndexPtr(), A.outerSize() + 1);
    inner = Eigen::Map<const Eigen::VectorXi>(A.innerIndexPtr(), A.nonZeros());
    set = true;
  }
};

// CHOLMOD on the lower triangle, silent (a failed Cholesky is an expected event here).
class Cholmod : public Eigen::CholmodDecomposition<SpMat, Eigen::Lower> {
 public:
  explicit Cholmod(Eigen::CholmodMode mode) {
    setMode(mode);
    cholmod().print = 0;
  }
  bool is_ll() const { return m_cholmodFactor != nullptr && m_cholmodFactor->is_ll != 0; }
};

struct LuCache {
  SparseLU lu;
  Pattern pattern;
};

// CHOLMOD chooses simplicial L D L^T for small systems and supernodal L L^T (BLAS) for
// large ones; the latter cannot factor an indefinite matrix, which then goes to `ldlt`.
struct SymmetricCache {
  Cholmod automatic{Eigen::CholmodAuto};
  Cholmod ldlt{Eigen::CholmodLDLt};
  Pattern automatic_pattern, ldlt_pattern;
};

bool factor(Cholmod& f, Pattern& pattern, const SpMat& S) {
  const bool analyse = !pattern.same(S);
  if (analyse) pattern.remember(S);
  timed(
      analyse, [&] { f.analyzePattern(S); }, [&] { f.factorize(S); });
  return f.info() == Eigen::Success;
}

// Componentwise backward error of x (0 where a row of |A| |x| + |b| is zero and so is r).
double backward_error(const SpMat& A_abs, const Eigen::VectorXd& b, const Eigen::VectorXd& x,
                      const Eigen::VectorXd& r) {
  const Eigen::VectorXd w = A_abs * x.cwiseAbs() + b.cwiseAbs();
  double e = 0;
  for (int i = 0; i < r.size(); ++i) {
    if (r[i] != 0) e = std::max(e, w[i] > 0 ? std::abs(r[i]) / w[i] : INFINITY);
  }
  return e;
}

// Solves with the factor of the symmetric part and refines against A, keeping the iterate of
// least backward error (a last step can undo some of the gain: 4.9e-15 -> 1.6e-14 on a
// generalized-alpha matrix of a sheet); returns that error (INFINITY: no finite iterate, x
// undefined).
double refined_solve(const Cholmod& f, const SpMat& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                     int& steps) {
  const SpMat A_abs = A.cwiseAbs();
  x = f.solve(b);
  Eigen::VectorXd best;
  double e_best = INFINITY;
  for (steps = 0;; ++steps) {
    if (!x.allFinite()) break;
    const Eigen::VectorXd r = b - A * x;
    const double e = backward_error(A_abs, b, x, r);
    const double e_prev = e_best;
    if (e < e_best) e_best = e, best = x;
    if (e <= kTargetError || steps == kMaxRefinements || e > 0.5 * e_prev) break;
    x += f.solve(r);
  }
  if (e_best < INFINITY) x = best;
  return e_best;
}

bool lu_solve(const SpMat& A, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  thread_local LuCache cache;
  const bool analyse = !cache.pattern.same(A);
  if (analyse) cache.pattern.remember(A);
  timed(
      analyse, [&] { cache.lu.analyzePattern(A); }, [&] { cache.lu.factorize(A); });
  ++linear_solve_counters().lu_factorizations;
  if (cache.lu.info() != Eigen::Success) return false;
  x = cache.lu.solve(b);
  return cache.lu.info() == Eigen::Success && x.allFinite();
}

// The symmetric path; nullopt if it does not apply (the factorization or the refinement
// failed), so that LU decides.
// `exactly_symmetric`: asymmetry 0 (a Newton matrix that is its own symmetric part). Its
// symmetric part is still formed: its pattern may not be symmetric (a stored zero), and
// factoring such a matrix directly crashed CHOLMOD (ContactDynamics.StaticSolverHoldsAPlate...).
std::optional<LinearSolvePath> symmetric_solve(const SpMat& A, bool exactly_symmetric,
                                               const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                               int& steps) {
  thread_local SymmetricCache cache;
  const SpMat S = symmetric_part(A);  // also for a symmetric A: a symmetric pattern
  if (factor(cache.automatic, cache.automatic_pattern, S)) {
    // L L^T of a positive definite matrix is backward stable: for an exactly symmetric A, LU
    // would add fill, not accuracy, where the refinement stalls just above kBackwardError
    // (1.7e-14 on a generalized-alpha matrix of a 10^4-segment sheet; at 10^5 the LU took
    // more than 8 GB).
    const bool ll = cache.automatic.is_ll();
    const double e = refined_solve(cache.automatic, A, b, x, steps);
    if (e > kBackwardError && !(ll && exactly_symmetric && e < INFINITY)) return std::nullopt;
    return ll ? LinearSolvePath::Cholesky : LinearSolvePath::LDLT;
  }
  // L L^T met a non-positive pivot (indefinite); L D L^T failed only on an exact zero pivot.
  if (!cache.automatic.is_ll()) return std::nullopt;
  ++linear_solve_counters().indefinite;
  if (factor(cache.ldlt, cache.ldlt_pattern, S) &&
      refined_solve(cache.ldlt, A, b, x, steps) <= kBackwardError) {
    return LinearSolvePath::LDLT;
  }
  return std::nullopt;
}

}  // namespace

LinearSolveCounters& linear_solve_counters() {
  thread_local LinearSolveCounters counters;
  return counters;
}

SpMat symmetric_part(const SpMat& A) {
  SpMat S = SpMat(A.transpose()) + A;  // pattern of A + A^T, kept even where values cancel
  S *= 0.5;
  return S;
}

double asymmetry_ratio(const SpMat& A) {
  const double A_norm = A.norm();
  if (A_norm == 0) return 0;
  return (A - SpMat(A.transpose())).norm() / A_norm;
}

namespace {

bool solve_system(const SpMat& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                  LinearSolveInfo* info) {
  SpMat Ac = A;
  Ac.makeCompressed();
  // Eigen's SparseLU never returns on subnormal entries (a modulus of 1e-320 Pa made them):
  // they are zero for every purpose here. A non-finite entry has no solution.
  for (double* v = Ac.valuePtr(); v != Ac.valuePtr() + Ac.nonZeros(); ++v) {
    if (!std::isfinite(*v)) return false;
    if (std::abs(*v) < std::numeric_limits<double>::min()) *v = 0;
  }
  if (!b.allFinite()) return false;
  LinearSolveInfo report;
  report.asymmetry = asymmetry_ratio(Ac);
  bool ok = false;
  if (Ac.rows() > 0 && Ac.rows() == Ac.cols() && report.asymmetry <= kSymmetricAsymmetry) {
    if (const auto path = symmetric_solve(Ac, report.asymmetry == 0, b, x, report.refinements)) {
      report.path = *path;
      ok = true;
    }
  }
  if (!ok) {
    report.path = LinearSolvePath::LU;
    ok = lu_solve(Ac, b, x);
  }
  if (info != nullptr) *info = report;
  return ok;
}

}  // namespace

bool sparse_solve(const SpMat& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                  LinearSolveInfo* info) {
  const auto t0 = Clock::now();
  ++linear_solve_counters().solves;
  const bool ok = solve_system(A, b, x, info);
  linear_solve_counters().total_s += seconds_since(t0);
  return ok;
}

}  // namespace finseg
