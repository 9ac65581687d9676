// finseg sweep SWEEP.yaml --out DIR [--jobs N]: runs the base scene once per case with the
// case's --set overrides, each as its own `finseg run` process in DIR/case_NNN, up to N at a
// time, and writes DIR/sweep.csv in case order (docs/sweep.md).
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

void sweep(const SweepOptions& o) {
  const SweepSpec spec = read_sweep(o.sweep);
  if (!fs::exists(spec.scene)) throw InputError(o.sweep, "scene", "no such file: " + spec.scene);
  const std::vector<std::vector<Override>> cases = sweep_cases(spec);
  fs::create_directories(o.out);
  const int jobs = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  std::vector<SweepCaseResult> results(cases.size());
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0, done = 0, failed = 0;
  while (done < cases.size()) {
    while (next < cases.size() && static_cast<int>(running.size()) < jobs) {
      running[start_case(spec, cases[next], next, o.out)] = next;
      ++next;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) throw std::runtime_error("waiting for the sweep's cases failed");
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const std::size_t i = it->second;
    running.erase(it);
    results[i] = collect(i, o.out, WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    const std::string st = results[i].summary.is_null()
                               ? std::string("failed")
                               : results[i].summary.value("status", std::string("?"));
    if (st != "ok") ++failed;
    ++done;
    if (!o.quiet) {
      fmt::print(stderr, "finseg: sweep: {} {}/{} {}\n", case_folder(i), done, cases.size(), st);
    }
  }
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
  if (failed > 0) throw ExitStatus{3};
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
