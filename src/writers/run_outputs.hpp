// Everything `finseg run` leaves in its output folder (docs/scene.md, "Run outputs"):
// one CSV per probe (and the per-pair contact forces on request), optional VTK frames, HTML
// page and force plots, and summary.json, written last. Every file is written atomically.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "probes/recorder.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/run_stage.hpp"

namespace finseg {

/// Counts of a model: bodies, elements, creases, dofs, fixed bodies, mass_kg, loads, drives,
/// probes, contact (enabled flag).
nlohmann::json model_counts(const Model& model);

/// CSV text of a probe table: header of unit-carrying names, one row per output.
std::string probe_csv(const ProbeTable& table);

/// Name of a contact probe's per-pair file: "<probe>_pairs.csv".
std::string pairs_file(const ProbeTable& table);

/// CSV text of a contact probe's pairs (table.pairs): the abscissa, body_a, body_b (names
/// in `model`), points, normal_force_N, friction_force_N, max_penetration_m and
/// fx_b_N, fy_b_N, fz_b_N (resultant contact force on body_b, world frame); one row per
/// touching pair per output.
std::string pairs_csv(const ProbeTable& table, const Model& model);

/// DriveDef::deployed_at of the drive a drive probe reads (matched by probe name), m; 0 when
/// not known or not a drive probe.
double deployed_at_of(const Model& model, const ProbeTable& table);

/// Per-probe summary: file, type, rows, final (point: [x, y, z] m; others: last row by
/// column name); for contact probes with pairs pairs_file and pair_rows; for drive probes
/// peak_force_N / peak_displacement_m (largest force over the whole travel),
/// deployment_peak_force_N / deployment_peak_displacement_m (find_deployment_peak over
/// deployment_window_m = [first displacement, `deployed_at` m or the travel's end when 0];
/// null when there is none) and end_force_N / end_displacement_m (the last row).
nlohmann::json probe_summary(const ProbeTable& table, double deployed_at = 0);

/// What `finseg run` records besides the probe tables for `scene`'s outputs: frames when VTK
/// or HTML is on, phase samples (and the watched panels) when phases are on.
RecorderOptions recorder_options(const Scene& scene);

/// What a finished (or diverged) run produced.
struct RunReport {
  std::vector<std::string> files;     ///< written, relative to the output folder
  std::vector<std::string> warnings;  ///< optional outputs that could not be written
  nlohmann::json summary;             ///< summary.json's object
};

/// summary.json's object (docs/scene.md): scene, status, solver and its statistics, model
/// counts, probe_summary per probe, phases, provenance and warnings, and `stages` where there
/// were any; `report` gives the files written and the warnings of outputs not written (none
/// when nothing was written).
nlohmann::json run_summary(const Scene& scene, const RunRecorder& rec, const SolverStats& stats,
                           double wall_seconds, const RunReport& report = {},
                           const std::vector<RunStage>& stages = {});

/// Writes the run's files into `dir` (created if needed); summary.json is written last.
/// `wall_seconds` is the whole run's wall time; `on_progress` gets the fraction of the VTK
/// frames written (the long part of large outputs); `stages` go into summary.json.
RunReport write_run_outputs(const std::string& dir, const Scene& scene, const RunRecorder& rec,
                            const SolverStats& stats, double wall_seconds,
                            const std::function<void(double)>& on_progress = {},
                            const std::vector<RunStage>& stages = {});

}  // namespace finseg
