// Sparse factorizations of a 2-D sheet's static tangent (issue 12 item 4) as a table: a square
// sheet of n x n segments (200 x 200 x 0.1 mm, clamped along one edge), slightly deformed,
// its stiffness K = -d(generalized force)/d(pose) assembled once; then CHOLMOD (what
// sparse_solve uses on the symmetric part) and Eigen's SparseLU with COLAMD (the unsymmetric
// path until 2026-11-27; UMFPACK since: bench_lu_factor_table) on it: fill, analyse / factor /
// solve times, and the whole sparse_solve call.
// Usage: bench_sheet_factor_table [--lu-max-dofs N] [n...]   (default n: 32 100 316;
// LU is skipped above N dofs, default 70000)
#include <fmt/format.h>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseLU>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "elements/assemble.hpp"
#include "generators/sheet.hpp"
#include "solvers/dofs.hpp"
#include "solvers/linear_solve.hpp"

namespace {

using namespace finseg;
using SpMat = Eigen::SparseMatrix<double>;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Eigen's CHOLMOD wrapper, telling which factorization CHOLMOD chose.
class Cholmod : public Eigen::CholmodDecomposition<SpMat, Eigen::Lower> {
 public:
  bool supernodal() const { return m_cholmodFactor != nullptr && m_cholmodFactor->is_super; }
};

struct Row {
  std::string solver;
  double fill = 0, analyse = 0, factor = 0, solve = 0, residual = 0;
  std::string note;
};

double relative_residual(const SpMat& A, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (b - A * x).norm() / b.norm();
}

Row cholmod_row(const SpMat& K, const Eigen::VectorXd& b) {
  const SpMat S = 0.5 * (SpMat(K.transpose()) + K);
  Cholmod f;
  f.setMode(Eigen::CholmodAuto);
  f.cholmod().print = 0;
  Row r{"CHOLMOD", 0, 0, 0, 0, 0, ""};
  auto t = Clock::now();
  f.analyzePattern(S);
  r.analyse = since(t);
  r.fill = f.cholmod().lnz;  // nnz(L) from the symbolic analysis
  t = Clock::now();
  f.factorize(S);
  r.factor = since(t);
  if (f.info() != Eigen::Success) r.note = "not positive definite; ";
  t = Clock::now();
  const Eigen::VectorXd x = f.solve(b);
  r.solve = since(t);
  r.residual = relative_residual(S, x, b);  // its own system, the symmetric part
  r.note += f.supernodal() ? "supernodal L L^T" : "simplicial L D L^T";
  return r;
}

Row lu_row(const SpMat& K, const Eigen::VectorXd& b) {
  Eigen::SparseLU<SpMat, Eigen::COLAMDOrdering<int>> lu;
  Row r{"SparseLU", 0, 0, 0, 0, 0, "COLAMD"};
  auto t = Clock::now();
  lu.analyzePattern(K);
  r.analyse = since(t);
  t = Clock::now();
  lu.factorize(K);
  r.factor = since(t);
  r.fill = static_cast<double>(lu.nnzL() + lu.nnzU());
  t = Clock::now();
  const Eigen::VectorXd x = lu.solve(b);
  r.solve = since(t);
  r.residual = relative_residual(K, x, b);
  return r;
}

Row sparse_solve_row(const SpMat& K, const Eigen::VectorXd& b) {
  Eigen::VectorXd x;
  LinearSolveInfo info;
  Row r{"sparse_solve", NAN, NAN, 0, 0, 0, ""};
  auto t = Clock::now();
  const bool ok = sparse_solve(K, b, x, &info);
  r.factor = since(t);  // first call: analyse + factor + solve + refinement
  t = Clock::now();
  sparse_solve(K, b, x, &info);
  r.solve = since(t);  // second call, pattern known: factor + solve + refinement
  r.residual = ok ? relative_residual(K, x, b) : NAN;
  const char* path = info.path == LinearSolvePath::Cholesky ? "Cholesky"
                     : info.path == LinearSolvePath::LDLT   ? "LDL^T"
                                                            : "LU";
  r.note = fmt::format("path {}, {} refinements; first call / repeat", path, info.refinements);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sides;
  long lu_max_dofs = 70000;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--lu-max-dofs" && i + 1 < argc) {
      lu_max_dofs = std::atol(argv[++i]);
    } else {
      sides.push_back(std::atoi(argv[i]));
    }
  }
  if (sides.empty()) sides = {32, 100, 316};
  fmt::print("{:>8} {:>8} {:>8} {:>10} {:>9} {:>12} {:>12} {:>11} {:>10} {:>10} {:>9} {}\n",
             "segments", "state", "dofs", "nnz(K)", "asym", "solver", "nnz(factor)", "analyse_s",
             "factor_s", "solve_s", "resid", "note");
  for (const int n : sides) {
    SheetSpec spec;
    spec.length = spec.width = 0.2;
    spec.cells_along = spec.cells_across = n;
    spec.clamp_start = true;
    const Model m = build_sheet_model(spec);
    for (const bool deformed : {false, true}) {
      State state = initial_state(m);
      if (deformed) {
        // The bending and twisting field w = a x^2 + c x y (x from the clamped edge, y
        // across), rotations following it (a pose free of membrane strain to first order):
        // 4 mm deflection at the free edge, out of equilibrium (torques: K unsymmetric).
        constexpr double a = 0.05, c = 0.05;  // 1/m
        Eigen::VectorXd dq = Eigen::VectorXd::Zero(m.num_dofs);
        for (size_t i = 0; i < m.bodies.size(); ++i) {
          const int d = m.dof_of_body[i];
          if (d < 0) continue;
          const double x = m.bodies[i].p0_W.x(), y = m.bodies[i].p0_W.y();
          dq[d + 2] = a * x * x + c * x * y;
          dq[d + 3] = c * x;                 // dw/dy
          dq[d + 4] = -(2 * a * x + c * y);  // -dw/dx
        }
        apply_pose_increment(m, state, dq);
      }
      BodyForces f;
      ForceJacobian jac;
      jac.with_velocity = false;
      auto t = Clock::now();
      compute_forces(m, state, f, &jac);
      const double assembly = since(t);
      SpMat K = -jac.dq;
      K.makeCompressed();
      Eigen::VectorXd b(m.num_dofs);
      for (int k = 0; k < m.num_dofs; ++k) b[k] = std::cos(0.1 * k);
      const double asym = asymmetry_ratio(K);
      const bool lu_fits = m.num_dofs <= lu_max_dofs;
      std::vector<Row> rows{cholmod_row(K, b)};
      if (asym <= kSymmetricAsymmetry || lu_fits) {
        rows.push_back(sparse_solve_row(K, b));
      } else {
        rows.push_back({"sparse_solve", NAN, NAN, NAN, NAN, NAN,
                        fmt::format("skipped (would take LU, dofs > {})", lu_max_dofs)});
      }
      if (!deformed) {
        // Same pattern as the deformed state's: LU measured there.
      } else if (lu_fits) {
        rows.push_back(lu_row(K, b));
      } else {
        rows.push_back(
            {"SparseLU", NAN, NAN, NAN, NAN, NAN, fmt::format("skipped (dofs > {})", lu_max_dofs)});
      }
      const char* state_name = deformed ? "twisted" : "flat";
      for (const Row& r : rows) {
        fmt::print(
            "{:>8} {:>8} {:>8} {:>10} {:>9.2e} {:>12} {:>12.4g} {:>11.4f} {:>10.4f} "
            "{:>10.4f} {:>9.1e} {}\n",
            n * n, state_name, m.num_dofs, K.nonZeros(), asym, r.solver, r.fill, r.analyse,
            r.factor, r.solve, r.residual, r.note);
      }
      fmt::print("{:>8} {:>8} assembly of K (compute_forces with the Jacobian): {:.3f} s\n", n * n,
                 state_name, assembly);
    }
  }
  return 0;
}
