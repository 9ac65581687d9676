// The shipped example scenes are the models they claim to be: examples/zigzag/ holds Table 1's
// four working conditions exactly as paper_condition(n) builds them (docs/zigzag.md).
#include <gtest/gtest.h>

#include <string>

#include "generators/zigzag.hpp"
#include "generators/zigzag_conditions.hpp"
#include "model_compare.hpp"
#include "scene/scene_reader.hpp"
#include "test_paths.hpp"

namespace finseg {
namespace examples_test {

TEST(Examples, ZigzagScenesAreTheFourPaperConditions) {
  const char* files[] = {"condition1-80deg-plain.yaml", "condition2-80deg-taped.yaml",
                         "condition3-83deg-plain.yaml", "condition4-83deg-taped.yaml"};
  for (int n = 1; n <= 4; ++n) {
    SCOPED_TRACE(files[n - 1]);
    const Scene scene =
        read_scene(std::string(FINSEG_SOURCE_DIR) + "/examples/zigzag/" + files[n - 1]);
    EXPECT_EQ(scene.solver.kind, SolverKind::Static);
    test::expect_same_model(scene.model, build_zigzag_model(paper_condition(n)));
  }
}

}  // namespace examples_test
}  // namespace finseg
