// Checks on the size of what a scene asks for, made before anything is built or run: the
// memory a model needs (against what the machine has free) and the number of steps and
// outputs of its run (docs/scene.md, "Size limits").
#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "scene/scene_parts.hpp"
#include "solvers/step_limits.hpp"

namespace finseg {
namespace {

// Peak RSS per segment, a lower bound fitted to measurements (BENCHMARKS.md, "Memory per
// segment"): one row, 4096 segments: 14.3 KiB (implicit; its sparse LU dominates). Several
// rows fill the LU in more, growing with the shorter side: 8 x 2000 >= 29 KiB, 256 x 16
// >= 41.5 KiB, 64 x 64 >= 63 KiB. The check refuses only models that cannot fit.
constexpr double kBytesOneRow = 16.0 * 1024;
constexpr double kBytesRows = 28.0 * 1024;
constexpr double kBytesPerShortSide = 0.5 * 1024;
// DOF indices are 32-bit ints (6 per segment).
constexpr double kMaxSegments = 1e8;

}  // namespace

std::optional<double> available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    std::string key;
    double kib = 0;
    if (ss >> key >> kib && key == "MemAvailable:") return kib * 1024;
  }
  return std::nullopt;
}

void check_model_memory(double along, double across, const std::string& file,
                        const std::string& fields) {
  const double segments = along * across;
  const double per_segment =
      across > 1 ? kBytesRows + kBytesPerShortSide * std::min(along, across) : kBytesOneRow;
  const double need = segments * per_segment;
  if (segments > kMaxSegments) {
    throw InputError(file, fields,
                     fmt::format("{:.3g} segments; at most {:.0e} (needs at least {:.3g} GiB)",
                                 segments, kMaxSegments, need / (1 << 30)));
  }
  const std::optional<double> free = available_memory_bytes();
  if (free && need > *free) {
    throw InputError(
        file, fields,
        fmt::format("{:.3g} segments ({:.3g} x {:.3g}) need at least {:.3g} GiB ({:.0f} KiB per "
                    "segment, BENCHMARKS.md) but {:.3g} GiB are available; use fewer segments",
                    segments, along, across, need / (1 << 30), per_segment / 1024,
                    *free / (1 << 30)));
  }
}

void check_run_size(const Scene& scene, const std::string& drive_step_field) {
  const SolverSettings& s = scene.solver;
  const std::string& file = scene.file;
  if (s.kind == SolverKind::Static) {
    const Model& m = scene.model;
    if (has_drive_path(m)) {
      checked_step_count(m.drives[0].travel, m.drives[0].step, kMaxSteps, file, drive_step_field);
    }
    return;
  }
  const double every = s.output_interval > 0 ? s.output_interval : s.t_end / 100;
  checked_step_count(s.t_end, every, kMaxOutputs, file, "solver.output_interval");
  if (s.kind == SolverKind::Explicit && s.dt > 0) {
    checked_step_count(s.t_end, s.dt, kMaxSteps, file, "solver.dt");
  }
  if (s.kind == SolverKind::Implicit) {
    checked_step_count(s.t_end, s.dt_max > 0 ? s.dt_max : every, kMaxSteps, file,
                       s.dt_max > 0 ? "solver.dt_max" : "solver.output_interval");
  }
}

}  // namespace finseg
