// finseg overlay: several run folders in one figure, peaks marked, a run that did not
// finish named as such; and the run outputs of a diverged run flagged in plot and HTML.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "cli_test_util.hpp"

namespace finseg::test {
namespace overlay_test {

// A small zigzag pulled quasi-statically (finishes) and explicitly with a far too large
// step (diverges after a few outputs).
void make_runs(const TempDir& dir) {
  ASSERT_EQ(run_finseg(dir,
                       "gen zigzag --segments-per-panel 3 --pull-travel 0.03 --pull-step 0.005 "
                       "--no-contact --out ok.yaml")
                .code,
            0);
  ASSERT_EQ(run_finseg(dir,
                       "gen zigzag --segments-per-panel 3 --pull-travel 0.03 --no-contact "
                       "--solver explicit --t-end 0.05 --dt 2e-3 --output-interval 2e-3 "
                       "--out bad.yaml")
                .code,
            0);
  ASSERT_EQ(run_finseg(dir, "run ok.yaml --out ok").code, 0);
  ASSERT_EQ(run_finseg(dir, "run bad.yaml --out bad").code, 3);
}

TEST(Overlay, DrawsEveryRunAndNamesTheOneThatDidNotFinish) {
  TempDir dir;
  make_runs(dir);
  // Former defect: a diverged run's plot and page looked finished.
  const auto summary = nlohmann::json::parse(slurp(dir / "bad/summary.json"));
  ASSERT_EQ(summary["status"], "diverged");
  EXPECT_NE(slurp(dir / "bad/gauge.png.gp").find("RUN DIVERGED"), std::string::npos);
  EXPECT_NE(slurp(dir / "bad/animation.html").find("role=\"alert\">RUN DIVERGED"),
            std::string::npos);
  EXPECT_EQ(slurp(dir / "ok/gauge.png.gp").find("RUN "), std::string::npos);
  // Former defect: the overlay was an inline gnuplot call in scripts/main.sh.
  const CliResult r = run_finseg(dir, "overlay ok bad --out both.svg --title 'two runs'");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string svg = slurp(dir / "both.svg");
  EXPECT_NE(svg.find("two runs"), std::string::npos);
  EXPECT_NE(svg.find("[diverged]"), std::string::npos);
  EXPECT_NE(svg.find("NOT FINISHED"), std::string::npos);
  const std::string gp = slurp(dir / "both.svg.gp");
  EXPECT_NE(gp.find("index 1 using 1:2"), std::string::npos);  // both curves drawn
  EXPECT_NE(gp.find("set key outside"), std::string::npos);
  // A folder without a run, or a probe the runs lack: exit 2 naming the file.
  const CliResult missing = run_finseg(dir, "overlay ok nowhere --out x.png");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("nowhere/summary.json"), std::string::npos) << missing.err;
  const CliResult probe = run_finseg(dir, "overlay ok --probe tip --out x.png");
  EXPECT_EQ(probe.code, 2);
  EXPECT_NE(probe.err.find("no drive probe 'tip'"), std::string::npos) << probe.err;
}

}  // namespace overlay_test
}  // namespace finseg::test
