// Where the tests find the finseg binary and the source tree. CMake sets both on
// test_paths.cpp alone, so that every other test file compiles the same in any checkout.
#pragma once

namespace finseg::test {
extern const char* const kFinsegBinary;  ///< absolute path of the built finseg program
extern const char* const kSourceDir;     ///< absolute path of the repository root
}  // namespace finseg::test

#define FINSEG_BINARY (::finseg::test::kFinsegBinary)
#define FINSEG_SOURCE_DIR (::finseg::test::kSourceDir)
