// Atomic file output for writers: content goes to `path.partial` first and is renamed onto
// `path` only once it is complete, so a crash never leaves a half-written file that looks
// finished.
#pragma once

#include <string>

namespace finseg {

/// Writes `content` to `path` atomically. Throws std::runtime_error naming the path and the
/// system's reason if the file cannot be written or renamed.
void write_file_atomically(const std::string& path, const std::string& content);

/// Reads a whole file into a string; throws std::runtime_error naming the path if it can't.
std::string read_whole_file(const std::string& path);

}  // namespace finseg
