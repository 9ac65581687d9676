// finseg sweep SWEEP.yaml --out DIR [--jobs N]: runs the base scene once per case with the
// case's --set overrides, each as its own `finseg run` process in DIR/case_NNN, up to N at a
// time, and writes DIR/sweep.csv in case order (docs/sweep.md); under mpirun the ranks share
// the cases and rank 0 writes the table (apps/finseg/sweep_mpi.hpp).
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "apps/finseg/commands.hpp"
#include "apps/finseg/sweep_mpi.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
#include "sweep/sweep_plot.hpp"
#include "sweep/sweep_spec.hpp"
#include "sweep/sweep_table.hpp"
#include "writers/atomic_write.hpp"

namespace finseg::cli {
namespace {

namespace fs = std::filesystem;

struct SweepOptions {
  std::string sweep, out;
  int jobs = 0;  // 0: one per core
  bool quiet = false;
};

std::string case_folder(std::size_t i) {
  return fmt::format("case_{:03d}", i + 1);
}

// Starts `finseg run` for case i; its stdout and stderr go to DIR/case_NNN.log.
pid_t start_case(const SweepSpec& spec, const std::vector<Override>& c, std::size_t i,
                 const std::string& out) {
  std::vector<std::string> args{
      "finseg", "run", spec.scene, "--out", (fs::path(out) / case_folder(i)).string(), "--quiet"};
  for (const Override& o : c) {
    args.push_back("--set");
    args.push_back(o.path + "=" + o.value);
  }
  const std::string log = (fs::path(out) / (case_folder(i) + ".log")).string();
  const pid_t pid = fork();
  if (pid == 0) {
    if (!freopen(log.c_str(), "w", stdout) || dup2(fileno(stdout), fileno(stderr)) < 0) _exit(120);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv("/proc/self/exe", argv.data());
    _exit(121);
  }
  if (pid < 0) throw std::runtime_error("cannot start a process for " + case_folder(i));
  return pid;
}

// "failed" when the case wrote no summary, else the summary's status.
std::string case_status(const SweepCaseResult& r) {
  return r.summary.is_null() ? std::string("failed") : r.summary.value("status", std::string("?"));
}

// What case i left in DIR: its summary, or the last error line of its log.
SweepCaseResult collect(std::size_t i, const std::string& out, int exit_code) {
  SweepCaseResult r;
  const fs::path summary = fs::path(out) / case_folder(i) / "summary.json";
  if (fs::exists(summary)) {
    r.summary = nlohmann::json::parse(read_text_file(summary.string()));
    return r;
  }
  const std::string log = read_text_file((fs::path(out) / (case_folder(i) + ".log")).string());
  const std::string marker = "finseg: error: ";
  const std::size_t at = log.rfind(marker);
  r.failure = at == std::string::npos
                  ? fmt::format("exit code {}", exit_code)
                  : log.substr(at + marker.size(), log.find('\n', at) - at - marker.size());
  return r;
}

// Runs the cases `mine` (indices into `cases`), up to `jobs` at a time; their results in
// the order of `mine`.
std::vector<SweepCaseResult> run_cases(const SweepSpec& spec,
                                       const std::vector<std::vector<Override>>& cases,
                                       const std::vector<std::size_t>& mine, int jobs,
                                       const SweepOptions& o, const std::string& who) {
  std::vector<SweepCaseResult> results(mine.size());
  std::map<pid_t, std::size_t> running;  // process -> position in `mine`
  std::size_t next = 0, done = 0;
  while (done < mine.size()) {
    while (next < mine.size() && static_cast<int>(running.size()) < jobs) {
      running[start_case(spec, cases[mine[next]], mine[next], o.out)] = next;
      ++next;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) throw std::runtime_error("waiting for the sweep's cases failed");
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const std::size_t k = it->second, i = mine[k];
    running.erase(it);
    results[k] = collect(i, o.out, WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    ++done;
    if (!o.quiet) {
      fmt::print(stderr, "finseg: sweep: {}{} {}/{} {}\n", who, case_folder(i), done, mine.size(),
                 case_status(results[k]));
    }
  }
  return results;
}

// Rank 0 (or the only process): the table and the plot; the number of cases not ok.
int write_table(const SweepSpec& spec, const std::vector<std::vector<Override>>& cases,
                const std::vector<SweepCaseResult>& results, const SweepOptions& o) {
  int failed = 0;
  for (const SweepCaseResult& r : results) failed += case_status(r) != "ok";
  const std::string table = (fs::path(o.out) / "sweep.csv").string();
  write_file_atomically(table, sweep_table_csv(spec, cases, results));
  fmt::print("wrote {} ({} cases, {} not ok)\n", table, cases.size(), failed);
  if (const auto plot = sweep_plot_spec(spec, cases, results)) {
    const std::string png = (fs::path(o.out) / "sweep.png").string();
    try {
      write_plot(png, *plot);
      fmt::print("wrote {}\n", png);
    } catch (const std::runtime_error& e) {
      fmt::print(stderr, "finseg: warning: {} not written: {}\n", png, e.what());
    }
  }
  return failed;
}

void sweep(const SweepOptions& o) {
  const SweepSpec spec = read_sweep(o.sweep);
  if (!fs::exists(spec.scene)) throw InputError(o.sweep, "scene", "no such file: " + spec.scene);
  const std::vector<std::vector<Override>> cases = sweep_cases(spec);
  const SweepMpi mpi;  // after the checks: a bad sweep file stops every rank alike, before MPI
  // Under mpirun each rank takes every size-th case (static round robin) and runs one at a
  // time unless --jobs says otherwise: the ranks are the parallelism.
  const int jobs = o.jobs > 0 ? o.jobs
                   : mpi.active()
                       ? 1
                       : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::size_t> mine;
  for (std::size_t i = mpi.rank(); i < cases.size(); i += mpi.size()) mine.push_back(i);
  const std::string who = mpi.active() ? fmt::format("rank {}: ", mpi.rank()) : "";
  std::vector<SweepCaseResult> results;
  int failed = 0;
  try {
    fs::create_directories(o.out);
    results = mpi.gather(mine, run_cases(spec, cases, mine, jobs, o, who), cases.size());
    if (mpi.rank() == 0) failed = write_table(spec, cases, results, o);
  } catch (const std::exception& e) {
    if (!mpi.active()) throw;
    fmt::print(stderr, "finseg: error: {}{}\n", who, e.what());
    mpi.abort(dynamic_cast<const OutputError*>(&e) ? 4 : 2);
  }
  if (mpi.broadcast(failed) > 0) throw ExitStatus{3};
}

}  // namespace

void register_sweep(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep", "run a scene once per case of a parameter sweep; table in DIR/sweep.csv");
  cmd->add_option("SWEEP", o->sweep, "sweep file (docs/sweep.md)")->required();
  cmd->add_option("--out", o->out, "folder for the cases and sweep.csv")->required();
  cmd->add_option("--jobs", o->jobs, "cases run at once (default: one per core)")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--quiet", o->quiet, "no line per finished case on stderr");
  cmd->callback([o] { sweep(*o); });
}

}  // namespace finseg::cli
