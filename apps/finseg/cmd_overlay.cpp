// finseg overlay DIR... --out FILE: the force curves of several `finseg run` folders in one
// figure (e.g. the four working conditions of scripts/main.sh), deployment peaks marked.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/finseg/commands.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
#include "writers/plot.hpp"

namespace finseg::cli {

namespace {

namespace fs = std::filesystem;

struct OverlayOptions {
  std::vector<std::string> dirs;
  std::string out = "pull_force.png", probe, title = "Pull force";
};

nlohmann::json read_summary(const std::string& dir) {
  const std::string path = (fs::path(dir) / "summary.json").string();
  std::ifstream in(path);
  if (!in) throw InputError(path, "file", "cannot be opened: not the output folder of a run");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path, "file", std::string("not valid JSON: ") + e.what());
  }
}

// The drive probe to draw: the one named, else the run's first drive probe.
std::string drive_probe(const nlohmann::json& summary, const std::string& wanted,
                        const std::string& path) {
  const nlohmann::json probes = summary.value("probes", nlohmann::json::object());
  for (const auto& [name, p] : probes.items()) {
    if (p.value("type", "") != "drive") continue;
    if (wanted.empty() || name == wanted) return name;
  }
  throw InputError(path, "probes",
                   wanted.empty() ? "the run has no drive probe"
                                  : "the run has no drive probe '" + wanted + "'");
}

// A drive probe's CSV (pull_displacement_m, force_N first): any number of rows, so that a
// run that stopped early is drawn too.
void read_drive_csv(const std::string& path, OverlayRun& r) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "file", "cannot be opened");
  std::string line;
  if (!std::getline(in, line) || line.rfind("pull_displacement_m,force_N", 0) != 0) {
    throw InputError(path, "header", "must begin with pull_displacement_m,force_N");
  }
  for (int number = 2; std::getline(in, line); ++number) {
    if (trim(line).empty()) continue;
    const std::vector<std::string> cells = split_csv_line(line);
    if (cells.size() < 2) throw InputError(path, fmt::format("line {}", number), "too few values");
    r.x_mm.push_back(1e3 * parse_number(cells[0], path, fmt::format("line {}", number)));
    r.force_N.push_back(parse_number(cells[1], path, fmt::format("line {}", number)));
  }
}

OverlayRun read_run(const std::string& dir, const std::string& wanted) {
  const nlohmann::json s = read_summary(dir);
  const std::string summary_path = (fs::path(dir) / "summary.json").string();
  const std::string probe = drive_probe(s, wanted, summary_path);
  OverlayRun r;
  r.label = s.value("title", fs::path(dir).filename().string());
  r.status = s.value("status", "unknown");
  read_drive_csv((fs::path(dir) / (probe + ".csv")).string(), r);
  const nlohmann::json& p = s["probes"][probe];
  if (p.contains("deployment_peak_force_N") && p["deployment_peak_force_N"].is_number()) {
    r.has_peak = true;
    r.peak_N = p["deployment_peak_force_N"];
    r.peak_x_mm = 1e3 * p["deployment_peak_displacement_m"].get<double>();
  }
  return r;
}

void run_overlay(const OverlayOptions& o) {
  std::vector<OverlayRun> runs;
  for (const std::string& d : o.dirs) runs.push_back(read_run(d, o.probe));
  write_plot(o.out, overlay_spec(o.title, runs));
  for (const OverlayRun& r : runs) {
    if (r.status != "ok") fmt::print(stderr, "finseg: note: {} ended '{}'\n", r.label, r.status);
  }
  fmt::print("wrote {} ({} runs)\n", o.out, runs.size());
}

}  // namespace

void register_overlay(CLI::App& app) {
  auto o = std::make_shared<OverlayOptions>();
  CLI::App* c = app.add_subcommand(
      "overlay", "draw the force curves of several run folders in one plot (.png or .svg)");
  c->add_option("dirs", o->dirs, "output folders of `finseg run`")->required();
  c->add_option("--out", o->out, "figure to write, .png or .svg")->capture_default_str();
  c->add_option("--probe", o->probe, "drive probe to draw (default: each run's first)");
  c->add_option("--title", o->title, "figure title")->capture_default_str();
  c->callback([o] { run_overlay(*o); });
}

}  // namespace finseg::cli
