#include "writers/run_outputs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/threads.hpp"
#include "core/warnings.hpp"
#include "probes/deployment_peak.hpp"
#include "writers/atomic_write.hpp"
#include "writers/html_animation.hpp"
#include "writers/json_numbers.hpp"
#include "writers/plot.hpp"
#include "writers/provenance.hpp"
#include "writers/unfolding_outputs.hpp"
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
          {"scheme", scheme_name(s.scheme)},
          {"rho_inf", s.rho_inf},
          {"load_steps", s.load_steps},
          {"max_iterations", newton_iterations(s)},
          {"tolerance", s.tolerance},
          {"jacobian_reuse", s.jacobian_reuse},
          {"jacobian_max_age", s.jacobian_max_age},
          {"krylov_steps", s.krylov_steps},
          {"newton_tolerance", s.newton_tolerance},
          {"error_measure", error_measure_name(s.error_at_points)}};
}

nlohmann::json linear_json(const LinearSolveCounters& c) {
  return {{"calls", c.solves},
          {"analyses", c.analyses},
          {"factorizations", c.factorizations},
          {"lu_factorizations", c.lu_factorizations},
          {"indefinite", c.indefinite},
          {"refinements", c.refinements},
          {"analyse_s", c.analyse_s},
          {"factor_s", c.factor_s},
          {"total_s", c.total_s}};
}

