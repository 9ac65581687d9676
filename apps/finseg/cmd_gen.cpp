// finseg gen: not implemented yet.
#include "apps/finseg/commands.hpp"

namespace finseg::cli {

void register_gen(CLI::App& /*app*/) {}

}  // namespace finseg::cli
