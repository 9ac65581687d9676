// Scene file -> Scene: parses the YAML once, then reads the sections in dependency order.
#include "scene/scene_reader.hpp"

#include <fmt/format.h>

#include "scene/scene_parts.hpp"
#include "writers/atomic_write.hpp"

namespace finseg {

Scene read_scene(const std::string& path) {
  std::string text;
  try {
    text = read_whole_file(path);
  } catch (const std::exception& e) {
    throw InputError(path, "file", std::string("cannot be read: ") + e.what());
  }
  return parse_scene(text, path);
}

Scene parse_scene(const std::string& yaml, const std::string& file) {
  YAML::Node root_node;
  try {
    root_node = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw InputError(file, fmt::format("line {}", e.mark.line + 1),
                     fmt::format("malformed YAML: {}", e.msg));
  }
  if (!root_node.IsMap()) throw InputError(file, "<top level>", "must be a map of sections");
  const Fields root(
      root_node, {file, ""},
      {"title", "material", "sheet", "discretisation", "stiffness", "fixtures", "gravity", "loads",
       "drives", "probes", "contact", "zigzag", "solver", "outputs", "pressures"});
  Scene scene;
  scene.file = file;
  try {
    scene.title = root.word("title", "");
    scene.model = read_structure(root, scene.zigzag);
    read_attachments(root, scene.zigzag, scene.model);
    read_pressures(root, scene.model);
    scene.solver = read_solver_section(root);
    scene.outputs = read_outputs_section(root, scene.model);
  } catch (const YAML::Exception& e) {  // e.g. a map or list used as a key
    throw InputError(file, fmt::format("line {}", e.mark.line + 1), e.msg);
  }
  in_scene_file(file, [&] { validate(scene.model); });
  return scene;
}

}  // namespace finseg
