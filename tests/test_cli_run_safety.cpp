// finseg run loses nothing (issue 14 item 2): SIGINT/SIGTERM sent to a real child process,
// write-time failures found before the run, --resume and --state, the manifest, progress
// lines off a terminal.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli_test_util.hpp"
#include "test_paths.hpp"
#include "writers/provenance.hpp"

namespace finseg {
namespace cli_run_safety_test {

namespace fs = std::filesystem;
using test::run_finseg;
using test::slurp;
using test::spit;
using test::TempDir;

nlohmann::json summary(const TempDir& dir, const std::string& out) {
  return nlohmann::json::parse(slurp(dir / (out + "/summary.json")));
}

std::vector<std::vector<double>> csv_numbers(const std::string& text) {
  std::string header;
  return test::csv_rows(text, &header);
}

// A cantilever under a tip load; `t_end` sets how long the dynamic run takes.
// Outputs every t_end / 20 s, at most every ms.
void write_cantilever(const TempDir& dir, const std::string& solver, double t_end,
                      const std::string& file = "c.yaml") {
  const auto r =
      run_finseg(dir, "gen cantilever --segments 8 --tip-force 0,0,-1e-3 --solver " + solver +
                          " --t-end " + std::to_string(t_end) + " --output-interval " +
                          std::to_string(std::min(1e-3, t_end / 20)) + " --out " + file);
  ASSERT_EQ(r.code, 0) << r.err;
}

// Starts `finseg run ARGS` as a child process; stdout and stderr go to files in `dir`.
pid_t spawn_run(const TempDir& dir, const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.path().c_str()) != 0) _exit(120);
    if (!freopen("child_stdout.txt", "w", stdout) || !freopen("child_stderr.txt", "w", stderr))
      _exit(121);
    std::vector<char*> argv{const_cast<char*>(FINSEG_BINARY), const_cast<char*>("run")};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(FINSEG_BINARY, argv.data());
    _exit(122);
  }
  return pid;
}

