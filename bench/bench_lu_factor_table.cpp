// The sparse LUs of unsymmetric Newton matrices as a table (issue 11 item 7, issue 12): Eigen's
// SparseLU with COLAMD (sparse_solve's LU until 2026-11-27), UMFPACK with its automatic and its
// symmetric strategy (the latter is sparse_solve's LU now; analysis from the pattern alone, as
// there) and KLU (AMD, BTF), each analysed once and then factored `--repeat` times (the Newton
// iterations of one pattern): fill, analyse / factor / solve CPU seconds (the least of the
// repeats for the factorization), relative residual |b - A x| / |b| for b_k = cos(0.1 k).
// Matrices: Matrix Market files (e.g. Newton matrices written from a run) or, for a number n,
// the twisted n x n sheet of bench_sheet_factor_table (static stiffness out of equilibrium).
// --orderings: UMFPACK's symmetric strategy only, with its AMD, METIS, CHOLMOD and BEST orderings,
// each solved with 2, 1 and 0 refinement steps, and CHOLMOD on the symmetric part with AMD and
// METIS, solved with 1 and 0 refinement steps (issue 11 item 7, 2026-11-28).
// Usage: bench_lu_factor_table [--repeat R] [--sparselu-max-dofs N] [--klu-max-dofs N]
//        [--orderings] (FILE.mtx | n)...
#include <fmt/format.h>
#include <klu.h>
#include <umfpack.h>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <string>
#include <unsupported/Eigen/SparseExtra>
#include <utility>
#include <vector>

#include "elements/assemble.hpp"
#include "generators/sheet.hpp"
#include "solvers/dofs.hpp"
#include "solvers/linear_solve.hpp"

namespace {

using namespace finseg;
using SpMat = Eigen::SparseMatrix<double>;
// CPU seconds of this (single-threaded) process: the machine is shared, and wall time
// would count the other jobs' turns.
struct Clock {
  static double now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  }
};

double since(double t0) {
  return Clock::now() - t0;
}

struct Row {
  std::string solver;
  double fill = NAN, analyse = NAN, factor = NAN, solve = NAN, residual = NAN;
  std::string note;
};

double relative_residual(const SpMat& A, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (b - A * x).norm() / b.norm();
}

// Factor seconds: the least of `repeat` factorizations (the machine is shared).
template <class Factor>
double least_of(int repeat, Factor factor) {
  double best = INFINITY;
  for (int k = 0; k < repeat; ++k) {
    const auto t = Clock::now();
    factor();
    best = std::min(best, since(t));
  }
  return best;
}

Row sparselu_row(const SpMat& A, const Eigen::VectorXd& b, int repeat) {
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu;
  Row r{"SparseLU", NAN, 0, 0, 0, 0, "COLAMD"};
  auto t = Clock::now();
  lu.analyzePattern(A);
  r.analyse = since(t);
  r.factor = least_of(repeat, [&] { lu.factorize(A); });
  if (lu.info() != Eigen::Success) return {"SparseLU", NAN, NAN, NAN, NAN, NAN, "failed"};
  r.fill = static_cast<double>(lu.nnzL() + lu.nnzU());
  t = Clock::now();
  const Eigen::VectorXd x = lu.solve(b);
  r.solve = since(t);
  r.residual = relative_residual(A, x, b);
  return r;
}

const char* ordering_name(double ordering) {
  switch (static_cast<int>(ordering)) {
    case UMFPACK_ORDERING_AMD:
      return "AMD";
    case UMFPACK_ORDERING_METIS:
      return "METIS";
    case UMFPACK_ORDERING_CHOLMOD:
      return "CHOLMOD (AMD, METIS if AMD fills much)";
    case UMFPACK_ORDERING_BEST:
      return "best of AMD, METIS, CHOLMOD";
    default:
      return "other";
  }
}

