// Helpers for tests that run the finseg binary (FINSEG_BINARY) in a fresh temporary folder.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "test_paths.hpp"

namespace finseg::test {

/// A fresh folder under the system's temp dir, removed when the test ends.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            (std::string("finseg_") + info->test_suite_name() + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void spit(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

/// Numbers of a CSV text's rows; its first line (the header) goes to `header`.
inline std::vector<std::vector<double>> csv_rows(const std::string& text, std::string* header) {
  std::stringstream in(text);
  std::string line;
  std::getline(in, *header);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> r;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) r.push_back(std::stod(cell));
    rows.push_back(r);
  }
  return rows;
}

/// Header of a contact probe's CSV (docs/scene.md, "Run outputs").
inline constexpr const char* kContactProbeHeader =
    "t_s,active_points,normal_force_N,friction_force_N,max_penetration_m,touching_pairs";

/// Result of one finseg invocation.
struct CliResult {
  int code = -1;
  std::string out, err;
};

/// Runs `finseg ARGS` in `dir` (stdout and stderr captured to files there).
/// Runs `finseg ARGS` in `dir`; `launcher` is shell text put before the program (e.g. a
/// `ulimit` and `exec`, or `setpriv ...`).
inline CliResult run_finseg(const TempDir& dir, const std::string& args,
                            const std::string& launcher = "") {
  const std::string out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd = "cd '" + dir.path().string() + "' && " + launcher + "'" + FINSEG_BINARY +
                          "' " + args + " > '" + out + "' 2> '" + err + "'";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

/// Runs a shipped example as a user would: copies `scene` and `files` (its FOLD pattern, data)
/// from examples/`folder`/ into `dir` and runs `finseg run SCENE --out run --quiet` there with
/// VTK, HTML and plot off, plus `extra` arguments (e.g. "--set solver.t_end=0.1").
inline CliResult run_example(const TempDir& dir, const std::string& folder,
                             const std::string& scene, const std::vector<std::string>& files,
                             const std::string& extra = "") {
  const std::string from = std::string(FINSEG_SOURCE_DIR) + "/examples/" + folder + "/";
  std::filesystem::copy_file(from + scene, dir / scene);
  for (const std::string& f : files) std::filesystem::copy_file(from + f, dir / f);
  return run_finseg(dir, "run " + scene +
                             " --out run --quiet --set outputs.vtk=false --set outputs.html=false "
                             "--set outputs.plot=false " +
                             extra);
}

/// Expects `finseg ARGS` run in `dir` to refuse with exit code 2 and a message containing
/// `named` (the option or field the refusal must name).
inline void expect_refused(const TempDir& dir, const std::string& args, const std::string& named) {
  const CliResult r = run_finseg(dir, args);
  EXPECT_EQ(r.code, 2) << args;
  EXPECT_NE(r.err.find(named), std::string::npos) << args << ": " << r.err;
}

/// The segment centres (p_W_m) of a state file (checkpoint.json), m, in body order.
inline std::vector<Vec3> state_centres(const std::filesystem::path& state_file) {
  std::ifstream in(state_file);
  const nlohmann::json j = nlohmann::json::parse(in);
  std::vector<Vec3> p;
  for (const auto& b : j["bodies"]) {
    p.emplace_back(b["p_W_m"][0].get<double>(), b["p_W_m"][1].get<double>(),
                   b["p_W_m"][2].get<double>());
  }
  return p;
}

/// The first word of `args` ("--radius 0" -> "--radius").
inline std::string first_word(const std::string& args) {
  return args.substr(0, args.find(' '));
}

}  // namespace finseg::test
