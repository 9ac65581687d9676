// Scene file -> Scene: parses the YAML once, then reads the sections in dependency order.
#include "scene/scene_reader.hpp"

#include <fmt/format.h>

#include "core/text.hpp"
#include "elements/chamber_gas.hpp"
#include "scene/scene_parts.hpp"

namespace finseg {

std::string scene_field_of_model(const std::string& model_field, bool zigzag) {
  const auto part = [&](const char* p) { return model_field.find(p) != std::string::npos; };
  if (model_field.rfind("bodies", 0) == 0) {
    if (part(".mass") || part(".inertia")) {
      return "material.density, sheet.thickness, sheet.length, sheet.width (segment mass = "
             "density x thickness x area; from " +
             model_field + ")";
    }
    return "sheet.length, sheet.width, sheet.thickness, discretisation (from " + model_field + ")";
  }
  if (model_field.rfind("elements", 0) == 0) {
    if (part(".damping")) return "material.damping_time (from " + model_field + ")";
    return "material.youngs_modulus, stiffness, crease laws (from " + model_field + ")";
  }
  if (zigzag && model_field.rfind("drives[0]", 0) == 0) {
    return "zigzag.pull_* / gauge_stiffness (from " + model_field + ")";
  }
  return model_field;  // loads[i], drives[i], gravity: named as in the scene
}

Scene read_scene(const std::string& path, const std::vector<Override>& overrides) {
  return parse_scene(read_text_file(path), path, overrides);
}

Scene parse_scene(const std::string& yaml, const std::string& file,
                  const std::vector<Override>& overrides) {
  YAML::Node root_node = load_yaml_map(yaml, file, "a map of sections");
  apply_overrides(root_node, overrides, file);
  const Fields root(root_node, {file, ""},
                    {"title", "material", "sheet", "discretisation", "stiffness", "fixtures",
                     "gravity", "loads", "drives", "probes", "contact", "zigzag", "pattern",
                     "solver", "outputs", "pressures", "chambers", "folding"});
  Scene scene;
  scene.file = file;
  scene.overrides = overrides;
  try {
    scene.title = root.word("title", "");
    scene.model = read_structure(root, scene.zigzag, scene.pattern_file);
    read_attachments(root, scene.zigzag, scene.model);
    read_pressures(root, scene.model);
    read_chambers(root, scene.model);
    scene.solver = read_solver_section(root);
    read_folding_section(root, scene);
    scene.outputs = read_outputs_section(root, scene.model);
    check_run_size(scene, scene.zigzag ? "zigzag.pull_step" : "drives[0].step");
  } catch (const YAML::Exception& e) {  // e.g. a map or list used as a key
    throw InputError(file, fmt::format("line {}", e.mark.line + 1), e.msg);
  }
  try {
    validate(scene.model);
    prepare_chambers(scene.model);  // closed, oriented outwards, vents smaller than the faces
  } catch (const InputError& e) {
    const std::string prefix = e.file() + ": " + e.field() + ": ";
    std::string what = e.what();
    if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
    throw InputError(file, scene_field_of_model(e.field(), scene.zigzag), what);
  }
  return scene;
}

}  // namespace finseg
