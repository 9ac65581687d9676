// The animation frames of a checkpoint, in a binary file beside it (DIR/checkpoint.json.frames)
// that grows by the frames recorded since the last checkpoint instead of being rewritten with
// all of them: at 10^4 segments a frame is about 8 MB of JSON, so checkpoints that held every
// frame grew to hundreds of MB each (docs/state-file.md, "Checkpoints").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "writers/frames.hpp"

namespace finseg {

/// Name of the frame file beside DIR/checkpoint.json.
inline constexpr const char* kCheckpointFramesFile = "checkpoint.json.frames";

/// Brings the frame file `path` to hold exactly `frames`, recorded by the run whose scene hash
/// is `run_hash`: keeps the leading frames it already holds (same run, same times), drops the
/// rest and appends the others. Returns its size in bytes. Throws OutputError if it cannot be
/// written.
std::uint64_t sync_frame_file(const std::string& path, const std::string& run_hash,
                              const std::vector<Frame>& frames);

/// The first `count` frames of `path`, which a checkpoint of run `run_hash` says fill its first
/// `bytes`; the file is cut back to `bytes` (frames appended after that checkpoint belong to a
/// run that did not reach the next one). Throws InputError naming the file when it is shorter,
/// of another run, or its frames do not fill `bytes`.
std::vector<Frame> read_frame_file(const std::string& path, const std::string& run_hash,
                                   std::size_t count, std::uint64_t bytes);

}  // namespace finseg
