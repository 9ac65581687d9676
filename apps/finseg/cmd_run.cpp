// finseg run SCENE --out DIR [--quiet] [--resume | --state FILE]: runs a scene and writes
// its probes' CSV files, optional VTK / HTML / plots, DIR/summary.json, DIR/checkpoint.json
// and DIR/manifest.json (docs/scene.md, "Run outputs"; docs/state-file.md).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/finseg/commands.hpp"
#include "apps/finseg/progress.hpp"
#include "core/error.hpp"
#include "core/threads.hpp"
#include "probes/recorder.hpp"
#include "scene/folding_run.hpp"
#include "scene/scene_reader.hpp"
#include "scene/state_file.hpp"
#include "scene/state_start.hpp"
#include "solvers/stop_request.hpp"
#include "writers/atomic_write.hpp"
#include "writers/checkpoint.hpp"
#include "writers/frame_file.hpp"
#include "writers/output_folder.hpp"
#include "writers/provenance.hpp"
#include "writers/run_outputs.hpp"
#include "writers/unfolding_outputs.hpp"

namespace finseg::cli {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct RunOptions {
  std::string scene, out, state_file;
  bool quiet = false, resume = false, fold = false;
  double checkpoint_every = 30;  // wall seconds between checkpoints (0: every output)
  double progress_every = 5;     // wall seconds between progress lines off a terminal
  std::vector<std::string> set;  // --set KEY.PATH=VALUE
  int threads = 0;               // 0: one per core (OpenMP's default, OMP_NUM_THREADS)
};

volatile std::sig_atomic_t g_signal = 0;

// Only sets flags (async-signal-safe); the run stops at its next output. SA_RESETHAND: a
// second Ctrl-C ends the program at once.
extern "C" void on_stop_signal(int sig) {
  g_signal = sig;
  request_stop();
}

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

// `x` on the run's abscissa as text ("t = 0.42 s", "pull 12 mm", "load 0.5").
std::string where(const RunRecorder& rec, double x) {
  if (rec.abscissa() == "t_s") return fmt::format("t = {:.4g} s", x);
  if (rec.abscissa() == "pull_displacement_m") return fmt::format("pull {:.4g} mm", 1e3 * x);
  return fmt::format("load {:.3g}", x);
}

// Where the last output is.
std::string where(const RunRecorder& rec) {
  return where(rec, rec.last_abscissa());
}

// Where the run is at `now` (a dynamic run may stop between outputs).
std::string where(const RunRecorder& rec, const State& now) {
  return where(rec, rec.abscissa() == "t_s" ? now.t : rec.last_abscissa());
}

// The progress line: where the run is and, for the dynamic solvers and static load stepping,
// its counts (a large model may take minutes from one output to the next; a folding run by
// the static solver has outputs only at its start and end).
std::string progress_text(const RunRecorder& rec, const SolverProgress& p) {
  if (p.stats != nullptr && rec.abscissa() == "load_scale") {
    std::string s =
        fmt::format("{}, {} Newton iterations", where(rec, p.t), p.stats->newton_iterations);
    if (p.stats->rejected_steps > 0) {
      s += fmt::format(" ({} load increments cut)", p.stats->rejected_steps);
    }
    return s + fmt::format(", {} outputs", rec.outputs());
  }
  if (p.stats == nullptr || rec.abscissa() != "t_s") {
    return fmt::format("{}, {} outputs", where(rec), rec.outputs());
  }
  std::string s =
      fmt::format("{}, step {:.2g} s, {} steps", where(rec, p.t), p.step, p.stats->steps);
  if (p.stats->rejected_steps > 0) s += fmt::format(" ({} rejected)", p.stats->rejected_steps);
  if (p.stats->newton_iterations > 0) {
    s += fmt::format(", {} Newton iterations", p.stats->newton_iterations);
  }
  return s + fmt::format(", {} outputs", rec.outputs());
}

// How many folded lines came half open, and the first few.
void print_unfolding(const ProbeTable& t, const std::vector<LineOpening>& order,
                     const std::string& abscissa) {
  std::string first;
  int opened = 0;
  for (const LineOpening& o : order) {
    if (!std::isfinite(o.half_open_at)) continue;
    if (++opened <= 5)
      first += fmt::format("{} {} at {:.4g}", first.empty() ? ":" : ",", o.name, o.half_open_at);
  }
  fmt::print("  {}: {} of {} folded lines came half open{}{} ({}; {})\n", t.name, opened,
             order.size(), first, opened > 5 ? ", ..." : "", abscissa,
             unfolding_order_file(t.name));
}

void print_results(const RunRecorder& rec, const RunOptions& o, const SolverStats& stats,
                   double wall, const Model& model) {
  fmt::print("finseg run {}: {} outputs, {} steps, wall {:.3g} s -> {}\n", o.scene, rec.outputs(),
             stats.steps, wall, o.out);
  for (std::size_t k = 0; k < rec.tables().size(); ++k) {
    const ProbeTable& t = rec.tables()[k];
    if (t.rows.empty()) continue;
    const auto& r = t.rows.back();
    if (t.kind == ProbeKind::Unfolding) {
      print_unfolding(t, unfolding_order(t.rows, rec.unfolding_lines_of(k)), rec.abscissa());
    } else if (t.kind == ProbeKind::Point) {
      fmt::print("  {}: final [{:.6g}, {:.6g}, {:.6g}] m\n", t.name, r[1], r[2], r[3]);
    } else if (t.kind == ProbeKind::Drive) {
      const nlohmann::json s = probe_summary(t, deployed_at_of(model, t));
      fmt::print("  {}: {}; largest force {:.6g} N at pull {:.6g} mm\n", t.name,
                 s["deployment_peak_force_N"].is_null()
                     ? std::string("no deployment peak")
                     : fmt::format("deployment peak {:.6g} N at pull {:.6g} mm",
                                   s["deployment_peak_force_N"].get<double>(),
                                   1e3 * s["deployment_peak_displacement_m"].get<double>()),
                 s["peak_force_N"].get<double>(), 1e3 * s["peak_displacement_m"].get<double>());
    }
  }
}

// A run started from a state file has that state's configuration as its model's initial one
// (drives' start points, crease openings: start_fresh_from), so the run resumed from its
// checkpoint must start from the same file; the scene hash then tells whether it changed.
void check_same_start(const std::string& path, const StateSnapshot& snap,
                      const std::string& state_file) {
  if (!snap.start_state.empty() && state_file.empty()) {
    throw InputError(path, "start_state",
                     fmt::format("the run started from the state file {}: continue it with "
                                 "--resume --state {}",
                                 snap.start_state, snap.start_state));
  }
  if (snap.start_state.empty() && !state_file.empty()) {
    throw InputError(path, "start_state",
                     "the run started from the scene's initial state: resume it without --state");
  }
}

// The state the run starts from: the scene's initial state, DIR's checkpoint (--resume,
// which also restores what was recorded) or any state file (--state).
State starting_state(const RunOptions& o, const Scene& scene, const std::string& hash,
                     RunRecorder& rec) {
  if (o.resume) {
    if (scene.solver.kind == SolverKind::Static && !has_drive_path(scene.model)) {
      throw InputError("<cli>", "--resume",
                       "a static run without a drive path has no output between its start and "
                       "its end to continue from: run it again (or use --state "
                       "DIR/checkpoint.json to start from its poses and history)");
    }
    const std::string path = (fs::path(o.out) / kCheckpointFile).string();
    if (!fs::exists(path)) throw InputError(path, "--resume", "no checkpoint to resume from");
    StateSnapshot snap = read_checkpoint(path, scene.model, rec);
    check_same_start(path, snap, o.state_file);
    if (snap.scene_hash != hash) {
      throw InputError(path, "scene_hash",
                       "the checkpoint was made from another scene (or the scene file or its "
                       "crease data changed since, or the --state file it started from): run "
                       "without --resume");
    }
    return snap.state;
  }
  return initial_state(scene.model);
}

// What the start state file adds to the scene's hash: its bytes ("" without one).
std::string start_state_mark(const std::string& state_file) {
  if (state_file.empty()) return "";
  return std::string("\n# finseg run --state\n") + read_whole_file(state_file);
}

// A run from a state file is a fresh run whose initial configuration is that state's
// (docs/state-file.md): its poses, crease history and contact anchors, drives starting from
// where their points are.
State start_scene_from_state_file(const RunOptions& o, Scene& scene) {
  scene.start_state = o.state_file;
  return start_fresh_from(scene, read_state_file(o.state_file, scene.model).state);
}

// Periodic checkpoints from the output callback; a checkpoint that cannot be written is a
// warning (the run goes on and still writes its results).
class Checkpointer {
 public:
  Checkpointer(const RunOptions& o, const Scene& scene, std::string hash)
      : o_(o), scene_(scene), hash_(std::move(hash)), last_(Clock::now()) {}

