// Scene.run(): what `finseg run` does (same recorder, solver and output writers), with the
// probes returned as numpy arrays and summary.json as a dict (docs/python.md).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <filesystem>
#include <optional>

#include "core/error.hpp"
#include "core/threads.hpp"
#include "core/warnings.hpp"
#include "py_errors.hpp"
#include "py_scene.hpp"
#include "scene/folding_run.hpp"
#include "scene/state_start.hpp"
#include "solvers/stop_request.hpp"
#include "writers/checkpoint.hpp"
#include "writers/output_folder.hpp"
#include "writers/provenance.hpp"
#include "writers/run_outputs.hpp"

namespace finseg::py {

namespace pyb = pybind11;

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// What a run gives back.
struct PyResult {
  std::shared_ptr<const Scene> scene;
  std::vector<ProbeTable> tables;
  nlohmann::json summary;
  PyState state;
  std::string abscissa;
  std::optional<std::string> out;
};

pyb::array_t<double> column(const ProbeTable& t, std::size_t c) {
  pyb::array_t<double> a(static_cast<pyb::ssize_t>(t.rows.size()));
  auto m = a.mutable_unchecked<1>();
  for (std::size_t r = 0; r < t.rows.size(); ++r) m(r) = t.rows[r][c];
  return a;
}

// {column name: array} of one probe, in the CSV's column order.
pyb::dict probe_dict(const ProbeTable& t) {
  pyb::dict d;
  for (std::size_t c = 0; c < t.columns.size(); ++c) d[pyb::str(t.columns[c])] = column(t, c);
  return d;
}

// A contact probe's pairs as the columns of its _pairs.csv (body names as lists of str).
pyb::dict pairs_dict(const ProbeTable& t, const Model& model) {
  const std::size_t n = t.pair_rows.size();
  std::vector<double> x(n), points(n), fn(n), ff(n), pen(n), fx(n), fy(n), fz(n);
  std::vector<std::string> a(n), b(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ContactPairForce& p = t.pair_rows[i].force;
    x[i] = t.pair_rows[i].x;
    a[i] = model.bodies[p.a].name;
    b[i] = model.bodies[p.b].name;
    points[i] = p.points;
    fn[i] = p.normal_force;
    ff[i] = p.friction_force;
    pen[i] = p.max_penetration;
    fx[i] = p.f_b_W.x();
    fy[i] = p.f_b_W.y();
    fz[i] = p.f_b_W.z();
  }
  const auto arr = [](const std::vector<double>& v) {
    return pyb::array_t<double>(static_cast<pyb::ssize_t>(v.size()), v.data());
  };
  pyb::dict d;
  d[pyb::str(t.columns[0])] = arr(x);
  d["body_a"] = a;
  d["body_b"] = b;
  d["points"] = arr(points);
  d["normal_force_N"] = arr(fn);
  d["friction_force_N"] = arr(ff);
  d["max_penetration_m"] = arr(pen);
  d["fx_b_N"] = arr(fx);
  d["fy_b_N"] = arr(fy);
  d["fz_b_N"] = arr(fz);
  return d;
}

// `start` checked against the model as a state file would be and made a fresh run's start
// as --state does (time and drives from 0, the model starting there).
State start_from(Scene& scene, const PyState& start) {
  const nlohmann::json j = state_json(start.scene->model, {start.state, start.scene_hash});
  return start_fresh_from(scene, parse_state_json(j, scene.model, "<python state>").state);
}

PyResult run(const PyScene& base, const std::optional<std::string>& solver,
             const std::optional<std::string>& out, const PyState* start, int threads, bool fold) {
  const auto t0 = Clock::now();
  clear_recorded_warnings();  // summary.json lists this run's warnings only
  std::vector<Override> overrides = base.overrides;
  if (solver && fold) {
    throw InputError("<python>", "solver",
                     "not with fold: the fold runs folding.solver (with_set it to change it)");
  }
  if (solver) overrides.push_back({"solver.type", *solver});
  const PyScene ps(base.text, base.file, overrides);
  Scene scene = *ps.scene;  // a start state moves its initial configuration
  if (threads < 0 || threads > 1024)
    throw InputError("<python>", "threads", "must be 0 (one per core) .. 1024");
  // The thread count is process-wide: each run sets its own and puts the previous back.
  struct ThreadsGuard {
    int previous = thread_count();
    ~ThreadsGuard() { set_thread_count(previous); }
  } threads_guard;
  set_thread_count(threads > 0 ? threads : thread_count());
  // A folding run's checkpoint is not its scene's run's (as finseg run --fold hashes it).
  const std::string hash = scene_inputs_hash(ps.text + (fold ? kFoldingRunMark : ""), scene);
  // As finseg run: from `start`, then folded on from there (or from the coarse cut's fold),
  // else from the (folding) model's initial state.
  std::optional<State> from;
  if (start) from = start_from(scene, *start);
  std::vector<RunStage> stages;
  if (fold) {
    // Ctrl-C during a fold on the coarse cut (which writes nothing) ends it at once.
    FoldingStart folding =
        make_folding_run(scene, ps.text, false, from.has_value(), [](std::size_t, int, double) {
          if (PyErr_CheckSignals() != 0) throw pyb::error_already_set();
        });
    if (folding.state) from = std::move(folding.state);
    stages = std::move(folding.stages);
  }
  State state = from ? std::move(*from) : initial_state(scene.model);
  if (out) {
    check_output_folder(*out, scene);
    remove_previous_run(*out);
    fs::remove(fs::path(*out) / "summary.json");
  }
  // Frames only feed the VTK and HTML files: without a folder they are not kept.
  RecorderOptions ro = recorder_options(scene);
  ro.frames = ro.frames && out.has_value();
  RunRecorder rec(scene.model, scene.solver, ro);
  // Ctrl-C: Python's handler only sets a flag; it is looked at here, between steps, and
  // stops the run at its next step as SIGINT stops `finseg run`.
  bool interrupted = false;
  clear_stop_request();
  SolverStats stats = run_solver(
      scene.model, state, scene.solver,
      [&](const State& s, const BodyForces& f) { rec.record(s, f); },
      [&](const SolverProgress&) {
        if (!interrupted && PyErr_CheckSignals() != 0) {
          PyErr_Clear();
          interrupted = true;
          request_stop();
        }
      });
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  PyResult r{ps.scene, rec.tables(), {}, state_of(ps, state), rec.abscissa(), out};
  if (out) {
    if (stats.status == "ok") write_checkpoint(*out, scene.model, {state, hash}, rec);
    RunReport report = write_run_outputs(*out, scene, rec, stats, wall, {}, stages);
    if (stats.status == "ok") report.files.push_back(kCheckpointFile);
    write_manifest(*out, report.files);
    r.summary = report.summary;
  } else {
    r.summary = run_summary(scene, rec, stats, wall, {}, stages);
  }
  if (interrupted) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw pyb::error_already_set();
  }
  return r;
}

}  // namespace