// Waits until `path` exists (the run has started recording), at most 60 s.
bool wait_for(const std::string& path) {
  for (int i = 0; i < 60000; ++i) {
    if (fs::exists(path)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

int wait_exit_code(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Interrupts a long run (minutes uninterrupted) as soon as it has recorded its first output.
int interrupt_run(const TempDir& dir, int sig, const std::string& out,
                  const std::vector<std::string>& more = {}) {
  std::vector<std::string> args{"c.yaml", "--out", out, "--checkpoint-every", "0"};
  args.insert(args.end(), more.begin(), more.end());
  const pid_t pid = spawn_run(dir, args);
  EXPECT_TRUE(wait_for(dir / (out + "/checkpoint.json")));
  kill(pid, sig);
  return wait_exit_code(pid);
}

void expect_interrupted_outputs(const TempDir& dir, const std::string& out) {
  const auto j = summary(dir, out);
  EXPECT_EQ(j["status"], "interrupted");
  EXPECT_NE(j["message"].get<std::string>().find("interrupted by"), std::string::npos);
  const auto rows = csv_numbers(slurp(dir / (out + "/tip.csv")));
  ASSERT_GE(rows.size(), 1u);
  EXPECT_EQ(rows.size(), j["outputs"].get<std::size_t>());
  EXPECT_LT(rows.back()[0], 1.0);  // stopped long before t_end = 100 s
  // The run stops at the step after the signal, or at an output if the signal lands while
  // one is written (the first output is enough).
  const std::string message = j["message"].get<std::string>();
  const auto at = message.find("t = ");
  ASSERT_NE(at, std::string::npos) << message;
  // Where it stopped: at or after the last output, before the next one (every ms), as in
  // the checkpoint (printed to 4 digits).
  const double t_stop = std::stod(message.substr(at + 4));
  EXPECT_GE(t_stop, rows.back()[0] * (1 - 1e-3) - 1e-12);
  EXPECT_LT(t_stop, rows.back()[0] + 1e-3);
  const auto c = nlohmann::json::parse(slurp(dir / (out + "/checkpoint.json")));
  EXPECT_NEAR(c["t"].get<double>(), t_stop, 1e-3 * t_stop + 1e-12);
  EXPECT_TRUE(fs::exists(dir / (out + "/manifest.json")));
}

TEST(CliRunSafety, SigintStopsAtTheNextStepAndKeepsEverything) {
  TempDir dir;
  write_cantilever(dir, "explicit", 100);
  EXPECT_EQ(interrupt_run(dir, SIGINT, "out"), 130) << slurp(dir / "child_stderr.txt");
  expect_interrupted_outputs(dir, "out");
  EXPECT_NE(slurp(dir / "child_stderr.txt").find("--resume"), std::string::npos);
}

TEST(CliRunSafety, SigtermStopsAtTheNextStepAndKeepsEverything) {
  TempDir dir;
  write_cantilever(dir, "implicit", 100);
  EXPECT_EQ(interrupt_run(dir, SIGTERM, "out"), 143) << slurp(dir / "child_stderr.txt");
  expect_interrupted_outputs(dir, "out");
}

void replace_line(const std::string& path, const std::string& from, const std::string& to) {
  std::string text = slurp(path);
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, from.size(), to);
  spit(path, text);
}

// Final state of a run from its checkpoint.json (17 significant digits: exact doubles): t and
// the poses, and with `velocities` the bodies' velocities too.
std::vector<double> final_state(const TempDir& dir, const std::string& out,
                                bool velocities = true) {
  const auto j = nlohmann::json::parse(slurp(dir / (out + "/checkpoint.json")));
  const std::vector<const char*> keys =
      velocities ? std::vector<const char*>{"p_W_m", "R_WB", "v_W_m_s", "w_W_rad_s"}
                 : std::vector<const char*>{"p_W_m", "R_WB"};
  std::vector<double> x{j["t"].get<double>()};
  for (const auto& b : j["bodies"]) {
    for (const char* k : keys) {
      for (const auto& v : b[k]) x.push_back(v.get<double>());
    }
  }
  return x;
}

// An interrupted and resumed run ends where an uninterrupted one does, with the same rows.
// The signal lands between outputs, where the explicit solver resumes to the bit; the implicit
// one resumes with a new Newton matrix where the uninterrupted run kept one, so the Newton
// iterates part (by up to their tolerance, 1e-3 of the local error tolerance, each step) and
// the poses agree within the local error tolerance the steps are controlled to (1e-7 m + 1e-4
// of the 0.1 m strip); the frames up to the stop agree to the bit.
void expect_resume_matches(const std::string& solver, const std::string& scheme = "") {
  const bool bitwise = solver == "explicit";
  const double tol = bitwise ? 1e-12 : 1e-7 + 1e-4 * 0.1;
  TempDir dir;
  write_cantilever(dir, solver, 0.02);
  if (!scheme.empty())
    replace_line(dir / "c.yaml", "type: implicit", "type: implicit\n  scheme: " + scheme);
  replace_line(dir / "c.yaml", "vtk: false", "vtk: true");  // frames are restored too
  auto r = run_finseg(dir, "run c.yaml --out whole --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(interrupt_run(dir, SIGINT, "parts"), 130) << slurp(dir / "child_stderr.txt");
  const std::size_t before = summary(dir, "parts")["outputs"];
  ASSERT_LT(before, 21u) << "the signal came after the run's end: nothing to resume";
  r = run_finseg(dir, "run c.yaml --out parts --resume --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(summary(dir, "parts")["status"], "ok");
  const auto a = final_state(dir, "whole", bitwise), b = final_state(dir, "parts", bitwise);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], tol) << i;
  const auto ra = csv_numbers(slurp(dir / "whole/tip.csv"));
  const auto rb = csv_numbers(slurp(dir / "parts/tip.csv"));
  ASSERT_EQ(ra.size(), rb.size());
  for (std::size_t i = 0; i < ra.size(); ++i) {
    for (std::size_t c = 0; c < ra[i].size(); ++c) EXPECT_NEAR(ra[i][c], rb[i][c], tol);
  }
  EXPECT_EQ(slurp(dir / "whole/vtk/frames.pvd"), slurp(dir / "parts/vtk/frames.pvd"));
  for (std::size_t f = 0; f < 21; ++f) {
    const std::string name = fmt::format("/vtk/frames_{:05d}.vtu", f);
    if (bitwise || f < before) {
      EXPECT_EQ(slurp(dir / ("whole" + name)), slurp(dir / ("parts" + name))) << name;
    }
  }
}

TEST(CliRunSafety, ResumedExplicitRunEqualsUninterruptedRun) {
  expect_resume_matches("explicit");
}

TEST(CliRunSafety, ResumedImplicitRunEqualsUninterruptedRun) {
  expect_resume_matches("implicit");
}

// Generalized-alpha's accelerations are part of the checkpoint (they were not: the resumed
// run restarted them from the forces and drifted off by about 1e-7 of the tip's travel).
TEST(CliRunSafety, ResumedGeneralizedAlphaRunEqualsUninterruptedRun) {
  expect_resume_matches("implicit", "generalized_alpha");
}

// The resumed static pull in "parts" ended as "whole": same status, end state and rows.
void expect_same_pull(const TempDir& dir) {
  EXPECT_EQ(summary(dir, "parts")["status"], "ok");
  const auto a = final_state(dir, "whole"), b = final_state(dir, "parts");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << i;
  EXPECT_EQ(slurp(dir / "whole/gauge.csv"), slurp(dir / "parts/gauge.csv"));
}

// A quasi-static pull (static solver, drive path with contact) continues where it stopped:
// same equilibria, same rows, same end state.
TEST(CliRunSafety, ResumedStaticPullEqualsUninterruptedPull) {
  TempDir dir;
  auto r = run_finseg(dir, "gen zigzag --segments-per-panel 4 --out c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "run c.yaml --out whole --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(interrupt_run(dir, SIGINT, "parts"), 130) << slurp(dir / "child_stderr.txt");
  const std::size_t before = summary(dir, "parts")["outputs"];
  ASSERT_LT(before, summary(dir, "whole")["outputs"].get<std::size_t>())
      << "the signal came after the run's end: nothing to resume";
  r = run_finseg(dir, "run c.yaml --out parts --resume --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  expect_same_pull(dir);
}

// A run from a state file starts its model there (drives from where their points are); its
// checkpoint says so, and the run resumes from the same file to the same equilibria. Resumed
// without it (the scene's drive start, the pull's first 30 mm undone) it was wrong, and is now
// refused; so is a checkpoint of a run from the scene's start resumed with a state file.
TEST(CliRunSafety, RunFromAStateFileResumesFromTheSameFile) {
  TempDir dir;
  auto r = run_finseg(dir, "gen zigzag --segments-per-panel 4 --out c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "run c.yaml --out a --quiet --set zigzag.pull_travel=0.03");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "run c.yaml --out whole --quiet --state a/checkpoint.json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto from = summary(dir, "whole")["provenance"]["start_state"];
  EXPECT_EQ(from["file"], "a/checkpoint.json");
  EXPECT_EQ(from["sha256"], sha256_file(dir / "a/checkpoint.json"));
  // (--set with the scene's own value: the same run, but its hash asks for it again)
  const std::string same = "solver.tolerance=1e-9";
  ASSERT_EQ(interrupt_run(dir, SIGINT, "parts", {"--set", same, "--state", "a/checkpoint.json"}),
            130)
      << slurp(dir / "child_stderr.txt");
  EXPECT_NE(slurp(dir / "child_stderr.txt")
                .find("continue with: finseg run c.yaml --out parts --set " + same +
                      " --state a/checkpoint.json --resume"),
            std::string::npos);
  ASSERT_LT(summary(dir, "parts")["outputs"].get<std::size_t>(),
            summary(dir, "whole")["outputs"].get<std::size_t>())
      << "the signal came after the run's end: nothing to resume";
  r = run_finseg(dir, "run c.yaml --out parts --resume --quiet --set " + same);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("parts/checkpoint.json: start_state: the run started from the state file "
                       "a/checkpoint.json"),
            std::string::npos)
      << r.err;
  r = run_finseg(dir,
                 "run c.yaml --out parts --resume --quiet --state a/checkpoint.json --set " + same);
  ASSERT_EQ(r.code, 0) << r.err;
  expect_same_pull(dir);
  r = run_finseg(dir, "run c.yaml --out a --resume --quiet --state whole/checkpoint.json");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("start_state: the run started from the scene's initial state"),
            std::string::npos)
      << r.err;
}

// The frames of a run with VTK on are kept in a file beside the checkpoint, which grows by the
// frames since the last checkpoint, not in checkpoint.json; a checkpoint written before (frames
// in run.frames) still resumes.
TEST(CliRunSafety, CheckpointKeepsItsFramesInAFileBeside) {
  TempDir dir;
  write_cantilever(dir, "implicit", 0.02);
  replace_line(dir / "c.yaml", "vtk: false", "vtk: true");
  ASSERT_EQ(interrupt_run(dir, SIGINT, "parts"), 130) << slurp(dir / "child_stderr.txt");
  auto j = nlohmann::json::parse(slurp(dir / "parts/checkpoint.json"));
  const std::size_t count = j["run"]["frames_file"]["count"];
  EXPECT_EQ(count, summary(dir, "parts")["outputs"].get<std::size_t>());
  EXPECT_FALSE(j["run"].contains("frames"));
  EXPECT_EQ(fs::file_size(dir / "parts/checkpoint.json.frames"),
            j["run"]["frames_file"]["bytes"].get<std::uintmax_t>());
  EXPECT_NE(slurp(dir / "parts/manifest.json").find("\"checkpoint.json.frames\""),
            std::string::npos);
  // As written before the frame file: each frame in the JSON (here every one at the
  // checkpoint's poses).
  nlohmann::json frames = nlohmann::json::array();
  nlohmann::json p = nlohmann::json::array(), r = nlohmann::json::array();
  for (const auto& b : j["bodies"]) {
    p.push_back(b["p_W_m"]);
    r.push_back(b["R_WB"]);
  }
  for (std::size_t k = 0; k < count; ++k)
    frames.push_back({{"t", 0.001 * k},
                      {"R_WB", r},
                      {"p_W_m", p},
                      {"contact_points_W_m", nlohmann::json::array()}});
  j["run"].erase("frames_file");
  j["run"]["frames"] = frames;
  spit(dir / "parts/checkpoint.json", j.dump());
  fs::remove(dir / "parts/checkpoint.json.frames");
  const auto res = run_finseg(dir, "run c.yaml --out parts --resume --quiet");
  ASSERT_EQ(res.code, 0) << res.err;
  EXPECT_EQ(summary(dir, "parts")["status"], "ok");
  EXPECT_TRUE(fs::exists(dir / "parts/vtk/frames_00020.vtu"));
  EXPECT_FALSE(fs::exists(dir / "parts/vtk/frames_00021.vtu"));
}

TEST(CliRunSafety, ResumeRefusesACheckpointOfAnotherScene) {
  TempDir dir;
  write_cantilever(dir, "explicit", 0.01);
  write_cantilever(dir, "explicit", 0.02, "d.yaml");
  ASSERT_EQ(run_finseg(dir, "run c.yaml --out out --quiet").code, 0);
  const auto r = run_finseg(dir, "run d.yaml --out out --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("scene_hash"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("another scene"), std::string::npos) << r.err;
}

TEST(CliRunSafety, StaticLoadOnlyRunStartsFromAStateFileButIsNotResumed) {
  TempDir dir;
  write_cantilever(dir, "static", 1);
  ASSERT_EQ(run_finseg(dir, "run c.yaml --out a --quiet").code, 0);
  auto r = run_finseg(dir, "run c.yaml --out a --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("no output between its start and its end"), std::string::npos) << r.err;
  // From its own equilibrium the static solver finds the same tip position.
  r = run_finseg(dir, "run c.yaml --out b --quiet --state a/checkpoint.json");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<double> ta = summary(dir, "a")["probes"]["tip"]["final"];
  const std::vector<double> tb = summary(dir, "b")["probes"]["tip"]["final"];
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(ta[k], tb[k], 1e-9);
}

TEST(CliRunSafety, StateFileOfAnotherModelIsRefused) {
  TempDir dir;
  write_cantilever(dir, "static", 1);
  ASSERT_EQ(run_finseg(dir, "run c.yaml --out a --quiet").code, 0);
  const auto r0 = run_finseg(dir, "gen cantilever --segments 4 --out e.yaml");
  ASSERT_EQ(r0.code, 0);
  const auto r = run_finseg(dir, "run e.yaml --out b --state a/checkpoint.json");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("model.bodies"), std::string::npos) << r.err;
}

// Write-time failures are found before the simulation: each scene below would run for
// minutes (t_end 1000 s, explicit) before writing anything.
void expect_refused_up_front(const TempDir& dir, const std::string& args,
                             const std::string& expected, const std::string& launcher = "") {
  const auto start = std::chrono::steady_clock::now();
  const auto r = run_finseg(dir, args, launcher);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
  EXPECT_LT(wall, 30.0);  // not after the run (which would take far longer)
}

TEST(CliRunSafety, InvalidUtf8TitleIsRefusedBeforeTheRun) {
  TempDir dir;
  write_cantilever(dir, "explicit", 1000);
  replace_line(dir / "c.yaml", "title: cantilever", "title: \"bad \xff\xfe title\"");
  expect_refused_up_front(dir, "run c.yaml --out out", "title: is not valid UTF-8");
  EXPECT_FALSE(fs::exists(dir / "out/summary.json"));
}

TEST(CliRunSafety, ProbeNamesThatCannotBeFileNamesAreRefusedBeforeTheRun) {
  TempDir dir;
  write_cantilever(dir, "explicit", 1000);
  replace_line(dir / "c.yaml", "name: tip", "name: " + std::string(256, 'p'));
  expect_refused_up_front(dir, "run c.yaml --out out", "probes[0].name: is 256 bytes long");
  replace_line(dir / "c.yaml", "name: " + std::string(256, 'p'), "name: \"a/b\"");
  expect_refused_up_front(dir, "run c.yaml --out out", "probes[0].name");
}

TEST(CliRunSafety, EmptyOutIsRefusedBeforeTheRun) {
  TempDir dir;
  write_cantilever(dir, "explicit", 1000);
  expect_refused_up_front(dir, "run c.yaml --out ''", "--out: must name a folder");
}

TEST(CliRunSafety, UncreatableOutIsRefusedBeforeTheRun) {
  TempDir dir;
  write_cantilever(dir, "explicit", 1000);
  spit(dir / "plain_file", "x");  // a path under a regular file stops root too
  expect_refused_up_front(dir, "run c.yaml --out plain_file/out", "cannot create");
}

TEST(CliRunSafety, ReadOnlyOutIsRefusedBeforeTheRun) {
  TempDir dir;
  write_cantilever(dir, "explicit", 1000);
  fs::create_directories(dir / "ro");
  chmod((dir / "ro").c_str(), 0555);
  // Root ignores permission bits; without the capabilities that let it, it obeys them.
  const std::string launcher =
      geteuid() == 0 ? "setpriv --bounding-set=-dac_override,-dac_read_search,-fowner " : "";
  expect_refused_up_front(dir, "run c.yaml --out ro", "cannot write files in this folder",
                          launcher);
  chmod((dir / "ro").c_str(), 0755);
}

// A disk that fills during the writing (a file-size limit, SIGXFSZ ignored so that writes
// fail with EFBIG as on a full disk): a clear error, non-zero exit, and no file that looks
// complete: no summary.json, no result file cut short, no partial file left behind.
TEST(CliRunSafety, FullDiskFailsClearlyAndLeavesNoFileThatLooksComplete) {
  TempDir dir;
  write_cantilever(dir, "explicit", 0.05);
  replace_line(dir / "c.yaml", "vtk: false", "vtk: true");
  const auto r =
      run_finseg(dir, "run c.yaml --out out --quiet", "trap '' XFSZ; ulimit -f 4; exec ");
  EXPECT_EQ(r.code, 4);
  EXPECT_NE(r.err.find("disk full?"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out/summary.json"));
  for (const auto& e : fs::recursive_directory_iterator(dir / "out")) {
    const std::string name = e.path().filename().string();
    EXPECT_EQ(name.find(".partial"), std::string::npos) << name;
    // Whatever is there was written whole: the tip CSV has all its 51 rows or is absent.
    if (name == "tip.csv") {
      EXPECT_EQ(csv_numbers(slurp(e.path())).size(), 51u);
    }
  }
}

// A second run into the same folder removes the first run's files (and only those).
TEST(CliRunSafety, SecondRunRemovesTheFirstRunsFiles) {
  TempDir dir;
  write_cantilever(dir, "explicit", 0.01);
  replace_line(dir / "c.yaml", "vtk: false", "vtk: true");
  ASSERT_EQ(run_finseg(dir, "run c.yaml --out out --quiet").code, 0);
  ASSERT_TRUE(fs::exists(dir / "out/vtk/frames.pvd"));
  ASSERT_TRUE(fs::exists(dir / "out/vtk/frames_00001.vtu"));
  spit(dir / "out/notes.txt", "mine");
  replace_line(dir / "c.yaml", "vtk: true", "vtk: false");
  replace_line(dir / "c.yaml", "name: tip", "name: end");
  ASSERT_EQ(run_finseg(dir, "run c.yaml --out out --quiet").code, 0);
  EXPECT_FALSE(fs::exists(dir / "out/tip.csv"));
  EXPECT_FALSE(fs::exists(dir / "out/vtk"));
  EXPECT_TRUE(fs::exists(dir / "out/end.csv"));
  EXPECT_EQ(slurp(dir / "out/notes.txt"), "mine");
  const auto m = nlohmann::json::parse(slurp(dir / "out/manifest.json"));
  const std::vector<std::string> files = m["files"];
  EXPECT_EQ(files, (std::vector<std::string>{"checkpoint.json", "end.csv", "summary.json",
                                             "manifest.json"}));
}

TEST(CliRunSafety, ProgressLinesWhenStderrIsNotATerminal) {
  TempDir dir;
  write_cantilever(dir, "implicit", 0.01);
  auto r = run_finseg(dir, "run c.yaml --out out --progress-every 0");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("finseg: [100.0%] t = 0.01 s"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ETA"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos);  // plain lines, no redrawing
  r = run_finseg(dir, "run c.yaml --out out --quiet --progress-every 0");
  EXPECT_EQ(r.err, "");
}

// A static load-only run reports its load steps, not only its end: the load reached (not the
// last output's, which stays at 0 until the end) and the Newton iterations so far.
TEST(CliRunSafety, StaticLoadSteppingReportsProgress) {
  TempDir dir;
  write_cantilever(dir, "static", 1);
  replace_line(dir / "c.yaml", "load_steps: 1", "load_steps: 4");
  const auto r = run_finseg(dir, "run c.yaml --out out --progress-every 0");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("finseg: [ 25.0%] load 0.25, "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" Newton iterations, 1 outputs"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("finseg: [100.0%] load 1"), std::string::npos) << r.err;
}

// Progress also where the run is not stepping: the static equilibrium and the eigen solve of
// `finseg modes`, and the writing of the VTK frames.
TEST(CliRunSafety, ModesAndOutputWritingReportProgress) {
  TempDir dir;
  write_cantilever(dir, "static", 1);
  replace_line(dir / "c.yaml", "load_steps: 1", "load_steps: 4");
  auto r = run_finseg(dir, "modes c.yaml --count 2 --progress-every 0");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("finseg: [100.0%] static equilibrium, load 1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("finseg: eigen solve: 2 modes of 48 degrees of freedom"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("finseg: eigen solve done in"), std::string::npos) << r.err;
  r = run_finseg(dir, "modes c.yaml --count 2 --quiet");
  EXPECT_EQ(r.err, "");
  write_cantilever(dir, "explicit", 0.02);
  replace_line(dir / "c.yaml", "vtk: false", "vtk: true");
  r = run_finseg(dir, "run c.yaml --out out --progress-every 0");
  ASSERT_EQ(r.code, 0) << r.err;
  std::size_t lines = 0;  // one a frame with --progress-every 0
  for (auto at = r.err.find("writing 21 VTK frames to out"); at != std::string::npos;
       at = r.err.find("writing 21 VTK frames to out", at + 1)) {
    ++lines;
  }
  EXPECT_EQ(lines, 21u) << r.err;
  EXPECT_NE(r.err.find("finseg: [100.0%] writing 21 VTK frames to out"), std::string::npos);
}

}  // namespace cli_run_safety_test
}  // namespace finseg
