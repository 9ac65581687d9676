// examples/cone/stowed.yaml as shipped: the fan stack's layers coincide (a whole thickness
// into each other; tests/test_cone_gathered.cpp measures that), and
// `contact.initial_overlap: ignore` starts it with contact on (docs/contact.md, "Layers that
// start overlapping"). References: no contact force at the start although every stacked pair
// overlaps (the overlap law's definition), and the pull going on with contact on. The
// penetration beyond the start's overlap is not bounded here: the stack's layers have no
// consistent order (docs/folding.md, "Why the fan stack has no counterpart with thickness")
// and the pull presses them 0.4 t into each other (measured, docs/folding.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cli_test_util.hpp"

namespace finseg {
namespace cone_stowed_test {

TEST(ConeStowed, ExamplePullStartsWithContactOnAndNoForceFromTheStacksOverlap) {
  test::TempDir dir;
  // The first 0.1 s of the pull (16 mm of the gauge's 160 mm).
  const auto r =
      test::run_example(dir, "cone", "stowed.yaml", {"stowed.fold"}, "--set solver.t_end=0.1");
  ASSERT_EQ(r.code, 0) << r.err;
  std::string header;
  const auto rows = test::csv_rows(test::slurp(dir / "run/contact.csv"), &header);
  ASSERT_EQ(header, test::kContactProbeHeader);
  ASSERT_GE(rows.size(), 10u);
  EXPECT_NEAR(rows.back()[0], 0.1, 1e-9);
  EXPECT_EQ(rows.front()[1], 0);  // overlapping everywhere, pushing nowhere
  EXPECT_EQ(rows.front()[2], 0);
  int touching = 0;
  for (const auto& row : rows) touching = std::max(touching, static_cast<int>(row[1]));
  EXPECT_GT(touching, 0);  // layers that have parted meet again
}

}  // namespace cone_stowed_test
}  // namespace finseg