// UMFPACK with `strategy` (UMFPACK_STRATEGY_AUTO: its default, which looks at the pattern).
// `sym_tol`: the symmetric strategy's diagonal pivot tolerance (UMFPACK's default 0.001);
// `ordering`: UMFPACK_ORDERING_*; one row per entry of `irsteps`, the refinement steps in the
// solve (UMFPACK's default 2), all on the same factorization.
std::vector<Row> umfpack_rows(const SpMat& A, const Eigen::VectorXd& b, int repeat, int strategy,
                              double sym_tol, int ordering, const std::vector<int>& irsteps) {
  std::vector<Row> rows;
  double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
  umfpack_di_defaults(control);
  control[UMFPACK_STRATEGY] = strategy;
  control[UMFPACK_SYM_PIVOT_TOLERANCE] = sym_tol;
  control[UMFPACK_ORDERING] = ordering;
  void *symbolic = nullptr, *numeric = nullptr;
  const int n = static_cast<int>(A.rows());
  const int *Ap = A.outerIndexPtr(), *Ai = A.innerIndexPtr();
  const double* Ax = A.valuePtr();
  Row r{"UMFPACK", NAN, 0, 0, 0, 0, ""};
  auto t = Clock::now();
  umfpack_di_symbolic(n, n, Ap, Ai, nullptr, &symbolic, control, info);
  r.analyse = since(t);
  const std::string ordering_used = ordering_name(info[UMFPACK_ORDERING_USED]);
  int status = 0;
  r.factor = least_of(repeat, [&] {
    if (numeric != nullptr) umfpack_di_free_numeric(&numeric);
    status = umfpack_di_numeric(Ap, Ai, Ax, symbolic, &numeric, control, info);
  });
  if (status != UMFPACK_OK) {
    rows.push_back({"UMFPACK", NAN, NAN, NAN, NAN, NAN, fmt::format("status {}", status)});
  }
  r.fill = info[UMFPACK_LNZ] + info[UMFPACK_UNZ];
  const char* used = info[UMFPACK_STRATEGY_USED] == UMFPACK_STRATEGY_SYMMETRIC
                         ? "symmetric strategy"
                         : "unsymmetric strategy";
  const double flops = info[UMFPACK_FLOPS], pattern_symmetry = info[UMFPACK_PATTERN_SYMMETRY];
  const double pivot_tolerance = info[UMFPACK_STRATEGY_USED] == UMFPACK_STRATEGY_SYMMETRIC
                                     ? sym_tol
                                     : control[UMFPACK_PIVOT_TOLERANCE];
  for (const int irstep : status == UMFPACK_OK ? irsteps : std::vector<int>{}) {
    control[UMFPACK_IRSTEP] = irstep;
    r.note = fmt::format(
        "{}{}, {} ordering, irstep {}, pivot tolerance {}, {:.3g} flops; pattern symmetry {:.2f}",
        used, control[UMFPACK_STRATEGY] == UMFPACK_STRATEGY_AUTO ? " (auto)" : "", ordering_used,
        irstep, pivot_tolerance, flops, pattern_symmetry);
    Eigen::VectorXd x(n);
    r.solve = least_of(repeat, [&] {
      umfpack_di_solve(UMFPACK_A, Ap, Ai, Ax, x.data(), b.data(), numeric, control, info);
    });
    r.residual = relative_residual(A, x, b);
    rows.push_back(r);
  }
  umfpack_di_free_numeric(&numeric);
  umfpack_di_free_symbolic(&symbolic);
  return rows;
}

