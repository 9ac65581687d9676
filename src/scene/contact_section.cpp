// Placeholder until the contact module reads its own section.
#include "core/error.hpp"
#include "scene/sections.hpp"

namespace finseg {

ContactDef read_contact_section(const YAML::Node&, const YamlContext& ctx) {
  throw InputError(ctx.file, ctx.field, "contact is not supported yet");
}

}  // namespace finseg
