// Placeholder until the crease module reads crease laws from scene files.
#include "core/error.hpp"
#include "scene/sections.hpp"

namespace finseg {

std::shared_ptr<const CreaseLaw> read_crease_law(const YAML::Node&, const YamlContext& ctx) {
  throw InputError(ctx.file, ctx.field, "crease laws in scene files are not supported yet");
}

}  // namespace finseg