void bind_run(pyb::module_& m, pyb::class_<PyScene>& scene) {
  pyb::class_<PyResult>(m, "Result",
                        "What a run recorded: probes as numpy arrays, summary.json as a dict, "
                        "the final state.")
      .def_property_readonly(
          "probes",
          [](const PyResult& r) {
            pyb::dict d;
            for (const ProbeTable& t : r.tables) d[pyb::str(t.name)] = probe_dict(t);
            return d;
          },
          "{probe: {column: array}}; column names carry their units as in the CSV files")
      .def_property_readonly(
          "pairs",
          [](const PyResult& r) {
            pyb::dict d;
            for (const ProbeTable& t : r.tables)
              if (t.pairs) d[pyb::str(t.name)] = pairs_dict(t, r.scene->model);
            return d;
          },
          "{contact probe with pairs: {column: array or list}} as <probe>_pairs.csv")
      .def_property_readonly(
          "summary", [](const PyResult& r) { return json_to_python(r.summary); },
          "summary.json as a dict (docs/scene.md)")
      .def_property_readonly(
          "status", [](const PyResult& r) { return r.summary.value("status", std::string()); },
          "ok, diverged or interrupted")
      .def_property_readonly(
          "abscissa", [](const PyResult& r) { return r.abscissa; },
          "the first column of every probe: t_s, pull_displacement_m or load_scale")
      .def_property_readonly(
          "state", [](const PyResult& r) { return r.state; }, "the state at the end of the run")
      .def_property_readonly(
          "out", [](const PyResult& r) { return r.out; }, "the output folder, or None");

  scene.def(
      "run",
      [](const PyScene& s, const std::optional<std::string>& solver,
         const std::optional<std::string>& out, const PyState* state, int threads, bool fold) {
        PyResult r = run(s, solver, out, state, threads, fold);
        if (r.summary.value("status", std::string()) == "ok") return r;
        const std::string message =
            s.file + ": the simulation diverged: " + r.summary.value("message", std::string());
        raise_python("DivergenceError", pyb::make_tuple(message, pyb::cast(std::move(r))));
      },
      pyb::arg("solver") = pyb::none(), pyb::arg("out") = pyb::none(),
      pyb::arg("state") = pyb::none(), pyb::arg("threads") = 0, pyb::arg("fold") = false,
      "run the scene (solver: 'static', 'implicit' or 'explicit' overrides the scene's, as "
      "--set solver.type=...); out: also write finseg run's output folder; state: start "
      "from this State (as --state); threads: force-element threads (0: one per core); "
      "fold: run the scene's folding run instead (as --fold; not with solver). "
      "Raises InputError, DivergenceError (its .result holds what was recorded), "
      "KeyboardInterrupt on Ctrl-C (outputs written first).");
}

}  // namespace finseg::py
