// Each subcommand of the `finseg` command line lives in its own file and registers here.
#pragma once

#include <CLI/CLI.hpp>

namespace finseg::cli {

/// Thrown by a subcommand that finished its work but must exit non-zero (e.g. 3: the
/// simulation diverged); main() returns `code`.
struct ExitStatus {
  int code = 0;
};

void register_run(CLI::App& app);  ///< finseg run SCENE --out DIR
void register_gen(CLI::App& app);  ///< finseg gen cantilever|zigzag|miura|cone ...
/// finseg gen miura|cone: a FOLD pattern and a scene (called by register_gen).
void register_pattern_generators(CLI::App* gen);
void register_inspect(CLI::App& app);   ///< finseg inspect SCENE
void register_modes(CLI::App& app);     ///< finseg modes SCENE
void register_identify(CLI::App& app);  ///< finseg identify bending|crease DATA
void register_compare(CLI::App& app);   ///< finseg compare SIM.csv EXP.csv...
void register_pattern(CLI::App& app);   ///< finseg pattern check|info|zigzag ...
void register_overlay(CLI::App& app);   ///< finseg overlay DIR... --out FILE
void register_sweep(CLI::App& app);     ///< finseg sweep SWEEP.yaml --out DIR
void register_fit(CLI::App& app);       ///< finseg fit FIT.yaml --out DIR

}  // namespace finseg::cli