nlohmann::json stats_json(const SolverStats& s) {
  return {{"steps", s.steps},
          {"rejected_steps", s.rejected_steps},
          {"newton_failures", s.newton_failures},
          {"newton_iterations", s.newton_iterations},
          {"force_evaluations", s.force_evaluations},
          {"jacobian_evaluations", s.jacobian_evaluations},
          {"factorizations", s.factorizations},
          {"krylov_steps", s.krylov_steps},
          {"krylov_iterations", s.krylov_iterations},
          {"secant_solves", s.secant_solves},
          {"settles", s.settles},
          {"smallest_step_s", s.smallest_step},
          {"largest_step_s", s.largest_step},
          {"solver_wall_s", s.wall_seconds},
          {"linear_solves", linear_json(s.linear)}};
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

// How the run's abscissa is shown on charts and the HTML slider (a pull in mm).
FrameAxis abscissa_axis(const std::string& abscissa) {
  if (abscissa == "t_s") return {"time [s]", 1};
  if (abscissa == "load_scale") return {"load scale [-]", 1};
  return {"pull displacement [mm]", 1e3};
}

bool has_time_curve(const ProbeTable& t) {
  return t.kind == ProbeKind::Chamber || t.kind == ProbeKind::Shape ||
         t.kind == ProbeKind::Unfolding;
}

// A chamber's pressure (Pa), a shape's RMS distance (mm) or the count of folds at least half
// open against the run's abscissa.
Curve time_curve(const ProbeTable& t, const std::string& abscissa) {
  const FrameAxis axis = abscissa_axis(abscissa);
  if (t.kind == ProbeKind::Unfolding) return unfolding_curve(t.name, t.rows, axis);
  const bool shape = t.kind == ProbeKind::Shape;
  Curve c{axis.label, t.name + (shape ? " RMS distance [mm]" : " pressure [Pa]"), {}, {}};
  for (const auto& r : t.rows) {
    c.x.push_back(axis.scale * r[0]);
    c.y.push_back(shape ? 1e3 * r[1] : r[1]);
  }
  return c;
}

// Largest value of every column of a chamber's table, and where the pressure peaked.
void add_chamber_peaks(const ProbeTable& t, nlohmann::json& j) {
  nlohmann::json peak;
  std::size_t at = 0;
  for (std::size_t c = 1; c < t.columns.size(); ++c) {
    double largest = t.rows[0][c];
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      if (t.rows[r][c] <= largest) continue;
      largest = t.rows[r][c];
      if (t.columns[c] == "pressure_Pa") at = r;
    }
    peak[t.columns[c]] = largest;
  }
  j["peak"] = peak;
  j["peak_pressure_at"] = t.rows[at][0];  // in the abscissa's unit (t_s: s)
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
  return {{"initial_deformation_m", or_null(p.initial_deformation)},
          {"contact_m", or_null(p.contact)},
          {"bending_m", or_null(p.bending)},
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

// Largest force, deployment peak and end-of-travel force of a drive probe (docs/scene.md).
void add_drive_peaks(const ProbeTable& t, double deployed_at, nlohmann::json& j) {
  const int fc = column(t, "force_N");
  std::vector<double> x, f;
  for (const auto& r : t.rows) x.push_back(r[0]), f.push_back(r[fc]);
  const int best = max_force_index(x, f, -INFINITY, INFINITY);
  j["peak_force_N"] = f[best];
  j["peak_displacement_m"] = x[best];
  const double hi = deployed_at > 0 ? deployed_at : INFINITY;
  const DeploymentPeak p = find_deployment_peak(x, f, -INFINITY, hi);
  j["deployment_peak_force_N"] = or_null(p.force);
  j["deployment_peak_displacement_m"] = or_null(p.x);
  j["deployment_window_m"] = {x.front(), std::min(hi, x.back())};
  j["deployed_at_m"] = deployed_at > 0 ? nlohmann::json(deployed_at) : nlohmann::json();
  j["end_force_N"] = f.back();
  j["end_displacement_m"] = x.back();
}

// Deployment peak and, where it differs, the largest force of a drive probe's summary, in
// the plot's units (mm, N).
std::vector<ChartMark> peak_marks(const nlohmann::json& s) {
  std::vector<ChartMark> m;
  if (!s.contains("peak_force_N")) return m;
  const double px = s["peak_displacement_m"], pf = s["peak_force_N"];
  if (!s["deployment_peak_force_N"].is_null()) {
    const double dx = s["deployment_peak_displacement_m"], df = s["deployment_peak_force_N"];
    m.push_back({1e3 * dx, df, fmt::format("deployment peak {:.4g} N", df)});
    if (dx == px) return m;
  }
  m.push_back({1e3 * px, pf, fmt::format("largest force {:.4g} N", pf)});
  return m;
}

// Banner of a run that did not finish (status other than "ok"); empty for a finished one.
std::string unfinished_warning(const SolverStats& stats) {
  if (stats.status == "ok") return "";
  std::string status = stats.status;
  for (char& c : status) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return fmt::format("RUN {} - not finished, results end early{}{}", status,
                     stats.message.empty() ? "" : ": ", stats.message);
}

// A run's unfinished warning as a plot's banner: the full message is in summary.json and on
// the HTML page; a plot line must fit.
std::string plot_warning(const std::string& warning) {
  return warning.size() > 110 ? warning.substr(0, 107) + "..." : warning;
}

// The run's title: the scene's, else its file name without extension.
std::string run_title(const Scene& scene) {
  return scene.title.empty() ? fs::path(scene.file).stem().string() : scene.title;
}

// Deployment phases of a run (NaN where not found or phases are off).
DeploymentPhases run_phases(const Scene& scene, const RunRecorder& rec) {
  const PhaseSettings& p = scene.outputs.phases;
  if (!p.enabled || rec.phase_samples().empty()) return {NAN, NAN, NAN};
  return detect_phases(rec.phase_samples(), p.bend_threshold);
}

// An unfolding probe's order (CSV) and, with plots, its curves and its map of the sheet.
void write_unfolding_files(const std::string& dir, const std::string& title,
                           const std::string& warning, const RunRecorder& rec, std::size_t k,
                           bool plot, RunReport& report) {
  const ProbeTable& t = rec.tables()[k];
  const std::vector<UnfoldingLine>& lines = rec.unfolding_lines_of(k);
  const std::vector<LineOpening> order = unfolding_order(t.rows, lines);
  write_csv(dir, unfolding_order_file(t.name), unfolding_order_csv(order, rec.abscissa()), report);
  if (!plot || t.rows.empty()) return;
  const FrameAxis axis = abscissa_axis(rec.abscissa());
  PlotSpec curves = unfolding_curve_plot(title, t.name, t.rows, order.size(), axis);
  curves.warning = plot_warning(warning);
  optional_output(report, t.name + ".png",
                  [&] { write_plot((fs::path(dir) / (t.name + ".png")).string(), curves); });
  PlotSpec map = unfolding_map_plot(title, lines, order, axis);
  map.warning = curves.warning;
  if (map.segments.empty()) return;
  const std::string file = unfolding_map_file(t.name);
  optional_output(report, file, [&] { write_plot((fs::path(dir) / file).string(), map); });
}

}  // namespace

double deployed_at_of(const Model& m, const ProbeTable& t) {
  for (const ProbeDef& p : m.probes) {
    if (p.name == t.name && p.kind == ProbeKind::Drive && !p.drives.empty()) {
      return m.drives[p.drives[0]].deployed_at;
    }
  }
  return 0;
}

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

nlohmann::json probe_summary(const ProbeTable& t, double deployed_at) {
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
  } else if (t.kind == ProbeKind::Unfolding) {  // the lines' angles are in its CSV
    j["final"] = {{t.columns[0], last[0]}, {t.columns[1], last[1]}, {t.columns[2], last[2]}};
  } else {
    nlohmann::json f;
    for (std::size_t c = 0; c < t.columns.size(); ++c) f[t.columns[c]] = last[c];
    j["final"] = f;
  }
  if (t.kind == ProbeKind::Drive) add_drive_peaks(t, deployed_at, j);
  if (t.kind == ProbeKind::Chamber) add_chamber_peaks(t, j);
  return j;
}

