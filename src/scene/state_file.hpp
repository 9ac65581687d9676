// State files: a State (poses, velocities, drives, crease and contact history, solver
// memory) as JSON text, tied to the model it belongs to (docs/state-file.md). `finseg run`
// writes its checkpoints in this format and starts from one with --resume or --state.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "model/model.hpp"
#include "model/state.hpp"

namespace finseg {

/// A State with the identity of the model and scene it was computed for.
struct StateSnapshot {
  State state;
  std::string scene_hash;  ///< scene_hash() of the scene file's text ("" if not known)
  /// The state file a run started from (`--state`, as given; "" for the scene's initial
  /// state): a checkpoint's model depends on it, so `--resume` needs it again.
  std::string start_state = {};
};

/// Fingerprint of a scene file's text (64-bit FNV-1a, as 16 hex digits).
std::string scene_hash(const std::string& scene_text);

/// JSON of a State: format, version, model counts, scene_hash and the state's fields.
nlohmann::json state_json(const Model& model, const StateSnapshot& snapshot);

/// Reads a state_json() object back, checking it against `model`. Throws InputError naming
/// `file` and the field (e.g. "bodies[3].R_WB") when a field is missing, malformed or does
/// not match the model.
StateSnapshot parse_state_json(const nlohmann::json& j, const Model& model,
                               const std::string& file);

/// Writes a state file atomically.
void write_state_file(const std::string& path, const Model& model, const StateSnapshot& snapshot);

/// Reads and validates a state file (any extra top-level keys are ignored).
StateSnapshot read_state_file(const std::string& path, const Model& model);

}  // namespace finseg