// CHOLMOD (Eigen's wrapper, as sparse_solve uses it) on the symmetric part S of A with the
// given ordering (CHOLMOD_AMD or CHOLMOD_METIS, nmethods 1): fill nnz(L), analyse and factor
// CPU, then the solve of S x = b unrefined and refined once against S.
std::vector<Row> cholmod_rows(const SpMat& A, const Eigen::VectorXd& b, int repeat, int ordering) {
  const SpMat S = symmetric_part(A);
  Eigen::CholmodDecomposition<SpMat, Eigen::Lower> f;
  f.cholmod().print = 0;
  f.cholmod().nmethods = 1;
  f.cholmod().method[0].ordering = ordering;
  f.cholmod().postorder = 1;
  const std::string name = ordering == CHOLMOD_METIS ? "METIS" : "AMD";
  Row r{"CHOLMOD", NAN, 0, 0, 0, 0, ""};
  auto t = Clock::now();
  f.analyzePattern(S);
  r.analyse = since(t);
  r.factor = least_of(repeat, [&] { f.factorize(S); });
  if (f.info() != Eigen::Success) return {{"CHOLMOD", NAN, NAN, NAN, NAN, NAN, "failed"}};
  r.fill = static_cast<double>(f.cholmod().lnz);
  std::vector<Row> rows;
  for (const int steps : {1, 0}) {
    Eigen::VectorXd x;
    r.solve = least_of(repeat, [&] {
      x = f.solve(b);
      for (int k = 0; k < steps; ++k) x += f.solve(b - S * x);
    });
    r.residual = relative_residual(S, x, b);
    r.note =
        fmt::format("symmetric part, {} ordering, {} refinement step(s) against it", name, steps);
    rows.push_back(r);
  }
  return rows;
}

Row klu_row(const SpMat& A, const Eigen::VectorXd& b, int repeat) {
  klu_common common;
  klu_defaults(&common);
  const int n = static_cast<int>(A.rows());
  SpMat Am = A;  // klu_* take non-const pointers
  Row r{"KLU", NAN, 0, 0, 0, 0, "AMD, BTF"};
  auto t = Clock::now();
  klu_symbolic* symbolic = klu_analyze(n, Am.outerIndexPtr(), Am.innerIndexPtr(), &common);
  r.analyse = since(t);
  klu_numeric* numeric = nullptr;
  r.factor = least_of(repeat, [&] {
    if (numeric != nullptr) klu_free_numeric(&numeric, &common);
    numeric = klu_factor(Am.outerIndexPtr(), Am.innerIndexPtr(), Am.valuePtr(), symbolic, &common);
  });
  if (numeric == nullptr || common.status != KLU_OK) {
    r = {"KLU", NAN, NAN, NAN, NAN, NAN, fmt::format("status {}", common.status)};
  } else {
    r.fill = static_cast<double>(numeric->lnz + numeric->unz);
    Eigen::VectorXd x = b;
    t = Clock::now();
    klu_solve(symbolic, numeric, n, 1, x.data(), &common);
    r.solve = since(t);
    r.residual = relative_residual(A, x, b);
  }
  if (numeric != nullptr) klu_free_numeric(&numeric, &common);
  klu_free_symbolic(&symbolic, &common);
  return r;
}

