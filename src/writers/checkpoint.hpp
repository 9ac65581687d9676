// Checkpoints of `finseg run` (DIR/checkpoint.json): a state file (scene/state_file.hpp)
// taken at an output, plus everything recorded up to that output, so that
// `finseg run --resume` continues the run and writes the same files an uninterrupted run
// would (docs/state-file.md).
#pragma once

#include <string>

#include "probes/recorder.hpp"
#include "scene/state_file.hpp"

namespace finseg {

/// File name of the checkpoint inside a run's output folder.
inline constexpr const char* kCheckpointFile = "checkpoint.json";

/// Writes `dir`/checkpoint.json atomically: the state at the recorder's last output and the
/// recorder's tables, frames and phase samples.
void write_checkpoint(const std::string& dir, const Model& model, const StateSnapshot& snapshot,
                      const RunRecorder& rec);

/// Reads `path` (a checkpoint), checks it against `model` and restores `rec` from it.
/// Returns the state to continue from. Throws InputError naming the file and field.
StateSnapshot read_checkpoint(const std::string& path, const Model& model, RunRecorder& rec);

}  // namespace finseg
