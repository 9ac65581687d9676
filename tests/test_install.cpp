// `cmake --install` of this build tree into a temporary prefix holds the program, the
// library, its public headers and the CMake package, and a tiny consumer project finds it
// with find_package(finseg), builds against finseg::finseg and prints the version.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_test_util.hpp"
#include "core/version.hpp"
#include "test_paths.hpp"

namespace finseg {
namespace install_test {

namespace fs = std::filesystem;
using test::slurp;
using test::spit;
using test::TempDir;

int sh(const std::string& cmd) {
  return std::system(cmd.c_str());
}

TEST(Install, PrefixHoldsProgramLibraryHeadersAndAPackageThatAConsumerFinds) {
  const TempDir dir;
  const std::string build = fs::path(FINSEG_BINARY).parent_path().string();
  const std::string prefix = dir / "prefix", log = dir / "log.txt";
  ASSERT_EQ(sh("cmake --install '" + build + "' --prefix '" + prefix + "' > '" + log + "' 2>&1"), 0)
      << slurp(log);
  for (const char* f :
       {"bin/finseg", "include/finseg/core/version.hpp", "include/finseg/scene/scene_reader.hpp",
        "include/finseg/writers/vtk.hpp", "include/finseg/elements/crease_laws/measured.hpp"}) {
    EXPECT_TRUE(fs::exists(fs::path(prefix) / f)) << f;
  }
  const fs::path lib = fs::exists(fs::path(prefix) / "lib64") ? "lib64" : "lib";
  EXPECT_TRUE(fs::exists(fs::path(prefix) / lib / "libfinseg.a"));
  EXPECT_TRUE(fs::exists(fs::path(prefix) / lib / "cmake/finseg/finsegConfig.cmake"));
  EXPECT_TRUE(fs::exists(fs::path(prefix) / lib / "cmake/finseg/finsegConfigVersion.cmake"));
  EXPECT_FALSE(fs::exists(fs::path(prefix) / "include/finseg/core/version.cpp"));

  const std::string src = dir / "consumer";
  fs::create_directories(src);
  spit(src + "/CMakeLists.txt",
       "cmake_minimum_required(VERSION 3.25)\nproject(consumer LANGUAGES CXX)\n"
       "set(CMAKE_CXX_STANDARD 20)\nfind_package(finseg 0.1 REQUIRED)\n"
       "add_executable(consumer main.cpp)\n"
       "target_link_libraries(consumer PRIVATE finseg::finseg)\n");
  spit(src + "/main.cpp",
       "#include <cstdio>\n#include \"core/version.hpp\"\n"
       "int main() { std::printf(\"%s\", finseg::version().c_str()); }\n");
  const std::string bin = dir / "consumer-build", out = dir / "out.txt";
  ASSERT_EQ(sh("cmake -S '" + src + "' -B '" + bin + "' -DCMAKE_PREFIX_PATH='" + prefix + "' > '" +
               log + "' 2>&1 && cmake --build '" + bin + "' >> '" + log + "' 2>&1"),
            0)
      << slurp(log);
  ASSERT_EQ(sh("'" + bin + "/consumer' > '" + out + "'"), 0);
  EXPECT_EQ(slurp(out), version());
}

}  // namespace install_test
}  // namespace finseg
