// The output folder of `finseg run`: checked before the simulation starts (so that nothing
// fails at write time after a long run), and owned through a manifest (DIR/manifest.json
// lists the files the run wrote; the next run into DIR removes exactly those).
#pragma once

#include <string>
#include <vector>

#include "scene/scene_reader.hpp"

namespace finseg {

/// File name of the manifest inside a run's output folder.
inline constexpr const char* kManifestFile = "manifest.json";

/// Longest probe name, bytes (its files add "_pairs.csv"; file systems allow 255 bytes).
inline constexpr std::size_t kMaxNameBytes = 200;

/// True when `text` is valid UTF-8 (no overlong forms, surrogates or code points > U+10FFFF).
bool is_valid_utf8(const std::string& text);

/// Creates `dir` if needed and checks that the run's outputs can be written there: the folder
/// is writable (a probe file is created and removed), every output file name is valid and
/// distinct (probe names: 1..200 bytes, no '/', NUL or control characters, not "." or ".."),
/// and every text that goes into the outputs is valid UTF-8 (title, probe and body names, the
/// scene's path). Throws InputError naming the scene field or --out.
void check_output_folder(const std::string& dir, const Scene& scene);

/// Removes what the previous run into `dir` listed in its manifest (only files inside `dir`;
/// folders it leaves empty go too), except the files named in `keep`.
void remove_previous_run(const std::string& dir, const std::vector<std::string>& keep = {});

/// Writes `dir`/manifest.json listing `files` (paths relative to `dir`; "vtk/frames.pvd"
/// stands for every file of the VTK series in `dir`/vtk) and the manifest itself.
void write_manifest(const std::string& dir, const std::vector<std::string>& files);

}  // namespace finseg
