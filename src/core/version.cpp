#include "core/version.hpp"

// The version is defined by CMake on this file only; the revision comes in a header that the
// build writes anew whenever HEAD moves (CMakeLists.txt, cmake/git_revision.cmake).
#include "finseg_git_revision.hpp"
#ifndef FINSEG_VERSION
#define FINSEG_VERSION "unknown"
#endif

namespace finseg {

std::string version() {
  return FINSEG_VERSION;
}

std::string git_revision() {
  return FINSEG_GIT_REVISION;
}

}  // namespace finseg
