// Static solves of issue 12 item 6(b) as a table: the 200 x 40 x 0.1 mm paper strip under its
// own weight and the slender cantilever under the end load alpha = 2, from the flat state with
// default settings: Newton iterations, Jacobian evaluations and wall time.
// Usage: bench_static_table [segments...]   (default 40 160 640 4096)
#include <fmt/format.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "generators/cantilever.hpp"
#include "solvers/solver.hpp"

int main(int argc, char** argv) {
  using namespace finseg;
  std::vector<int> segments{40, 160, 640, 4096};
  if (argc > 1) {
    segments.clear();
    for (int i = 1; i < argc; ++i) segments.push_back(std::atoi(argv[i]));
  }
  fmt::print("{:>24} {:>9} {:>7} {:>9} {:>10} {:>10} {}\n", "case", "segments", "newton",
             "jacobians", "wall_s", "tip_z_mm", "status");
  for (const bool self_weight : {true, false}) {
    for (const int n : segments) {
      CantileverSpec s;
      s.segments = n;
      if (self_weight) {
        s.length = 0.2;
        s.width = 0.04;
        s.gravity = true;
      } else {
        s.tip_force = Vec3(0, 0, -2 * bending_rigidity(s) / (s.length * s.length));
      }
      const Model m = build_cantilever_model(s);
      State state = initial_state(m);
      SolverSettings set;
      set.kind = SolverKind::Static;
      const SolverStats st = run_solver(m, state, set, {});
      double tip_z = 0;
      for (const ProbeDef& p : m.probes) {
        if (p.name == "tip") tip_z = (state.p_W[p.body] + state.R_WB[p.body] * p.point_B).z();
      }
      fmt::print("{:>24} {:>9} {:>7} {:>9} {:>10.4f} {:>10.3f} {}\n",
                 self_weight ? "self-weight strip" : "cantilever alpha = 2", n,
                 st.newton_iterations, st.jacobian_evaluations, st.wall_seconds, 1e3 * tip_z,
                 st.status);
    }
  }
  return 0;
}