RecorderOptions recorder_options(const Scene& scene) {
  RecorderOptions ro;
  ro.frames = scene.outputs.vtk || scene.outputs.html;
  ro.phases = scene.outputs.phases.enabled;
  for (int p : scene.outputs.phases.panels) ro.watched_panels.push_back(p - 1);
  return ro;
}

nlohmann::json run_summary(const Scene& scene, const RunRecorder& rec, const SolverStats& stats,
                           double wall_seconds, const RunReport& report,
                           const std::vector<RunStage>& stages) {
  nlohmann::json probes = nlohmann::json::object();
  for (std::size_t k = 0; k < rec.tables().size(); ++k) {
    const ProbeTable& t = rec.tables()[k];
    probes[t.name] = probe_summary(t, deployed_at_of(scene.model, t));
    if (t.kind != ProbeKind::Unfolding) continue;
    const auto& lines = rec.unfolding_lines_of(k);
    probes[t.name].update(
        unfolding_summary(t.name, lines.size(), unfolding_order(t.rows, lines), t.rows));
  }
  nlohmann::json overrides = nlohmann::json::array();
  for (const Override& o : scene.overrides) overrides.push_back(o.path + "=" + o.value);
  nlohmann::json j{
      {"scene", scene.file},
      {"overrides", overrides},
      {"title", run_title(scene)},
      {"status", stats.status},
      {"message", stats.message},
      {"wall_time_s", wall_seconds},
      {"threads", thread_count()},
      {"solver", solver_json(scene.solver)},
      {"stats", stats_json(stats)},
      {"model", model_counts(scene.model)},
      {"abscissa", rec.abscissa()},
      {"outputs", rec.outputs()},
      {"probes", probes},
      {"files", report.files},
      {"warnings", report.warnings},
  };
  const PhaseSettings& ph = scene.outputs.phases;
  if (ph.enabled) j["phases"] = phases_json(run_phases(scene, rec), ph);
  for (const RunStage& st : stages) {
    j["stages"].push_back({{"what", st.what},
                           {"segments", st.segments},
                           {"wall_time_s", st.wall_seconds},
                           {"stats", stats_json(st.stats)}});
  }
  j["provenance"] = provenance_json(scene);
  for (const std::string& w : recorded_warnings()) j["warnings"].push_back(w);
  return j;
}

