// Records every probe of a model at each solver output (one table per probe, one row per
// output; a contact probe with `pairs` also keeps every touching pair's forces), plus
// animation frames and deployment-phase samples when asked. `finseg run` writes the tables
// as CSV (docs/scene.md lists the columns).
#pragma once

#include <string>
#include <vector>

#include "collision/contact_forces.hpp"
#include "elements/assemble.hpp"
#include "model/model.hpp"
#include "model/state.hpp"
#include "probes/deployment_phases.hpp"
#include "probes/unfolding.hpp"
#include "solvers/solver.hpp"
#include "writers/frames.hpp"

namespace finseg {

/// One touching pair at one output, for contact probes with `pairs`.
struct PairSample {
  double x = 0;  ///< the run's abscissa at that output
  ContactPairForce force;
};

/// Recorded history of one probe, or of one chamber's gas (after the probes, one per
/// chamber); every column name carries its unit (e.g. "z_m").
struct ProbeTable {
  std::string name;
  ProbeKind kind = ProbeKind::Point;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  bool pairs = false;                 ///< contact probe recording per-pair forces
  std::vector<PairSample> pair_rows;  ///< when `pairs`: every touching pair of every output
};

/// What the run's x axis is: "t_s" (dynamic solvers), "pull_displacement_m" (static solver
/// pulling its first drive), "load_scale" (static solver, loads only).
std::string abscissa_column(const Model& model, const SolverSettings& settings);

/// Name of a chamber's table and file stem: "chamber_<name>".
std::string chamber_table_name(const ChamberDef& chamber);

/// Name of a probe kind as written in scene files.
std::string probe_kind_name(ProbeKind kind);

struct RecorderOptions {
  bool frames = false;              ///< keep a Frame per output (VTK, HTML)
  bool phases = false;              ///< keep a PhaseSample per output
  std::vector<int> watched_panels;  ///< 0-based panels for PhaseSample::bend
};

class RunRecorder {
 public:
  RunRecorder(const Model& model, const SolverSettings& settings, RecorderOptions options);

  /// Appends one row to every table (and a frame / phase sample). Use as OutputCallback.
  void record(const State& state, const BodyForces& forces);

  const std::vector<ProbeTable>& tables() const { return tables_; }
  const std::vector<Frame>& frames() const { return frames_; }
  const std::vector<PhaseSample>& phase_samples() const { return samples_; }
  /// Abscissa of the last recorded output (NaN before the first).
  double last_abscissa() const { return last_x_; }
  const std::string& abscissa() const { return abscissa_; }
  std::size_t outputs() const { return outputs_; }  ///< outputs recorded so far
  /// The lines of table k when it is an unfolding probe's (empty for other tables).
  const std::vector<UnfoldingLine>& unfolding_lines_of(std::size_t k) const;

  /// Replaces what was recorded by what a checkpoint saved (`finseg run --resume`): tables
  /// are this recorder's (same probes, same order) with their rows.
  void restore(std::vector<ProbeTable> tables, std::vector<Frame> frames,
               std::vector<PhaseSample> samples, double last_x, std::size_t outputs);

 private:
  std::vector<double> row(std::size_t probe, const State& s, const BodyForces& f,
                          const ContactSummary* contact) const;

  const Model& model_;
  RecorderOptions options_;
  std::string abscissa_;
  bool dynamic_ = false;
  std::vector<ProbeTable> tables_;
  std::vector<std::vector<int>> crease_elements_;  ///< per probe: a crease probe's elements
  std::vector<std::vector<UnfoldingLine>> lines_;  ///< per probe: an unfolding probe's lines
  std::vector<Frame> frames_;
  std::vector<PhaseSample> samples_;
  double last_x_;
  std::size_t outputs_ = 0;
};

}  // namespace finseg
