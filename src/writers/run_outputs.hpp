// Everything `finseg run` leaves in its output folder (docs/scene.md, "Run outputs"):
// one CSV per probe, optional VTK frames, HTML page and force plots, and summary.json,
// written last. Every file is written atomically.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "probes/recorder.hpp"
#include "scene/scene_reader.hpp"

namespace finseg {

/// Counts of a model: bodies, elements, creases, dofs, fixed bodies, mass_kg, loads, drives,
/// probes, contact (enabled flag).
nlohmann::json model_counts(const Model& model);

/// CSV text of a probe table: header of unit-carrying names, one row per output.
std::string probe_csv(const ProbeTable& table);

/// Per-probe summary: file, type, rows, final (point: [x, y, z] m; others: last row by
/// column name) and, for drive probes, peak_force_N and peak_displacement_m.
nlohmann::json probe_summary(const ProbeTable& table);

/// What a finished (or diverged) run produced.
struct RunReport {
  std::vector<std::string> files;     ///< written, relative to the output folder
  std::vector<std::string> warnings;  ///< optional outputs that could not be written
};

/// Writes the run's files into `dir` (created if needed); summary.json is written last.
/// `wall_seconds` is the whole run's wall time.
RunReport write_run_outputs(const std::string& dir, const Scene& scene, const RunRecorder& rec,
                            const SolverStats& stats, double wall_seconds);

}  // namespace finseg