// The twisted n x n sheet's static stiffness (bench_sheet_factor_table's "twisted" state).
SpMat twisted_sheet(int n) {
  SheetSpec spec;
  spec.length = spec.width = 0.2;
  spec.cells_along = spec.cells_across = n;
  spec.clamp_start = true;
  const Model m = build_sheet_model(spec);
  State state = initial_state(m);
  constexpr double a = 0.05, c = 0.05;  // 1/m: w = a x^2 + c x y
  Eigen::VectorXd dq = Eigen::VectorXd::Zero(m.num_dofs);
  for (size_t i = 0; i < m.bodies.size(); ++i) {
    const int d = m.dof_of_body[i];
    if (d < 0) continue;
    const double x = m.bodies[i].p0_W.x(), y = m.bodies[i].p0_W.y();
    dq[d + 2] = a * x * x + c * x * y;
    dq[d + 3] = c * x;
    dq[d + 4] = -(2 * a * x + c * y);
  }
  apply_pose_increment(m, state, dq);
  BodyForces f;
  ForceJacobian jac;
  jac.with_velocity = false;
  compute_forces(m, state, f, &jac);
  SpMat K = -jac.dq;
  K.makeCompressed();
  return K;
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 3;
  long sparselu_max_dofs = 70000, klu_max_dofs = 70000;
  bool orderings = false;  // UMFPACK symmetric only: AMD / METIS / CHOLMOD, irstep 0 / 1 / 2
  std::vector<std::string> inputs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--sparselu-max-dofs" && i + 1 < argc) {
      sparselu_max_dofs = std::atol(argv[++i]);
    } else if (a == "--orderings") {
      orderings = true;
    } else if (a == "--klu-max-dofs" && i + 1 < argc) {
      klu_max_dofs = std::atol(argv[++i]);
    } else {
      inputs.push_back(a);
    }
  }
  if (inputs.empty()) inputs = {"32", "100"};
  fmt::print("{:>24} {:>8} {:>10} {:>9} {:>9} {:>10} {:>9} {:>9} {:>9} {:>9} {}\n", "matrix",
             "dofs", "nnz(A)", "asym", "solver", "nnz(L+U)", "analyse_s", "factor_s", "solve_s",
             "resid", "note");
  for (const std::string& input : inputs) {
    SpMat A;
    const bool file = input.size() > 4 && input.substr(input.size() - 4) == ".mtx";
    if (file) {
      if (!Eigen::loadMarket(A, input)) {
        fmt::print(stderr, "{}: cannot read a Matrix Market file\n", input);
        return 1;
      }
    } else {
      A = twisted_sheet(std::atoi(input.c_str()));
    }
    A.makeCompressed();
    Eigen::VectorXd b(A.rows());
    for (Eigen::Index k = 0; k < b.size(); ++k) b[k] = std::cos(0.1 * k);
    const std::string name =
        file ? input.substr(input.find_last_of('/') + 1) : "twisted sheet n=" + input;
    const double asym = asymmetry_ratio(A);
    std::vector<Row> rows;
    if (orderings) {
      for (const int ordering : {UMFPACK_ORDERING_AMD, UMFPACK_ORDERING_METIS,
                                 UMFPACK_ORDERING_CHOLMOD, UMFPACK_ORDERING_BEST}) {
        for (const Row& r :
             umfpack_rows(A, b, repeat, UMFPACK_STRATEGY_SYMMETRIC, 0.001, ordering, {2, 1, 0})) {
          rows.push_back(r);
        }
      }
      for (const int ordering : {CHOLMOD_AMD, CHOLMOD_METIS}) {
        for (const Row& r : cholmod_rows(A, b, repeat, ordering)) rows.push_back(r);
      }
    } else if (A.rows() <= sparselu_max_dofs) {
      rows.push_back(sparselu_row(A, b, repeat));
    } else {
      rows.push_back({"SparseLU", NAN, NAN, NAN, NAN, NAN, "skipped"});
    }
    if (!orderings) {
      for (const auto& [strategy, sym_tol] : {std::pair{UMFPACK_STRATEGY_AUTO, 0.001},
                                              {UMFPACK_STRATEGY_SYMMETRIC, 0.001},
                                              {UMFPACK_STRATEGY_SYMMETRIC, 1.0}}) {
        for (const Row& r :
             umfpack_rows(A, b, repeat, strategy, sym_tol, UMFPACK_ORDERING_AMD, {2})) {
          rows.push_back(r);
        }
      }
      if (A.rows() <= klu_max_dofs) {
        rows.push_back(klu_row(A, b, repeat));
      } else {
        rows.push_back({"KLU", NAN, NAN, NAN, NAN, NAN, "skipped"});
      }
    }
    for (const Row& r : rows) {
      fmt::print(
          "{:>24} {:>8} {:>10} {:>9.2e} {:>9} {:>10.4g} {:>9.4f} {:>9.4f} {:>9.4f} {:>9.1e} {}\n",
          name, A.rows(), A.nonZeros(), asym, r.solver, r.fill, r.analyse, r.factor, r.solve,
          r.residual, r.note);
    }
  }
  return 0;
}
