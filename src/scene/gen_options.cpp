#include "scene/gen_options.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "core/error.hpp"

namespace finseg {
namespace {

// A data file as the scene must name it: relative to the scene file's folder (crease-law
// files are resolved against it).
std::string relative_to_scene(const std::string& data, const std::string& scene_out,
                              const OptionNaming& names) {
  namespace fs = std::filesystem;
  if (!fs::exists(data)) throw InputError(data, names("crease_law"), "file does not exist");
  if (scene_out.empty() || fs::path(data).is_absolute()) return data;
  const fs::path dir = fs::absolute(scene_out).parent_path();
  return fs::proximate(fs::absolute(data), dir).generic_string();
}

}  // namespace

std::string OptionNaming::operator()(const std::string& key) const {
  std::string out = prefix + key;
  for (std::size_t i = prefix.size(); i < out.size(); ++i)
    if (out[i] == '_') out[i] = separator;
  return out;
}

std::optional<SolverKind> solver_kind_from_name(const std::string& name) {
  for (SolverKind k : {SolverKind::Static, SolverKind::Implicit, SolverKind::Explicit})
    if (solver_name(k) == name) return k;
  return std::nullopt;
}

std::string zigzag_gen_scene(ZigzagGenOptions o, const OptionNaming& names,
                             const std::string& scene_out) {
  ZigzagSceneOptions& z = o.z;
  const std::string& src = names.source;
  if (!z.crease_law_file.empty() && z.crease_stiffness) {
    throw InputError(
        src, names("crease_law"),
        fmt::format("give {} or {}, not both", names("crease_law"), names("crease_stiffness")));
  }
  if (z.pressing_time && z.crease_law_file.empty())
    throw InputError(src, names("pressing_time"), "needs " + names("crease_law"));
  if (!z.crease_law_file.empty())
    z.crease_law_file = relative_to_scene(z.crease_law_file, scene_out, names);
  ZigzagSpec check = z.spec;
  check.fold_angle = z.fold_angle_deg * kDegToRad;
  validate(check, src);
  if (z.pull_speed) {
    const double v = *z.pull_speed;
    if (!(v > 0 && std::isfinite(v))) {
      throw InputError(src, names("pull_speed"), fmt::format("{} m/s; must be finite and > 0", v));
    }
    const double travel =
        z.spec.pull_travel > 0 ? z.spec.pull_travel : zigzag_default_travel(check);
    if (!o.t_end_given) o.solver.t_end = travel / v;
  }
  return zigzag_scene(z, o.solver);
}

std::string cantilever_gen_scene(const CantileverSpec& spec, const SolverSettings& solver,
                                 const OptionNaming& names) {
  validate(spec, names.source);
  return cantilever_scene(spec, solver);
}

}  // namespace finseg
