// Scene-file sections owned by their modules (contact, creases); the scene reader calls
// these so that each module validates its own keys.
#pragma once

#include <memory>
#include <string>

#include <yaml-cpp/yaml.h>

#include "model/contact_def.hpp"

namespace finseg {

class CreaseLaw;

/// Where a YAML node came from, for error messages ("file: field: problem").
struct YamlContext {
  std::string file;   ///< scene file path
  std::string field;  ///< dotted path of the node, e.g. "sheet.folds[2].law"
};

/// Reads the `contact:` section (docs/scene.md). Throws InputError on bad values. Panels in
/// `groups` are numbered from 1 as everywhere in scene files (stored from 0); with
/// `panels` > 0 each must be one of 1..panels.
ContactDef read_contact_section(const YAML::Node& node, const YamlContext& ctx, int panels = 0);

/// Reads a crease law description (docs/scene.md, docs/crease-data.md); relative file
/// names are resolved against the scene file's folder.
std::shared_ptr<const CreaseLaw> read_crease_law(const YAML::Node& node, const YamlContext& ctx);

}  // namespace finseg
