// Scene files (YAML, docs/scene.md): material, sheet, discretisation, fixtures, loads,
// drives, probes, contact, solver and outputs -> a Model plus run settings.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "generators/folding.hpp"
#include "model/model.hpp"
#include "probes/deployment_phases.hpp"
#include "scene/overrides.hpp"
#include "solvers/solver.hpp"

namespace finseg {

/// Deployment-phase detection of a pull test (probes/deployment_phases.hpp).
struct PhaseSettings {
  bool enabled = false;
  std::vector<int> panels{2, 5};                  ///< watched panels, 1-based
  double bend_threshold = kDefaultBendThreshold;  ///< rad (scene key bend_threshold_deg)
};

/// What `finseg run` writes besides the probe CSVs and summary.json (scene `outputs:`).
/// Defaults: all on for scenes with a drive, off otherwise.
struct OutputSettings {
  bool vtk = false;   ///< DIR/vtk/frames.pvd + .vtu
  bool html = false;  ///< DIR/animation.html
  bool plot = false;  ///< DIR/<drive probe>.png: force against pull displacement
  PhaseSettings phases;
};

/// A scene read from a file: the model and how to run it.
struct Scene {
  std::string file;          ///< path it was read from
  std::string title;         ///< optional `title:`
  bool zigzag = false;       ///< built by the zigzag generator (`zigzag:` section)
  std::string pattern_file;  ///< FOLD file the structure was cut from (`pattern:`), if any
  Model model;
  SolverSettings solver;
  OutputSettings outputs;
  /// `folding:` (docs/folding.md): how `finseg run --fold` folds the sheet, and its solver.
  std::optional<FoldingSpec> folding;
  SolverSettings folding_solver;
  std::vector<Override> overrides;  ///< `--set` changes applied on top of the file
  std::string start_state;          ///< state file the run starts from (`--state`), if any
};

/// Reads and validates a scene file (read once), with `overrides` (scene/overrides.hpp) set in
/// its YAML first. Throws InputError naming the file, the dotted field and the allowed range.
Scene read_scene(const std::string& path, const std::vector<Override>& overrides = {});

/// Same from YAML text; `file` names it in messages and resolves relative data files.
Scene parse_scene(const std::string& yaml, const std::string& file,
                  const std::vector<Override>& overrides = {});

/// Name of a solver kind as written in scene files: static, implicit, explicit.
std::string solver_name(SolverKind kind);
/// Scene-file word of an implicit scheme: "backward_euler" or "generalized_alpha".
std::string scheme_name(ImplicitScheme scheme);
/// The scene's word for SolverSettings::error_at_points: "points" or "dofs".
std::string error_measure_name(bool at_points);

}  // namespace finseg
