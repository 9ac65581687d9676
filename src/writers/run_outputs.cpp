#include "writers/run_outputs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/warnings.hpp"
#include "writers/atomic_write.hpp"
#include "writers/html_animation.hpp"
#include "writers/plot.hpp"
#include "writers/provenance.hpp"
#include "writers/vtk.hpp"

namespace finseg {
namespace {

namespace fs = std::filesystem;

nlohmann::json solver_json(const SolverSettings& s) {
  return {{"type", solver_name(s.kind)},
          {"t_end_s", s.t_end},
          {"output_interval_s", s.output_interval},
          {"dt_s", s.dt},
          {"dt_min_s", s.dt_min},
          {"dt_max_s", s.dt_max},
          {"rtol", s.rtol},
          {"atol", s.atol},
          {"load_steps", s.load_steps},
          {"max_iterations", s.max_iterations},
          {"tolerance", s.tolerance}};
}

nlohmann::json stats_json(const SolverStats& s) {
  return {{"steps", s.steps},
          {"rejected_steps", s.rejected_steps},
          {"newton_iterations", s.newton_iterations},
          {"force_evaluations", s.force_evaluations},
          {"jacobian_evaluations", s.jacobian_evaluations},
          {"settles", s.settles},
          {"smallest_step_s", s.smallest_step},
          {"largest_step_s", s.largest_step},
          {"solver_wall_s", s.wall_seconds}};
}

int column(const ProbeTable& t, const std::string& name) {
  const auto it = std::find(t.columns.begin(), t.columns.end(), name);
  return it == t.columns.end() ? -1 : static_cast<int>(it - t.columns.begin());
}

// Force against pull displacement (mm) of a drive probe.
Curve drive_curve(const ProbeTable& t) {
  Curve c{"pull displacement [mm]", t.name + " force [N]", {}, {}};
  for (const auto& r : t.rows) {
    c.x.push_back(1e3 * r[0]);
    c.y.push_back(r[1]);
  }
  return c;
}

std::vector<PlotMarker> phase_markers(const DeploymentPhases& p) {
  std::vector<PlotMarker> m;
  if (std::isfinite(p.initial_deformation))
    m.push_back({1e3 * p.initial_deformation, "initial deformation"});
  if (std::isfinite(p.contact)) m.push_back({1e3 * p.contact, "contact"});
  if (std::isfinite(p.bending)) m.push_back({1e3 * p.bending, "panel bending"});
  // Phases that begin at the same output share one marker (their labels would overlap).
  std::vector<PlotMarker> merged;
  for (const PlotMarker& k : m) {
    if (!merged.empty() && merged.back().x == k.x) {
      merged.back().label += " + " + k.label;
    } else {
      merged.push_back(k);
    }
  }
  return merged;
}

nlohmann::json phases_json(const DeploymentPhases& p, const PhaseSettings& s) {
  auto value = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
  return {{"initial_deformation_m", value(p.initial_deformation)},
          {"contact_m", value(p.contact)},
          {"bending_m", value(p.bending)},
          {"watched_panels", s.panels},
          {"bend_threshold_deg", s.bend_threshold / kDegToRad},
          {"rule",
           "contact: first output with an active contact point; bending: first later output "
           "where a watched panel's bend exceeds the threshold"}};
}

// One CSV line of text cells (a header).
std::string csv_line(const std::vector<std::string>& cells) {
  std::string out;
  for (std::size_t c = 0; c < cells.size(); ++c) out += (c ? "," : "") + cells[c];
  return out + "\n";
}

// Numbers of one CSV row (12 significant digits), without the line end.
std::string csv_numbers(const std::vector<double>& values) {
  std::string out;
  for (std::size_t c = 0; c < values.size(); ++c)
    out += fmt::format("{}{:.12g}", c ? "," : "", values[c]);
  return out;
}

// Writes one CSV file of the run and lists it in the report.
void write_csv(const std::string& dir, const std::string& file, const std::string& text,
               RunReport& report) {
  write_file_atomically((fs::path(dir) / file).string(), text);
  report.files.push_back(file);
}

// Runs an optional writer; a failure becomes a warning instead of losing the run.
template <class F>
void optional_output(RunReport& report, const std::string& file, F&& write) {
  try {
    write();
    report.files.push_back(file);
  } catch (const std::exception& e) {
    report.warnings.push_back(fmt::format("{} not written: {}", file, e.what()));
  }
}

}  // namespace

nlohmann::json model_counts(const Model& m) {
  double mass = 0;
  int fixed = 0;
  for (const BodyDef& b : m.bodies) {
    mass += b.mass;
    fixed += b.fixed ? 1 : 0;
  }
  return {
      {"bodies", m.bodies.size()},   {"fixed_bodies", fixed},     {"elements", m.elements.size()},
      {"creases", m.creases.size()}, {"dofs", m.num_dofs},        {"mass_kg", mass},
      {"loads", m.loads.size()},     {"drives", m.drives.size()}, {"probes", m.probes.size()},
      {"contact", m.contact.enabled}};
}

std::string probe_csv(const ProbeTable& t) {
  std::string out = csv_line(t.columns);
  for (const auto& r : t.rows) out += csv_numbers(r) + "\n";
  return out;
}

std::string pairs_file(const ProbeTable& t) {
  return t.name + "_pairs.csv";
}

std::string pairs_csv(const ProbeTable& t, const Model& model) {
  std::string out =
      csv_line({t.columns[0], "body_a", "body_b", "points", "normal_force_N", "friction_force_N",
                "max_penetration_m", "fx_b_N", "fy_b_N", "fz_b_N"});
  for (const PairSample& s : t.pair_rows) {
    const ContactPairForce& p = s.force;
    out += fmt::format("{:.12g},{},{},", s.x, model.bodies[p.a].name, model.bodies[p.b].name);
    out += csv_numbers({static_cast<double>(p.points), p.normal_force, p.friction_force,
                        p.max_penetration, p.f_b_W.x(), p.f_b_W.y(), p.f_b_W.z()}) +
           "\n";
  }
  return out;
}

nlohmann::json probe_summary(const ProbeTable& t) {
  nlohmann::json j{{"type", probe_kind_name(t.kind)},
                   {"file", t.name + ".csv"},
                   {"rows", t.rows.size()},
                   {"columns", t.columns}};
  if (t.pairs) {
    j["pairs_file"] = pairs_file(t);
    j["pair_rows"] = t.pair_rows.size();
  }
  if (t.rows.empty()) return j;
  const auto& last = t.rows.back();
  if (t.kind == ProbeKind::Point) {
    j["final"] = {last[1], last[2], last[3]};
  } else {
    nlohmann::json f;
    for (std::size_t c = 0; c < t.columns.size(); ++c) f[t.columns[c]] = last[c];
    j["final"] = f;
  }
  if (t.kind == ProbeKind::Drive) {
    const int fc = column(t, "force_N");
    std::size_t best = 0;
    for (std::size_t r = 1; r < t.rows.size(); ++r) {
      if (t.rows[r][fc] > t.rows[best][fc]) best = r;
    }
    j["peak_force_N"] = t.rows[best][fc];
    j["peak_displacement_m"] = t.rows[best][0];
  }
  return j;
}

RunReport write_run_outputs(const std::string& dir, const Scene& scene, const RunRecorder& rec,
                            const SolverStats& stats, double wall_seconds) {
  fs::create_directories(dir);
  RunReport report;
  nlohmann::json probes = nlohmann::json::object();
  const ProbeTable* first_drive = nullptr;
  for (const ProbeTable& t : rec.tables()) {
    write_csv(dir, t.name + ".csv", probe_csv(t), report);
    if (t.pairs) write_csv(dir, pairs_file(t), pairs_csv(t, scene.model), report);
    probes[t.name] = probe_summary(t);
    if (t.kind == ProbeKind::Drive && !first_drive) first_drive = &t;
  }
  const OutputSettings& o = scene.outputs;
  DeploymentPhases phases{NAN, NAN, NAN};
  if (o.phases.enabled && !rec.phase_samples().empty()) {
    phases = detect_phases(rec.phase_samples(), o.phases.bend_threshold);
    std::string csv = "pull_displacement_m,active_contacts,watched_bend_deg\n";
    for (const PhaseSample& p : rec.phase_samples()) {
      csv += fmt::format("{:.12g},{},{:.12g}\n", p.displacement, p.active_contacts,
                         p.bend / kDegToRad);
    }
    write_csv(dir, "phases.csv", csv, report);
  }
  const std::string title =
      scene.title.empty() ? fs::path(scene.file).stem().string() : scene.title;
  if (o.plot) {
    for (const ProbeTable& t : rec.tables()) {
      if (t.kind != ProbeKind::Drive) continue;
      const Curve c = drive_curve(t);
      PlotSpec spec{title + ": " + t.name, c.x_label, c.y_label, {{t.name, c.x, c.y, "lines"}}, {}};
      if (&t == first_drive && o.phases.enabled) spec.markers = phase_markers(phases);
      optional_output(report, t.name + ".png",
                      [&] { write_plot((fs::path(dir) / (t.name + ".png")).string(), spec); });
    }
  }
  if (o.vtk && !rec.frames().empty()) {
    optional_output(report, "vtk/frames.pvd", [&] {
      write_vtk_series((fs::path(dir) / "vtk").string(), "frames", scene.model, rec.frames());
    });
  }
  if (o.html && !rec.frames().empty()) {
    const Curve curve = first_drive ? drive_curve(*first_drive) : Curve{};
    const std::string label = rec.abscissa() == "t_s"          ? "time [s]"
                              : rec.abscissa() == "load_scale" ? "load scale [-]"
                                                               : "pull displacement [m]";
    optional_output(report, "animation.html", [&] {
      write_html_animation((fs::path(dir) / "animation.html").string(), title, scene.model,
                           rec.frames(), curve, label);
    });
  }
  nlohmann::json j{{"scene", scene.file},
                   {"title", title},
                   {"status", stats.status},
                   {"message", stats.message},
                   {"wall_time_s", wall_seconds},
                   {"solver", solver_json(scene.solver)},
                   {"stats", stats_json(stats)},
                   {"model", model_counts(scene.model)},
                   {"abscissa", rec.abscissa()},
                   {"outputs", rec.outputs()},
                   {"probes", probes},
                   {"files", report.files},
                   {"warnings", report.warnings}};
  if (o.phases.enabled) j["phases"] = phases_json(phases, o.phases);
  j["provenance"] = provenance_json(scene);
  for (const std::string& w : recorded_warnings()) j["warnings"].push_back(w);
  write_file_atomically((fs::path(dir) / "summary.json").string(), j.dump(2) + "\n");
  report.files.push_back("summary.json");
  return report;
}

}  // namespace finseg