  void at_output(const State& s, const RunRecorder& rec) {
    const bool due = o_.checkpoint_every <= 0 ||
                     Clock::now() - last_ >= std::chrono::duration<double>(o_.checkpoint_every);
    if (due || stop_requested()) write(s, rec);
  }
  void write(const State& s, const RunRecorder& rec) {
    try {
      write_checkpoint(o_.out, scene_.model, {s, hash_, o_.state_file}, rec);
      write_manifest(o_.out, {kCheckpointFile});
    } catch (const std::exception& e) {
      if (!warned_) fmt::print(stderr, "finseg: warning: checkpoint not written: {}\n", e.what());
      warned_ = true;
    }
    last_ = Clock::now();
  }

 private:
  const RunOptions& o_;
  const Scene& scene_;
  std::string hash_;
  Clock::time_point last_;
  bool warned_ = false;
};

// The command that continues an interrupted run: its scene, folder, --fold, --set changes and
// start state, which its checkpoint's hash covers, and --resume.
std::string continue_command(const RunOptions& o) {
  std::string c = fmt::format("finseg run {} --out {}", o.scene, o.out);
  if (o.fold) c += " --fold";
  for (const std::string& s : o.set) c += " --set " + s;
  if (!o.state_file.empty()) c += " --state " + o.state_file;
  return c + " --resume";
}

[[noreturn]] void stop_interrupted(const RunOptions& o, const RunRecorder& rec, const State& now) {
  const int sig = g_signal;
  fmt::print(stderr,
             "finseg: interrupted by {} at {}: kept the {} outputs recorded ({} to {}) and the "
             "state there in {}\n",
             sig == SIGTERM ? "SIGTERM" : "SIGINT", where(rec, now), rec.outputs(), where(rec),
             o.out, kCheckpointFile);
  fmt::print(stderr, "finseg: continue with: {}\n", continue_command(o));
  throw ExitStatus{sig == SIGTERM ? 143 : 130};
}

// The folding run (scene/folding_run.hpp) with a progress line for a fold on a coarse cut
// and, unless quiet, a line of its counts.
FoldingStart fold_with_progress(Scene& scene, const std::string& yaml, const RunOptions& o,
                                bool from_state) {
  std::size_t segments = 0;
  int subdivisions = 0;
  ProgressLine progress(
      progress_mode(o.quiet),
      [&] {
        return fmt::format("folding on the coarse cut ({} segments, pattern.subdivisions {})",
                           segments, subdivisions);
      },
      5.0);
  FoldingStart folding = make_folding_run(scene, yaml, o.resume, from_state,
                                          [&](std::size_t n, int cut, double fraction) {
                                            segments = n;
                                            subdivisions = cut;
                                            progress.update(fraction);
                                          });
  progress.finish();
  if (o.quiet) return folding;
  for (const RunStage& st : folding.stages) {
    fmt::print(stderr,
               "finseg: folded on the coarse cut: {} segments, {} Newton iterations, wall {:.3g} "
               "s; carried onto {} segments\n",
               st.segments, st.stats.newton_iterations, st.wall_seconds, scene.model.bodies.size());
  }
  return folding;
}

void run_scene(const RunOptions& o) {
  const auto start = Clock::now();
  set_thread_count(o.threads > 0 ? o.threads : thread_count());
  std::vector<Override> overrides;
  for (const std::string& s : o.set) overrides.push_back(parse_override(s));
  Scene scene = read_scene(o.scene, overrides);
  // The checkpoint's hash covers the crease data and the --set changes too: a resume after a
  // table or an override changed is refused; a folding run's checkpoint is not its scene's.
  const std::string yaml = read_whole_file(o.scene);
  // ... and the start state's: the model starts from it.
  const std::string hash = scene_inputs_hash(
      yaml + (o.fold ? kFoldingRunMark : "") + start_state_mark(o.state_file), scene);
  // From a state file first, so that a folding run folds on from there; a resumed run's model
  // starts from it as the interrupted run's did.
  std::optional<State> from_file;
  std::vector<RunStage> stages;  // solves made before this run (a coarse fold)
  if (!o.state_file.empty()) from_file = start_scene_from_state_file(o, scene);
  if (o.fold) {
    FoldingStart folding = fold_with_progress(scene, yaml, o, from_file.has_value());
    if (folding.state) from_file = std::move(folding.state);
    stages = std::move(folding.stages);
  }
  check_output_folder(o.out, scene);
  RunRecorder rec(scene.model, scene.solver, recorder_options(scene));
  State state = from_file && !o.resume ? *from_file : starting_state(o, scene, hash, rec);
  // Resumed: the same step sizes as the interrupted run (explicit: its fixed step; implicit:
  // the step it would have tried next). summary.json keeps the scene's settings.
  SolverSettings settings = scene.solver;
  if (o.resume && state.solver.t == state.t && state.solver.dt > 0) settings.dt = state.solver.dt;
  // Only this run's files in DIR from now on; a summary.json of a run from before manifests
  // must not make this one look complete either.
  remove_previous_run(o.out, o.resume
                                 ? std::vector<std::string>{kCheckpointFile, kCheckpointFramesFile}
                                 : std::vector<std::string>{});
  fs::remove(fs::path(o.out) / "summary.json");
  clear_stop_request();
  install_stop_handlers();
  SolverProgress now;
  ProgressLine progress(
      progress_mode(o.quiet), [&] { return progress_text(rec, now); }, o.progress_every);
  Checkpointer checkpoints(o, scene, hash);
  bool skip = o.resume;  // a resumed run's first output is the checkpoint's last one
  SolverStats stats = run_solver(
      scene.model, state, settings,
      [&](const State& s, const BodyForces& f) {
        if (!std::exchange(skip, false)) rec.record(s, f);
        checkpoints.at_output(s, rec);
      },
      [&](const SolverProgress& p) {
        now = p;
        progress.update(p.fraction);
      });
  now.stats = nullptr;  // the counts lived in run_solver
  progress.finish();
  signal(SIGINT, SIG_DFL);
  signal(SIGTERM, SIG_DFL);
  const bool interrupted = stats.status == kInterruptedStatus;
  // The final state, or where the run stopped (maybe between outputs; docs/state-file.md).
  if (stats.status == "ok" || interrupted) checkpoints.write(state, rec);
  if (interrupted) {
    stats.message = fmt::format("interrupted by {} at {}; continue with: {}",
                                g_signal == SIGTERM ? "SIGTERM" : "SIGINT", where(rec, state),
                                continue_command(o));
  }
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  const std::size_t frames = rec.frames().size();
  ProgressLine writing(
      progress_mode(o.quiet || !scene.outputs.vtk),
      [&] { return fmt::format("writing {} VTK frames to {}", frames, o.out); }, o.progress_every);
  RunReport report = write_run_outputs(
      o.out, scene, rec, stats, wall, [&](double fraction) { writing.update(fraction); }, stages);
  writing.finish();
  if (fs::exists(fs::path(o.out) / kCheckpointFile)) report.files.push_back(kCheckpointFile);
  write_manifest(o.out, report.files);
  for (const std::string& w : report.warnings) fmt::print(stderr, "finseg: warning: {}\n", w);
  if (interrupted) stop_interrupted(o, rec, state);
  if (stats.status != "ok") {
    fmt::print(stderr, "finseg: error: {}: the simulation diverged: {}\n", o.scene, stats.message);
    fmt::print(stderr, "finseg: kept the {} outputs recorded before ({} to {})\n", rec.outputs(),
               where(rec), o.out);
    throw ExitStatus{3};
  }
  if (!o.quiet) print_results(rec, o, stats, wall, scene.model);
}

}  // namespace

