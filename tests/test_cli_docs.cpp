// Documents that say what the program does: the README's commands leave tracked files
// alone, and `gen zigzag --pull-speed` writes the documented dynamic pull.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "cli_test_util.hpp"
#include "generators/zigzag.hpp"
#include "scene/scene_reader.hpp"
#include "test_paths.hpp"

namespace finseg::test {
namespace cli_docs_test {

TEST(CliDocs, ReadmeCommandsWriteNoTrackedExampleFile) {
  // Former defect: the README's cantilever example wrote examples/cantilever/alpha2.yaml.
  const std::string readme = slurp(std::string(FINSEG_SOURCE_DIR) + "/README.md");
  // "--out examples/...": split into words (std::regex trips GCC 12's -Wmaybe-uninitialized
  // under the sanitizers).
  const auto writes_into_examples = [](const std::string& line) {
    std::istringstream words(line);
    std::string word, previous;
    while (words >> word) {
      if (previous == "--out" && word.rfind("examples/", 0) == 0) return true;
      previous = word;
    }
    return false;
  };
  std::istringstream lines(readme);
  std::string line;
  int commands = 0;
  while (std::getline(lines, line)) {
    if (line.find("finseg ") == std::string::npos) continue;
    ++commands;
    EXPECT_FALSE(writes_into_examples(line)) << line;
  }
  EXPECT_GT(commands, 3);
}

TEST(CliDocs, GenZigzagPullSpeedWritesTheDynamicPull) {
  // Former defect: docs/zigzag.md's slow dynamic pull (zigzag.pull_speed) could not be
  // generated: `gen zigzag` had no --pull-speed.
  TempDir dir;
  CliResult r = run_finseg(dir,
                           "gen zigzag --solver implicit --pull-speed 0.01 --damping-time 0.001 "
                           "--output-interval 0.2 --out z.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  const Scene s = read_scene(dir / "z.yaml");
  ASSERT_EQ(s.model.drives.size(), 1u);
  EXPECT_EQ(s.model.drives[0].speed, 0.01);
  // Without --t-end: the default travel 0.9 * 2 a sin(80 deg) at 10 mm/s.
  const double travel = 0.9 * 2 * 0.08 * std::sin(80 * kDegToRad);
  EXPECT_NEAR(s.solver.t_end, travel / 0.01, 1e-12);
  r = run_finseg(dir, "gen zigzag --solver implicit --pull-speed 0.02 --t-end 3 --out y.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(read_scene(dir / "y.yaml").solver.t_end, 3.0);
  r = run_finseg(dir, "gen zigzag --pull-speed 0 --out x.yaml");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--pull-speed"), std::string::npos) << r.err;
}

}  // namespace cli_docs_test
}  // namespace finseg::test
