// finseg command line: a thin layer over the library.
#include <fmt/format.h>

#include <exception>

#include "apps/finseg/commands.hpp"
#include "core/allocator.hpp"
#include "core/error.hpp"
#include "core/version.hpp"

int main(int argc, char** argv) {
  finseg::keep_freed_memory();  // also done by run_solver; here for the generators' solves
  CLI::App app{"finseg: finite-segment simulation of folded flexible sheets"};
  app.set_version_flag(
      "--version", fmt::format("finseg {} (git {})", finseg::version(), finseg::git_revision()));
  app.require_subcommand(1);
  finseg::cli::register_run(app);
  finseg::cli::register_gen(app);
  finseg::cli::register_inspect(app);
  finseg::cli::register_modes(app);
  finseg::cli::register_identify(app);
  finseg::cli::register_compare(app);
  finseg::cli::register_pattern(app);
  finseg::cli::register_overlay(app);
  finseg::cli::register_sweep(app);
  finseg::cli::register_fit(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const finseg::cli::ExitStatus& e) {
    return e.code;
  } catch (const finseg::OutputError& e) {
    fmt::print(stderr, "finseg: error: {}\n", e.what());
    return 4;
  } catch (const std::exception& e) {
    fmt::print(stderr, "finseg: error: {}\n", e.what());
    return 2;
  }
  return 0;
}