void register_run(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* run = app.add_subcommand("run", "run a scene file; write probe CSVs and summary.json");
  run->add_option("SCENE", o->scene, "scene file (YAML, docs/scene.md)")->required();
  run->add_option("--out", o->out, "output folder (created if needed)")->required();
  run->add_flag("--quiet", o->quiet, "no progress display and no result lines");
  run->add_flag("--resume", o->resume,
                "continue the run whose checkpoint is in --out (same scene, and the same --state "
                "file if it started from one; dynamic solvers and static drive paths)");
  run->add_option("--state", o->state_file,
                  "start from this state file instead of the scene's initial state "
                  "(docs/state-file.md)");
  run->add_flag("--fold", o->fold,
                "run the scene's folding: section instead (creases carried from flat to their "
                "target angles; DIR/checkpoint.json is then the stowed state for --state; "
                "docs/folding.md)");
  run->add_option("--checkpoint-every", o->checkpoint_every,
                  "wall seconds between checkpoints in DIR/checkpoint.json (0: every output)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  run->add_option("--set", o->set,
                  "change the scene: KEY.PATH=VALUE (repeatable; lists by index from 0, e.g. "
                  "drives.0.speed=0.02; docs/scene.md)");
  run->add_option("--progress-every", o->progress_every,
                  "wall seconds between progress lines when stderr is not a terminal")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  run->add_option("--threads", o->threads,
                  "threads for the force elements (0: one per core or OMP_NUM_THREADS; results "
                  "are the same for any number)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  run->callback([o] { run_scene(*o); });
}

}  // namespace finseg::cli
