// Sweep files (docs/sweep.md): a base scene, parameters with lists or ranges of values for
// `--set` paths, full factorial or listed cases, and the summary.json keys to tabulate.
#pragma once

#include <string>
#include <vector>

#include "scene/overrides.hpp"

namespace finseg {

/// One swept parameter: a `--set` path and its values as YAML text.
struct SweepParameter {
  std::string path;
  std::vector<std::string> values;
};

/// A sweep as read from its file.
struct SweepSpec {
  std::string file;   ///< the sweep file, for messages
  std::string scene;  ///< base scene, resolved against the sweep file's folder
  std::vector<SweepParameter> parameters;
  bool listed = false;               ///< case k takes value k of every parameter
  std::vector<std::string> outputs;  ///< dotted summary.json keys, e.g. "wall_time_s"
};

/// Reads and validates a sweep file. Throws InputError naming the file and the field.
SweepSpec read_sweep(const std::string& path);

/// The cases as override lists: full factorial (the last parameter varies fastest) or listed.
std::vector<std::vector<Override>> sweep_cases(const SweepSpec& spec);

}  // namespace finseg
