// finseg run: not implemented yet.
#include "apps/finseg/commands.hpp"

namespace finseg::cli {

void register_run(CLI::App& /*app*/) {}

}  // namespace finseg::cli