RunReport write_run_outputs(const std::string& dir, const Scene& scene, const RunRecorder& rec,
                            const SolverStats& stats, double wall_seconds,
                            const std::function<void(double)>& on_progress,
                            const std::vector<RunStage>& stages) {
  fs::create_directories(dir);
  RunReport report;
  nlohmann::json probes = nlohmann::json::object();
  const ProbeTable* first_drive = nullptr;
  for (const ProbeTable& t : rec.tables()) {
    write_csv(dir, t.name + ".csv", probe_csv(t), report);
    if (t.pairs) write_csv(dir, pairs_file(t), pairs_csv(t, scene.model), report);
    probes[t.name] = probe_summary(t, deployed_at_of(scene.model, t));
    if (t.kind == ProbeKind::Drive && !first_drive) first_drive = &t;
  }
  const OutputSettings& o = scene.outputs;
  const DeploymentPhases phases = run_phases(scene, rec);
  if (o.phases.enabled && !rec.phase_samples().empty()) {
    std::string csv = "pull_displacement_m,active_contacts,watched_bend_deg\n";
    for (const PhaseSample& p : rec.phase_samples()) {
      csv += fmt::format("{:.12g},{},{:.12g}\n", p.displacement, p.active_contacts,
                         p.bend / kDegToRad);
    }
    write_csv(dir, "phases.csv", csv, report);
  }
  const std::string title = run_title(scene);
  const std::string warning = unfinished_warning(stats);
  // Charts beside the force chart on the HTML page: chambers' pressures, shapes' distances.
  std::vector<Curve> time_curves;
  for (const ProbeTable& t : rec.tables()) {
    if (has_time_curve(t)) time_curves.push_back(time_curve(t, rec.abscissa()));
  }
  for (std::size_t k = 0; k < rec.tables().size(); ++k) {
    if (rec.tables()[k].kind == ProbeKind::Unfolding) {
      write_unfolding_files(dir, title, warning, rec, k, o.plot, report);
    }
  }
  if (o.plot) {
    for (const ProbeTable& t : rec.tables()) {
      if (t.kind != ProbeKind::Drive && !has_time_curve(t)) continue;
      if (t.kind == ProbeKind::Unfolding) continue;  // write_unfolding_files
      const Curve c = t.kind == ProbeKind::Drive ? drive_curve(t) : time_curve(t, rec.abscissa());
      PlotSpec spec;
      spec.title = title + ": " + t.name;
      spec.x_label = c.x_label;
      spec.y_label = c.y_label;
      spec.series = {{t.name, c.x, c.y, "lines"}};
      if (&t == first_drive && o.phases.enabled) spec.markers = phase_markers(phases);
      for (const ChartMark& m : peak_marks(probes[t.name]))
        spec.points.push_back({m.x, m.y, m.label});
      spec.warning = plot_warning(warning);
      optional_output(report, t.name + ".png",
                      [&] { write_plot((fs::path(dir) / (t.name + ".png")).string(), spec); });
    }
  }
  if (o.vtk && !rec.frames().empty()) {
    optional_output(report, "vtk/frames.pvd", [&] {
      write_vtk_series((fs::path(dir) / "vtk").string(), "frames", scene.model, rec.frames(),
                       on_progress);
    });
  }
  if (o.html && !rec.frames().empty()) {
    const Curve curve = first_drive ? drive_curve(*first_drive) : Curve{};
    // The slider shows a pull in mm, as the chart beside it.
    const FrameAxis axis = abscissa_axis(rec.abscissa());
    optional_output(report, "animation.html", [&] {
      HtmlAnnotations notes{warning, {}, {}};
      for (const Curve& c : time_curves) {
        if (c.x.size() == rec.frames().size()) notes.curves.push_back(c);
      }
      if (first_drive && curve.x.size() == rec.frames().size()) {
        notes.marks = peak_marks(probes[first_drive->name]);
      }
      write_html_animation((fs::path(dir) / "animation.html").string(), title, scene.model,
                           rec.frames(), curve, axis, notes);
    });
  }
  report.summary = run_summary(scene, rec, stats, wall_seconds, report, stages);
  // Invalid UTF-8 is refused before the run (writers/output_folder.hpp); should any text
  // still carry some, the summary must not be lost for it.
  write_file_atomically(
      (fs::path(dir) / "summary.json").string(),
      report.summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  report.files.push_back("summary.json");
  return report;
}

}  // namespace finseg
