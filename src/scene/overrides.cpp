#include "scene/overrides.hpp"

#include <fmt/format.h>

#include <charconv>

#include "core/error.hpp"
#include "core/text.hpp"
#include "scene/yaml_fields.hpp"

namespace finseg {
namespace {

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    parts.push_back(path.substr(start, dot - start));
    if (dot == std::string::npos) return parts;
    start = dot + 1;
  }
}

// List index of `part`, or -1 if it is not a non-negative integer.
long index_of(const std::string& part) {
  long i = -1;
  const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), i);
  return ec == std::errc() && end == part.data() + part.size() && i >= 0 ? i : -1;
}

// The child `part` of `node` (a map key or a list index), which must exist; `path` is the
// node's own dotted path, for messages.
YAML::Node child(const YAML::Node& node, const std::string& path, const std::string& part,
                 const std::string& file) {
  const std::string where = child_field(path, part);
  if (node.IsMap()) {
    const YAML::Node c = node[part];
    if (!c) throw InputError(file, where, "no such key in the scene (--set changes existing keys)");
    return c;
  }
  if (node.IsSequence()) {
    const long i = index_of(part);
    if (i < 0 || static_cast<std::size_t>(i) >= node.size()) {
      throw InputError(file, where,
                       fmt::format("the list has {} entries: index 0 to {}", node.size(),
                                   static_cast<long>(node.size()) - 1));
    }
    return node[static_cast<std::size_t>(i)];
  }
  throw InputError(file, path, "is a single value, not a map or a list");
}

YAML::Node value_node(const Override& o, const std::string& file) {
  try {
    return YAML::Load(o.value);
  } catch (const YAML::Exception& e) {
    throw InputError(
        file, o.path,
        fmt::format("--set value {} is not valid YAML: {}", finseg::quoted(o.value), e.msg));
  }
}

}  // namespace

Override parse_override(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) {
    throw InputError("--set", finseg::quoted(text),
                     "expected KEY.PATH=VALUE, e.g. solver.t_end=0.5");
  }
  Override o{text.substr(0, eq), text.substr(eq + 1)};
  for (const std::string& part : split_path(o.path)) {
    if (part.empty()) throw InputError("--set", finseg::quoted(o.path), "a path part is empty");
  }
  return o;
}

void apply_overrides(YAML::Node& root, const std::vector<Override>& overrides,
                     const std::string& file) {
  for (const Override& o : overrides) {
    const std::vector<std::string> parts = split_path(o.path);
    YAML::Node node;
    node.reset(root);  // rebinds; assigning would overwrite the root's value
    std::string path;  // of `node`
    for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
      node.reset(child(node, path, parts[k], file));
      path = child_field(path, parts[k]);
    }
    const std::string& last = parts.back();
    const YAML::Node value = value_node(o, file);
    if (node.IsMap()) {
      node[last] = value;  // a new key is checked by its section
    } else {
      child(node, path, last, file);  // refuses a missing index and a single value
      node[static_cast<std::size_t>(index_of(last))] = value;
    }
  }
}

}  // namespace finseg
