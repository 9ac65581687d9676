// Provenance of a run for summary.json: which finseg, when, and the hashes of the scene
// and of every data file it read.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_reader.hpp"

namespace finseg {

/// SHA-256 (lowercase hex) of a file's bytes, with OpenSSL's libcrypto. Throws
/// std::runtime_error naming the file if it cannot be read.
std::string sha256_file(const std::string& path);

/// Current time in UTC, ISO 8601 to the second, e.g. "2026-11-23T21:30:00Z".
std::string utc_now_iso8601();

/// The data files a scene's model read (its FOLD pattern, then the crease-law CSVs), each
/// once, in model order.
std::vector<std::string> scene_data_files(const Scene& scene);

/// The `scene_hash` of a run's checkpoint (docs/state-file.md): the scene's text, then each
/// of its data files' bytes, then its `--set` overrides, so that a resume is refused when any
/// of them changed.
std::string scene_inputs_hash(const std::string& scene_text, const Scene& scene);

/// {finseg_version, git_revision, date_utc, scene: {file, sha256}, data_files: [{file,
/// sha256}]} with data_files the crease-law CSVs of the scene's model (each once), hashed
/// when called; sha256 is null for a file that cannot be read.
nlohmann::json provenance_json(const Scene& scene);

}  // namespace finseg
