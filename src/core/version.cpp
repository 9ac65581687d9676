#include "core/version.hpp"

// Both are defined by CMake on this file only (CMakeLists.txt).
#ifndef FINSEG_VERSION
#define FINSEG_VERSION "unknown"
#endif
#ifndef FINSEG_GIT_REVISION
#define FINSEG_GIT_REVISION "unknown"
#endif

namespace finseg {

std::string version() {
  return FINSEG_VERSION;
}

std::string git_revision() {
  return FINSEG_GIT_REVISION;
}

}  // namespace finseg
