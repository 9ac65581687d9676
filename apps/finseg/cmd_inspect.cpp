// finseg inspect: not implemented yet.
#include "apps/finseg/commands.hpp"

namespace finseg::cli {

void register_inspect(CLI::App& /*app*/) {}

}  // namespace finseg::cli
