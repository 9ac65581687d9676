// finseg compare: not implemented yet.
#include "apps/finseg/commands.hpp"

namespace finseg::cli {

void register_compare(CLI::App& /*app*/) {}

}  // namespace finseg::cli
