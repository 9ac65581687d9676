// Where one force evaluation's time goes on a scene, at its initial state or at a state file
// (a fold's checkpoint, say): compute_forces without and with the Jacobian, each part alone
// (force elements, plate cells, membrane cells, contact) and the Jacobian's conversion to
// compressed columns, as means over repeated evaluations on one thread, with the Jacobian
// scratch kept between evaluations as the implicit solver keeps it; then what backward
// Euler's Newton does with it: the iteration matrix as newton_linearisation returns it (forces,
// Jacobian and its copy out included, which the solver does not make) and the symmetric part a
// factorization is given. Prints a table (ms).
// Usage: bench_force_evaluation SCENE [STATE] [--repeat N]   (default N = 10)
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include "collision/contact_forces.hpp"
#include "core/allocator.hpp"
#include "core/threads.hpp"
#include "elements/assemble.hpp"
#include "elements/assembler.hpp"
#include "elements/force_elements.hpp"
#include "elements/membrane_cells.hpp"
#include "elements/plate_cells.hpp"
#include "scene/scene_reader.hpp"
#include "scene/state_file.hpp"
#include "solvers/dofs.hpp"
#include "solvers/implicit_newton.hpp"
#include "solvers/linear_solve.hpp"

namespace {

using namespace finseg;
using Clock = std::chrono::steady_clock;

// Mean milliseconds of `f` over `repeat` calls.
template <class F>
double mean_ms(int repeat, F f) {
  const auto t0 = Clock::now();
  for (int i = 0; i < repeat; ++i) f();
  return 1e3 * std::chrono::duration<double>(Clock::now() - t0).count() / repeat;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  int repeat = 10;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--repeat" && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else {
      files.push_back(a);
    }
  }
  if (files.empty() || files.size() > 2) {
    fmt::print(stderr, "usage: bench_force_evaluation SCENE [STATE] [--repeat N]\n");
    return 2;
  }
  set_thread_count(1);
  keep_freed_memory();  // as finseg runs: large matrices reused from the heap, not faulted in
  const Scene scene = read_scene(files[0]);
  const Model& m = scene.model;
  State state = files.size() == 2 ? read_state_file(files[1], m).state : initial_state(m);
  commit_history(m, state, false);  // the contact candidates a run's state carries
  BodyForces f;
  ForceJacobian jac;
  compute_forces(m, state, f, &jac);  // the scratch and its layout, as after a solver's first
  fmt::print("{} segments, {} elements, {} plate cells, {} membrane cells, {} Jacobian entries\n",
             m.bodies.size(), m.elements.size(), m.plate_cells.size(), m.membrane_cells.size(),
             jac.dq.nonZeros());
  const auto part = [&](auto add, bool jacobian) {
    return mean_ms(repeat, [&] {
      f.f_W.assign(m.bodies.size(), Vec3::Zero());
      f.tau_W.assign(m.bodies.size(), Vec3::Zero());
      Assembler as(m, state, f, jacobian ? &jac : nullptr);
      add(as);
    });
  };
  fmt::print("{:<22} {:>10} {:>14}\n", "part", "forces_ms", "with_jacobian");
  fmt::print("{:<22} {:>10.2f} {:>14.2f}\n", "compute_forces",
             mean_ms(repeat, [&] { compute_forces(m, state, f); }),
             mean_ms(repeat, [&] { compute_forces(m, state, f, &jac); }));
  const auto row = [&](const char* name, auto add) {
    fmt::print("{:<22} {:>10.2f} {:>14.2f}\n", name, part(add, false), part(add, true));
  };
  row("force elements", [&](Assembler& as) { add_force_elements(m, state, as); });
  row("plate cells", [&](Assembler& as) { add_plate_cells(m, state, as); });
  row("membrane cells", [&](Assembler& as) { add_membrane_cells(m, state, as); });
  row("contact", [&](Assembler& as) { add_contact_forces(m, state, as); });
  compute_forces(m, state, f, &jac);
  fmt::print("{:<22} {:>10} {:>14.2f}\n", "to compressed columns", "-",
             mean_ms(repeat, [&] { jac.dq_blocks.to_sparse(m.num_dofs, jac.dq); }));
  // Backward Euler's Newton at a step of 1 ms from this state (v1 guessed as v0).
  const double h = 1e-3;
  AffineStep map{Eigen::VectorXd::Zero(m.num_dofs), velocity_vector(m, state), h, 1};
  NewtonResidual res{momentum(m, state), h, false};
  const Eigen::VectorXd x = map.v0;
  State at = state;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> A;
  fmt::print("{:<22} {:>10} {:>14.2f}\n", "Newton matrix", "-",
             mean_ms(repeat, [&] { newton_linearisation(m, state, h, map, res, x, at, r, A); }));
  fmt::print("{:<22} {:>10} {:>14.2f}\n", "its symmetric part", "-", mean_ms(repeat, [&] {
               const Eigen::SparseMatrix<double> At = A.transpose();  // as the solver does
               if (asymmetry_ratio(A, At) < 0) std::abort();
               if (!SymmetricMatrix::symmetric_part_of(A, At).finite()) std::abort();
             }));
  return 0;
}
