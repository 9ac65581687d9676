#include "solvers/linear_solve.hpp"

#include <umfpack.h>

#include <Eigen/CholmodSupport>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "core/blas_kernels.hpp"
#include "solvers/block_ordering.hpp"
#include "solvers/single_precision_factor.hpp"

namespace finseg {
namespace {

using SpMat = Eigen::SparseMatrix<double>;

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

// A sparsity pattern (compressed column storage), with a hash that rules out most other
// patterns before the full comparison.
struct Pattern {
  Eigen::VectorXi outer, inner;
  std::uint64_t hash = 0;

  static std::uint64_t hash_of(const SpMat& A) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a
    const auto mix = [&h](int v) { h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ull; };
    mix(static_cast<int>(A.rows()));
    for (Eigen::Index k = 0; k <= A.outerSize(); ++k) mix(A.outerIndexPtr()[k]);
    for (Eigen::Index k = 0; k < A.nonZeros(); ++k) mix(A.innerIndexPtr()[k]);
    return h;
  }
  bool same(const SpMat& A, std::uint64_t h) const {
    if (h != hash || outer.size() != A.outerSize() + 1 || inner.size() != A.nonZeros()) {
      return false;
    }
    return std::equal(outer.data(), outer.data() + outer.size(), A.outerIndexPtr()) &&
           std::equal(inner.data(), inner.data() + inner.size(), A.innerIndexPtr());
  }
  void remember(const SpMat& A, std::uint64_t h) {
    outer = Eigen::Map<const Eigen::VectorXi>(A.outerIndexPtr(), A.outerSize() + 1);
    inner = Eigen::Map<const Eigen::VectorXi>(A.innerIndexPtr(), A.nonZeros());
    hash = h;
  }
};

// The factorizations of the last kCachedPatterns patterns, most recent first: a Newton run
// alternates few patterns (the stiffness and the line search's translation block), and each
// keeps its symbolic analysis. Only the front slot keeps its numeric factor: every slot_for
// is followed by a factorization, so a slot behind the front would be refactored before its
// factor is used again (at 10^4 segments a factor is about 240 MB). `Slot` holds a Pattern
// `pattern` and the factorization objects, and frees their numeric part in release_numeric().
template <class Slot>
class PatternCache {
 public:
  // The slot of A's pattern; `fresh`: newly made (its factorizations need an analysis).
  Slot& slot_for(const SpMat& A, bool& fresh) {
    const std::uint64_t h = Pattern::hash_of(A);
    for (auto it = slots_.begin(); it != slots_.end(); ++it) {
      if ((*it)->pattern.same(A, h)) {
        if (it != slots_.begin()) slots_.front()->release_numeric();
        std::rotate(slots_.begin(), it, it + 1);
        fresh = false;
        return *slots_.front();
      }
    }
    if (!slots_.empty()) slots_.front()->release_numeric();
    if (slots_.size() == static_cast<std::size_t>(kCachedPatterns)) slots_.pop_back();
    slots_.insert(slots_.begin(), std::make_unique<Slot>());
    slots_.front()->pattern.remember(A, h);
    fresh = true;
    return *slots_.front();
  }

