// finseg identify: not implemented yet.
#include "apps/finseg/commands.hpp"

namespace finseg::cli {

void register_identify(CLI::App& /*app*/) {}

}  // namespace finseg::cli
