// Placeholder section readers until the contact and crease modules provide theirs.
#include "core/error.hpp"
#include "scene/sections.hpp"

namespace finseg {

ContactDef read_contact_section(const YAML::Node&, const YamlContext& ctx) {
  throw InputError(ctx.file, ctx.field, "contact is not supported yet");
}

std::shared_ptr<const CreaseLaw> read_crease_law(const YAML::Node&, const YamlContext& ctx) {
  throw InputError(ctx.file, ctx.field, "crease laws in scene files are not supported yet");
}

}  // namespace finseg
