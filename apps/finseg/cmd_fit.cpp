// finseg fit FIT.yaml --out DIR: fits scene parameters (`--set` paths) to measured
// force-displacement curves by bounded nonlinear least squares, each residual evaluation a
// simulation run in this process; writes DIR/fit.json, fit.csv and fit.png (docs/fit.md).
#include <fmt/format.h>

#include <chrono>
#include <memory>
#include <string>

#include "apps/finseg/commands.hpp"
#include "core/error.hpp"
#include "fitting/fit_output.hpp"
#include "fitting/fit_solve.hpp"
#include "fitting/fit_spec.hpp"

namespace finseg::cli {
namespace {

struct FitOptions {
  std::string fit, out;
  bool quiet = false, no_plot = false;
};

void print_result(const FitSpec& spec, const FitResult& r) {
  fmt::print("finseg fit {}: {} after {} iterations, {} simulations; rms {:.6g} N -> {:.6g} N\n",
             spec.file, r.termination, r.iterations, r.simulations, r.initial_rms, r.final_rms);
  for (std::size_t i = 0; i < spec.parameters.size(); ++i) {
    const FitParameter& p = spec.parameters[i];
    const std::string more =
        p.paths.size() > 1 ? fmt::format(" (and {} more paths)", p.paths.size() - 1) : "";
    fmt::print("  {}{} = {:.8g} +- {:.3g}{}\n", p.path, more, r.values[i], r.standard_errors[i],
               r.at_bound[i] ? " (at its bound)" : "");
  }
}

void fit(const FitOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const FitSpec spec = read_fit(o.fit);
  FitResult r;
  try {
    r = run_fit(spec, [&](const std::string& line) {
      if (!o.quiet) fmt::print(stderr, "finseg: fit: {}\n", line);
    });
  } catch (const DivergenceError& e) {
    fmt::print(stderr, "finseg: error: at the initial values: {}\n", e.what());
    throw ExitStatus{3};
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_fit(spec, r, o.out, wall);
  if (!o.no_plot) {
    try {
      write_fit_plot(spec, r, o.out);
    } catch (const std::runtime_error& e) {
      fmt::print(stderr, "finseg: warning: {}/fit.png not written: {}\n", o.out, e.what());
    }
  }
  if (!o.quiet) print_result(spec, r);
  if (r.termination != "convergence") {
    fmt::print(stderr, "finseg: fit: did not converge: {}\n", r.message);
    throw ExitStatus{3};
  }
}

}  // namespace

void register_fit(CLI::App& app) {
  auto o = std::make_shared<FitOptions>();
  CLI::App* cmd = app.add_subcommand(
      "fit", "fit scene parameters to measured force-displacement curves (least squares)");
  cmd->add_option("FIT", o->fit, "fit file (docs/fit.md)")->required();
  cmd->add_option("--out", o->out, "folder for fit.json, fit.csv and fit.png")->required();
  cmd->add_flag("--quiet", o->quiet, "no progress lines and no result lines");
  cmd->add_flag("--no-plot", o->no_plot, "skip fit.png (no gnuplot needed)");
  cmd->callback([o] { fit(*o); });
}

}  // namespace finseg::cli
