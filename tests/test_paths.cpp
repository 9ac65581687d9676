#include "test_paths.hpp"

namespace finseg::test {
const char* const kFinsegBinary = FINSEG_BINARY_PATH;
const char* const kSourceDir = FINSEG_SOURCE_PATH;
}  // namespace finseg::test
