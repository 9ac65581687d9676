// `--set key.path=value`: changes to a scene's YAML made on the command line, applied before
// the scene is read, so that every check of the scene applies to them too (docs/scene.md,
// "Overrides").
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace finseg {

/// One override: a dotted path through the scene's maps (keys) and lists (indices from 0),
/// e.g. "drives.0.speed", and a YAML value, e.g. "0.01", "[0, 0, -9.81]" or "true".
struct Override {
  std::string path;
  std::string value;
};

/// Splits "key.path=value" at its first '='. Throws InputError (field "--set") if there is
/// no '=' or the path is empty or has an empty part.
Override parse_override(const std::string& text);

/// Sets each override in `root` (a scene's top-level map), in order. Every map key and list
/// index on the way must exist; the last key of a map may be new (the section's own check
/// then refuses a key it does not know). Throws InputError naming `file`, the path and what
/// is wrong.
void apply_overrides(YAML::Node& root, const std::vector<Override>& overrides,
                     const std::string& file);

}  // namespace finseg
