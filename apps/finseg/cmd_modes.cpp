// finseg modes: not implemented yet.
#include "apps/finseg/commands.hpp"

namespace finseg::cli {

void register_modes(CLI::App& /*app*/) {}

}  // namespace finseg::cli