 private:
  std::vector<std::unique_ptr<Slot>> slots_;
};

// CHOLMOD on the lower triangle, silent (a failed Cholesky is an expected event here).
class Cholmod : public Eigen::CholmodDecomposition<SpMat, Eigen::Lower> {
 public:
  explicit Cholmod(Eigen::CholmodMode mode) {
    use_cpu_blas_kernels();
    setMode(mode);
    cholmod().print = 0;
  }
  bool is_ll() const { return m_cholmodFactor != nullptr && m_cholmodFactor->is_ll != 0; }
  const cholmod_factor* factor() const { return m_cholmodFactor; }
  // The analysis of S's pattern (lower triangle) with the ordering `perm` (CHOLMOD's Perm).
  void analyse_with(const SpMat& S, std::vector<int>& perm) {
    if (m_cholmodFactor != nullptr) cholmod_free_factor(&m_cholmodFactor, &cholmod());
    cholmod_sparse A = Eigen::viewAsCholmod(S.selfadjointView<Eigen::Lower>());
    const int nmethods = cholmod().nmethods;
    cholmod().nmethods = 1;  // method[0], CHOLMOD_GIVEN: perm
    m_cholmodFactor = cholmod_analyze_p(&A, perm.data(), nullptr, 0, &cholmod());
    cholmod().nmethods = nmethods;
    m_isInitialized = true;
    m_info = m_cholmodFactor != nullptr ? Eigen::Success : Eigen::NumericalIssue;
    m_analysisIsOk = m_cholmodFactor != nullptr;
    m_factorizationIsOk = false;
  }
  // Frees the numeric factor, keeps the analysis (the next factorize() allocates it again).
  void release_numeric() {
    cholmod_factor* L = m_cholmodFactor;
    if (L == nullptr || L->xtype == CHOLMOD_PATTERN) return;
    cholmod_change_factor(CHOLMOD_PATTERN, L->is_ll, L->is_super, 1, 1, L, &cholmod());
  }
  // A factorization that succeeded is of a positive definite matrix: L L^T, or a simplicial
  // L D L^T (no pivoting) with every D_jj > 0 (D_jj first in column j).
  bool positive_definite() const {
    if (info() != Eigen::Success || m_cholmodFactor == nullptr) return false;
    const cholmod_factor& L = *m_cholmodFactor;
    if (L.is_ll != 0) return true;
    if (L.is_super != 0) return false;
    const auto* p = static_cast<const int*>(L.p);
    const auto* x = static_cast<const double*>(L.x);
    for (std::size_t j = 0; j < L.n; ++j) {
      if (!(x[p[j]] > 0)) return false;
    }
    return true;
  }
};

// From this many rows on, the analyses try AMD and nested dissection and keep the better
// ordering (CHOLMOD: fewer flops, on the graph of the 6 x 6 blocks where the matrix has them,
// block_ordering.hpp, else AMD and METIS on the matrix; CHOLMOD's default tries METIS only
// where AMD fills much; UMFPACK: UMFPACK_ORDERING_BEST). On the lab cone's Newton matrices METIS
// factored 1.2-1.5x faster from 16 704 rows (2 800 segments) on, and on the 10^4-segment sheet
// it needs 2.28e9 flops against AMD's 2.57e9; the analysis costs about twice AMD's, once per
// pattern (BENCHMARKS.md). Below, as before: the tests' models (up to about 6 000 dofs) keep
// their orderings, and their results their bits.
constexpr Eigen::Index kCompareOrderings = 10000;

// UMFPACK's LU (multifrontal, BLAS-3 on its frontal matrices) of one sparsity pattern: the
// symbolic analysis (the fill-reducing ordering and the frontal matrices' sizes) kept, the
// numeric factorization redone for each matrix. The analysis is given the pattern only (no
// values), so that it, and every result after it, depends on the pattern alone.
class Umfpack {
 public:
  Umfpack() {
    use_cpu_blas_kernels();
    umfpack_di_defaults(control_);
    control_[UMFPACK_PRL] = 0;  // silent: a singular matrix is an expected event here
    // AMD on the pattern of A + A^T, diagonal pivots preferred (kept unless below 0.001 of
    // their column's largest entry): our Newton matrices have symmetric patterns (6 x 6
    // blocks), where this filled 14-52 % less than the COLAMD ordering of the unsymmetric
    // strategy that UMFPACK's automatic choice took on them (BENCHMARKS.md).
    control_[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
  }
  ~Umfpack() { release(); }
  bool analysed() const { return analysed_; }
  Umfpack(const Umfpack&) = delete;
  Umfpack& operator=(const Umfpack&) = delete;

  // The analysis of A's pattern; false if UMFPACK refused it (out of memory).
  bool analyse(const SpMat& A) {
    release();
    const int n = static_cast<int>(A.rows());
    control_[UMFPACK_ORDERING] =
        A.rows() >= kCompareOrderings ? UMFPACK_ORDERING_BEST : UMFPACK_ORDERING_AMD;
    analysed_ = umfpack_di_symbolic(n, n, A.outerIndexPtr(), A.innerIndexPtr(), nullptr, &symbolic_,
                                    control_, info_) == UMFPACK_OK;
    return analysed_;
  }
  // The numeric factorization of A (the analysed pattern); false if A is singular (an exact
  // zero pivot: UMFPACK_WARNING_singular_matrix) or memory ran out.
  bool factorize(const SpMat& A) {
    if (numeric_ != nullptr) umfpack_di_free_numeric(&numeric_);
    if (!analysed_) return false;
    const int status = umfpack_di_numeric(A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr(),
                                          symbolic_, &numeric_, control_, info_);
    return status == UMFPACK_OK;
  }
  // Frees the numeric factorization, keeps the analysis.
  void release_numeric() {
    if (numeric_ != nullptr) umfpack_di_free_numeric(&numeric_);
  }
  // x = A^-1 b with the last factorization (of A), refined against A by UMFPACK when `refine`
  // (at most Control[UMFPACK_IRSTEP] = 2 steps, while they reduce the backward error).
  bool solve(const SpMat& A, const Eigen::VectorXd& b, Eigen::VectorXd& x, bool refine = true) {
    x.resize(b.size());
    double control[UMFPACK_CONTROL];
    std::copy(control_, control_ + UMFPACK_CONTROL, control);
    if (!refine) control[UMFPACK_IRSTEP] = 0;
    return umfpack_di_solve(UMFPACK_A, A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr(), x.data(),
                            b.data(), numeric_, control, info_) == UMFPACK_OK &&
           x.allFinite();
  }

 private:
  void release() {
    if (numeric_ != nullptr) umfpack_di_free_numeric(&numeric_);
    if (symbolic_ != nullptr) umfpack_di_free_symbolic(&symbolic_);
    analysed_ = false;
  }
  double control_[UMFPACK_CONTROL];
  double info_[UMFPACK_INFO];
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  bool analysed_ = false;
};

struct LuSlot {
  Pattern pattern;
  Umfpack lu;
  void release_numeric() { lu.release_numeric(); }
};

// CHOLMOD chooses simplicial L D L^T for small systems and supernodal L L^T (BLAS) for
// large ones; the latter cannot factor an indefinite matrix, which then goes to `ldlt`.
struct SymmetricSlot {
  Pattern pattern;
  Cholmod automatic{Eigen::CholmodAuto};
  Cholmod ldlt{Eigen::CholmodLDLt};
  bool automatic_analysed = false, ldlt_analysed = false;
  void release_numeric() {
    automatic.release_numeric();
    ldlt.release_numeric();
  }
};

// The analysis of S's pattern. From kCompareOrderings rows on, where S is made of 6 x 6
// blocks (block_ordering: the better of AMD and nested dissection on the graph of the
// blocks, a fraction of an ordering's cost on S), else with the better of AMD and METIS on S.
void analyse(Cholmod& f, const SpMat& S) {
  if (S.rows() < kCompareOrderings) return f.analyzePattern(S);
  std::optional<std::vector<int>> perm = block_ordering(S, f.cholmod());
  if (perm) return f.analyse_with(S, *perm);
  const int nmethods = f.cholmod().nmethods;
  f.cholmod().nmethods = 3;  // the given permutation (none here, skipped), AMD and METIS
  f.analyzePattern(S);
  f.cholmod().nmethods = nmethods;
}

bool factor(Cholmod& f, bool& analysed, const SpMat& S) {
  const bool first = !analysed;
  analysed = true;
  timed(
      first, [&] { analyse(f, S); }, [&] { f.factorize(S); });
  return f.info() == Eigen::Success;
}

// The pattern caches a solve uses: this thread's, or a kept factorization's own.
struct Caches {
  PatternCache<LuSlot>& lu;
  PatternCache<SymmetricSlot>& symmetric;
  bool refine_lu = true;  // false: LU solves unrefined (modified Newton corrects them)
};

Caches thread_caches() {
  thread_local PatternCache<LuSlot> lu;
  thread_local PatternCache<SymmetricSlot> symmetric;
  return {lu, symmetric};
}

// The factorization a solve ended with (for a kept factorization to solve with again).
struct UsedFactor {
  Cholmod* cholmod = nullptr;
  Umfpack* umfpack = nullptr;
};

SymmetricSlot& symmetric_slot(PatternCache<SymmetricSlot>& cache, const SpMat& S) {
  bool fresh = false;
  return cache.slot_for(S, fresh);
}

// Componentwise backward error of x with residual r = b - A x (0 where a row of |A| |x| + |b|
// is zero and so is r); |A| |x| without forming |A|.
double backward_error(const SpMat& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x,
                      const Eigen::VectorXd& r) {
  Eigen::VectorXd w = b.cwiseAbs();
  for (Eigen::Index c = 0; c < A.outerSize(); ++c) {
    const double x_c = std::abs(x[c]);
    for (SpMat::InnerIterator it(A, c); it; ++it) w[it.row()] += std::abs(it.value()) * x_c;
  }
  double e = 0;
  for (Eigen::Index i = 0; i < r.size(); ++i) {
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
  x = f.solve(b);
  Eigen::VectorXd best;
  double e_best = INFINITY;
  for (steps = 0;; ++steps) {
    if (!x.allFinite()) break;
    const Eigen::VectorXd r = b - A * x;
    const double e = backward_error(A, b, x, r);
    const double e_prev = e_best;
    if (e < e_best) e_best = e, best = x;
    if (e <= kTargetError || steps == kMaxRefinements || e > 0.5 * e_prev) break;
    x += f.solve(r);
  }
  linear_solve_counters().refinements += steps;
  if (e_best < INFINITY) x = std::move(best);
  return e_best;
}

// Solves A X = B, one factorization for all columns (each solved as a vector: the same bits
// as a single solve), refined against A when `refine`.
bool lu_solve(PatternCache<LuSlot>& cache, const SpMat& A, const Eigen::MatrixXd& B,
              Eigen::MatrixXd& X, UsedFactor& used, bool refine) {
  if (A.rows() != A.cols() || B.rows() != A.rows()) return false;
  if (A.rows() == 0) {  // UMFPACK refuses n = 0; the empty system has the empty solution
    X.resize(0, B.cols());
    return true;
  }
  bool analyse = false;
  LuSlot& slot = cache.slot_for(A, analyse);
  analyse = analyse || !slot.lu.analysed();  // (a failed analysis is tried again)
  bool factored = false;
  timed(
      analyse, [&] { slot.lu.analyse(A); }, [&] { factored = slot.lu.factorize(A); });
  ++linear_solve_counters().lu_factorizations;
  if (!factored) return false;
  used.umfpack = &slot.lu;
  X.resize(B.rows(), B.cols());
  Eigen::VectorXd x;
  for (Eigen::Index j = 0; j < B.cols(); ++j) {
    const Eigen::VectorXd b = B.col(j);
    if (!slot.lu.solve(A, b, x, refine)) return false;
    X.col(j) = x;
  }
  return true;
}

// The symmetric path for A, whose symmetric part S is (S itself when `exact`); nullopt if it
// does not apply (the factorization or the refinement failed), so that LU decides.
// A positive definite factor of an exactly symmetric matrix is backward stable: it is
// accepted whatever the refinement reached (LU would add fill, not accuracy, where the
// refinement stalls just above kBackwardError: 1.7e-14 on a generalized-alpha matrix of a
// 10^4-segment sheet; at 10^5 the LU took more than 8 GB).
std::optional<LinearSolvePath> symmetric_solve(PatternCache<SymmetricSlot>& cache, const SpMat& A,
                                               const SpMat& S, bool exact, const Eigen::MatrixXd& B,
                                               Eigen::MatrixXd& X, int& steps, UsedFactor& used) {
  SymmetricSlot& slot = symmetric_slot(cache, S);
  // Each column refined as a vector, accepted if `accept` says so for its backward error.
  const auto solve_columns = [&](const Cholmod& f, auto accept) {
    X.resize(B.rows(), B.cols());
    for (Eigen::Index j = 0; j < B.cols(); ++j) {
      Eigen::VectorXd x;
      int s = 0;
      const double e = refined_solve(f, A, B.col(j), x, s);
      steps = std::max(steps, s);
      if (!accept(e)) return false;
      X.col(j) = x;
    }
    return true;
  };
  steps = 0;
  if (factor(slot.automatic, slot.automatic_analysed, S)) {
    const bool pd = slot.automatic.positive_definite();
    if (!solve_columns(slot.automatic, [&](double e) {
          return e <= kBackwardError || (pd && exact && e < INFINITY);
        })) {
      return std::nullopt;
    }
    used.cholmod = &slot.automatic;
    return slot.automatic.is_ll() ? LinearSolvePath::Cholesky : LinearSolvePath::LDLT;
  }
  // L L^T met a non-positive pivot (indefinite); L D L^T failed only on an exact zero pivot.
  if (!slot.automatic.is_ll()) return std::nullopt;
  ++linear_solve_counters().indefinite;
  if (factor(slot.ldlt, slot.ldlt_analysed, S) &&
      solve_columns(slot.ldlt, [](double e) { return e <= kBackwardError; })) {
    used.cholmod = &slot.ldlt;
    return LinearSolvePath::LDLT;
  }
  return std::nullopt;
}

// Flushes subnormal entries to zero (a modulus of 1e-320 Pa made some, and Eigen's SparseLU,
// the LU before UMFPACK, never returned on them; they are zero for every purpose here, so a
// matrix of them is singular, and no factorization runs on slow subnormal arithmetic); false
// if an entry is not finite.
bool clean_entries(SpMat& A) {
  for (double* v = A.valuePtr(); v != A.valuePtr() + A.nonZeros(); ++v) {
    if (!std::isfinite(*v)) return false;
    if (std::abs(*v) < std::numeric_limits<double>::min()) *v = 0;
  }
  return true;
}

}  // namespace

LinearSolveCounters& linear_solve_counters() {
  thread_local LinearSolveCounters counters;
  return counters;
}

LinearSolveCounters operator-(const LinearSolveCounters& later,
                              const LinearSolveCounters& earlier) {
  LinearSolveCounters d;
  d.solves = later.solves - earlier.solves;
  d.analyses = later.analyses - earlier.analyses;
  d.factorizations = later.factorizations - earlier.factorizations;
  d.lu_factorizations = later.lu_factorizations - earlier.lu_factorizations;
  d.indefinite = later.indefinite - earlier.indefinite;
  d.refinements = later.refinements - earlier.refinements;
  d.analyse_s = later.analyse_s - earlier.analyse_s;
  d.factor_s = later.factor_s - earlier.factor_s;
  d.total_s = later.total_s - earlier.total_s;
  return d;
}

SpMat symmetric_part(const SpMat& A, const SpMat& At) {
  SpMat S = At + A;  // pattern of A + A^T, kept even where values cancel
  S *= 0.5;
  return S;
}

SpMat symmetric_part(const SpMat& A) {
  return symmetric_part(A, SpMat(A.transpose()));
}

double asymmetry_ratio(const SpMat& A, const SpMat& At) {
  const double A_norm = A.norm();
  if (A_norm == 0) return 0;
  return (A - At).norm() / A_norm;
}

double asymmetry_ratio(const SpMat& A) {
  return asymmetry_ratio(A, SpMat(A.transpose()));
}

SymmetricMatrix::SymmetricMatrix(SpMat S, bool finite) : S_(std::move(S)), finite_(finite) {
  S_.makeCompressed();
  finite_ = finite_ && clean_entries(S_);
}

SymmetricMatrix SymmetricMatrix::symmetric_part_of(const SpMat& A) {
  return symmetric_part_of(A, SpMat(A.transpose()));
}

SymmetricMatrix SymmetricMatrix::symmetric_part_of(const SpMat& A, const SpMat& At) {
  if (A.rows() != A.cols()) return SymmetricMatrix(SpMat(), false);  // refused by the solves
  // (a + b) / 2 is commutative in floating point: S(i, j) == S(j, i) exactly.
  return SymmetricMatrix(symmetric_part(A, At), true);
}

SymmetricMatrix SymmetricMatrix::plus_diagonal(const Eigen::VectorXd& d) const {
  SpMat D(S_.rows(), S_.cols());
  D.reserve(Eigen::VectorXi::Ones(S_.cols()));
  for (Eigen::Index i = 0; i < d.size(); ++i) D.insert(i, i) = d[i];
  return SymmetricMatrix(S_ + D, finite_ && d.allFinite());
}

Eigen::VectorXd SymmetricMatrix::shift_scale() const {
  const Eigen::VectorXd d = S_.diagonal().cwiseAbs();
  return d.cwiseMax(1e-12 * d.maxCoeff());
}

namespace {

// The symmetric path for A (symmetric part S, S itself when `exact`), else LU of A.
bool symmetric_else_lu(Caches caches, const SpMat& A, const SpMat& S, bool exact,
                       const Eigen::MatrixXd& B, Eigen::MatrixXd& X, LinearSolveInfo& report,
                       UsedFactor& used) {
  if (const auto path =
          symmetric_solve(caches.symmetric, A, S, exact, B, X, report.refinements, used)) {
    report.path = *path;
    return true;
  }
  report.path = LinearSolvePath::LU;
  return lu_solve(caches.lu, A, B, X, used, caches.refine_lu);
}

// sparse_solve(A, B, X) with the given caches; `Ac` ends as the matrix solved (compressed,
// subnormals flushed), `used` names the factorization.
bool solve_system(Caches caches, const SpMat& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
                  LinearSolveInfo* info, SpMat& Ac, UsedFactor& used) {
  Ac = A;
  Ac.makeCompressed();
  if (!clean_entries(Ac) || !B.allFinite()) return false;
  LinearSolveInfo report;
  const SpMat At = Ac.transpose();
  report.asymmetry = asymmetry_ratio(Ac, At);
  bool ok = false;
  if (Ac.rows() > 0 && Ac.rows() == Ac.cols() && report.asymmetry <= kSymmetricAsymmetry) {
    // Also for a symmetric A: its stored pattern need not be (a stored zero), and CHOLMOD
    // crashed on such a pattern (ContactDynamics.StaticSolverHoldsAPlateInsideTheCone).
    ok = symmetric_else_lu(caches, Ac, symmetric_part(Ac, At), report.asymmetry == 0, B, X, report,
                           used);
  } else {
    report.path = LinearSolvePath::LU;
    ok = lu_solve(caches.lu, Ac, B, X, used, caches.refine_lu);
  }
  if (info != nullptr) *info = report;
  return ok;
}

bool solve_system(const SpMat& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
                  LinearSolveInfo* info) {
  SpMat Ac;
  UsedFactor used;
  return solve_system(thread_caches(), A, B, X, info, Ac, used);
}

// sparse_solve(S, B, X) with the given caches; `used` names the factorization.
bool solve_symmetric(Caches caches, const SymmetricMatrix& S, const Eigen::MatrixXd& B,
                     Eigen::MatrixXd& X, LinearSolveInfo* info, UsedFactor& used) {
  if (!S.finite() || !B.allFinite()) return false;
  LinearSolveInfo report;
  bool ok = false;
  if (S.size() > 0) {
    ok = symmetric_else_lu(caches, S.matrix(), S.matrix(), true, B, X, report, used);
  } else {
    report.path = LinearSolvePath::LU;
    ok = lu_solve(caches.lu, S.matrix(), B, X, used, caches.refine_lu);
  }
  if (info != nullptr) *info = report;
  return ok;
}

// A vector as a one-column matrix and back.
template <class Solve>
bool solve_vector(const Eigen::VectorXd& b, Eigen::VectorXd& x, Solve solve) {
  Eigen::MatrixXd X;
  if (!solve(Eigen::MatrixXd(b), X)) return false;
  x = X.col(0);
  return true;
}

// Counts a whole call's time and number.
template <class Solve>
auto counted(Solve solve) {
  const auto t0 = Clock::now();
  ++linear_solve_counters().solves;
  const auto result = solve();
  linear_solve_counters().total_s += seconds_since(t0);
  return result;
}

}  // namespace

bool sparse_solve(const SpMat& A, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                  LinearSolveInfo* info) {
  return counted([&] {
    return solve_vector(b, x, [&](const Eigen::MatrixXd& B, Eigen::MatrixXd& X) {
      return solve_system(A, B, X, info);
    });
  });
}

bool sparse_solve(const SpMat& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
                  LinearSolveInfo* info) {
  return counted([&] { return solve_system(A, B, X, info); });
}

bool sparse_solve(const SymmetricMatrix& S, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                  LinearSolveInfo* info) {
  return counted([&] {
    if (!S.finite() || !b.allFinite()) return false;
    return solve_vector(b, x, [&](const Eigen::MatrixXd& B, Eigen::MatrixXd& X) {
      UsedFactor used;
      return solve_symmetric(thread_caches(), S, B, X, info, used);
    });
  });
}

CholeskyStatus cholesky_solve(const SymmetricMatrix& S, const Eigen::VectorXd& b,
                              Eigen::VectorXd& x, LinearSolveInfo* info) {
  return counted([&] {
    if (!S.finite() || !b.allFinite() || S.size() == 0) return CholeskyStatus::Failed;
    SymmetricSlot& slot = symmetric_slot(thread_caches().symmetric, S.matrix());
    LinearSolveInfo report;
    if (!factor(slot.automatic, slot.automatic_analysed, S.matrix()) ||
        !slot.automatic.positive_definite()) {
      ++linear_solve_counters().indefinite;
      return CholeskyStatus::NotPositiveDefinite;
    }
    // Backward stable: accepted whatever the refinement reaches (see symmetric_solve).
    if (refined_solve(slot.automatic, S.matrix(), b, x, report.refinements) == INFINITY) {
      return CholeskyStatus::Failed;
    }
    report.path = slot.automatic.is_ll() ? LinearSolvePath::Cholesky : LinearSolvePath::LDLT;
    if (info != nullptr) *info = report;
    return CholeskyStatus::Solved;
  });
}

// The caches of its own (the thread's may be evicted or refactored by other solves between
// ours), the matrix factored (for the refinement) and the factorization it ended with.
struct KeptFactorization::Impl {
  PatternCache<LuSlot> lu;
  PatternCache<SymmetricSlot> symmetric;
  SpMat A;  // the matrix factored where UMFPACK's solves need it (empty for CHOLMOD's factor)
  Eigen::Index rows = 0;
  UsedFactor used;
  bool valid = false;
  std::size_t single_from = kSinglePrecisionEntries;
  SinglePrecisionFactor single;  // CHOLMOD's factor in single precision, where it is large
  // After a factoring solve: the single-precision copy of a large CHOLMOD factor, which then
  // replaces the factor's values (the next factorization makes them anew).
  void keep_single() {
    const cholmod_factor* L = valid && used.cholmod != nullptr ? used.cholmod->factor() : nullptr;
    if (L == nullptr || L->xsize < single_from) return;
    single = SinglePrecisionFactor::of(*L);
    if (single.valid()) used.cholmod->release_numeric();
  }
};

KeptFactorization::KeptFactorization() : impl_(std::make_unique<Impl>()) {}
KeptFactorization::~KeptFactorization() = default;

bool KeptFactorization::factor_and_solve(const SpMat& A, const Eigen::MatrixXd& B,
                                         Eigen::MatrixXd& X) {
  Impl& k = *impl_;
  k.used = {};
  k.single = {};  // before the factorization, which may need its memory
  k.valid = counted([&] {
    return solve_system({k.lu, k.symmetric, false}, A, B, X, nullptr, k.A, k.used);
  });
  k.rows = A.rows();
  k.keep_single();
  return k.valid;
}

bool KeptFactorization::factor_and_solve(const SymmetricMatrix& S, const Eigen::MatrixXd& B,
                                         Eigen::MatrixXd& X) {
  Impl& k = *impl_;
  k.used = {};
  k.single = {};  // before the factorization, which may need its memory
  k.valid = counted([&] {
    return solve_symmetric({k.lu, k.symmetric, false}, S, B, X, nullptr, k.used);
  });
  k.rows = S.size();
  k.A = k.valid && k.used.umfpack != nullptr ? S.matrix() : SpMat();
  k.keep_single();
  return k.valid;
}

bool KeptFactorization::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  const Impl& k = *impl_;
  if (!k.valid || b.size() != k.rows || !b.allFinite()) return false;
  return counted([&] {
    if (k.rows == 0) {
      x.resize(0);
      return true;
    }
    // Unrefined: the modified Newton iteration that asks corrects an inexact step anyway
    // (its residual is exact), and the refinement cost 2-4x the triangular solves.
    if (k.single.valid()) return k.single.solve(b, x);
    if (k.used.cholmod != nullptr) {
      x = k.used.cholmod->solve(b);
      return x.allFinite();
    }
    return k.used.umfpack != nullptr && k.used.umfpack->solve(k.A, b, x, false);
  });
}

bool KeptFactorization::valid() const {
  return impl_->valid;
}

void KeptFactorization::clear() {
  impl_->valid = false;
  impl_->single = SinglePrecisionFactor();
}

void KeptFactorization::single_precision_from(std::size_t entries) {
  impl_->single_from = entries;
}

bool KeptFactorization::single_precision() const {
  return impl_->single.valid();
}

}  // namespace finseg
