// The cone gathered by simulation (`finseg gen cone --fold-to-gathered F`, docs/folding.md,
// "The cone gathered by folding"): `finseg run --fold` carries the deployed wall's creases to the
// gathered state's fold angles, and the static solver lands on the geometric gathered wall
// (`cone_gathered`, checked against the cone's closed form in test_cone_pattern.cpp) up to the
// rigid motion that keeps the clamped face in place; the generated drive then draws the pulled
// facet from where the fold leaves it back to its deployed place. The static solver gets there
// in a few hundred Newton iterations, not thousands (solvers/stiff_projection.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_test_util.hpp"
#include "core/rigid_fit.hpp"
#include "model/state.hpp"
#include "scene/scene_reader.hpp"

namespace finseg {
namespace cone_fold_gathered_test {

// Segment centroids of a state file (docs/state-file.md), m.
std::vector<Vec3> checkpoint_centroids(const std::string& path) {
  const nlohmann::json j = nlohmann::json::parse(test::slurp(path));
  std::vector<Vec3> p;
  for (const auto& b : j.at("bodies")) {
    const auto& x = b.at("p_W_m");
    p.emplace_back(x.at(0).get<double>(), x.at(1).get<double>(), x.at(2).get<double>());
  }
  return p;
}

constexpr const char* kCone =
    "gen cone --top open --base open --pleats 3 --axial-folds 1 --subdivisions 1 ";

TEST(ConeFoldGathered, StaticFoldLandsOnTheGatheredWallAndTheDriveLeadsBack) {
  test::TempDir dir;
  auto r = test::run_finseg(dir, std::string(kCone) + "--fold-to-gathered 0.9 --out c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = test::run_finseg(dir, std::string(kCone) + "--gathered 0.9 --out g.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = test::run_finseg(dir,
                       "run c.yaml --fold --out folded --quiet --set outputs.vtk=false "
                       "--set outputs.html=false --set outputs.plot=false");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Vec3> folded = checkpoint_centroids(dir / "folded/checkpoint.json");
  // The static solver follows the closed loop of facets with its projected trials
  // (solvers/stiff_projection.hpp): 169 Newton iterations; 1 458 without them.
  const nlohmann::json summary = nlohmann::json::parse(test::slurp(dir / "folded/summary.json"));
  EXPECT_LT(summary.at("stats").at("newton_iterations").get<int>(), 500);
  const Scene gathered = read_scene(dir / "g.yaml");
  const std::vector<Vec3> reference = initial_state(gathered.model).p_W;
  ASSERT_EQ(folded.size(), reference.size());
  ASSERT_EQ(folded.size(), 14u);  // 2 bands of 2 x 3 facets and the seam's halves
  // Every centroid where the gathered geometry puts it, up to one rigid motion: the static
  // solver's round-off (measured 9e-16 m at most; 1.5e-12 m for 6 pleats, 2 folds).
  const RigidFit fit = best_rigid_fit(reference, folded);
  for (std::size_t i = 0; i < folded.size(); ++i) {
    EXPECT_LT((fit.apply(reference[i]) - folded[i]).norm(), 1e-9) << "segment " << i;
  }
  // The fold moved the wall (the deployed cone is far from that)...
  const Scene deploy = read_scene(dir / "c.yaml");
  const std::vector<Vec3> deployed = initial_state(deploy.model).p_W;
  const RigidFit to_deployed = best_rigid_fit(deployed, folded);
  double farthest = 0;
  for (std::size_t i = 0; i < folded.size(); ++i) {
    farthest = std::max(farthest, (to_deployed.apply(deployed[i]) - folded[i]).norm());
  }
  EXPECT_GT(farthest, 0.02);
  // ... and the drive's travel along its direction takes its point (the pulled face's
  // centroid, one segment per face) from the folded place to the deployed one.
  ASSERT_EQ(deploy.model.drives.size(), 1u);
  const DriveDef& d = deploy.model.drives[0];
  double nearest = INFINITY;
  std::size_t pulled = 0;
  for (std::size_t i = 0; i < deployed.size(); ++i) {
    const double gap = (deployed[i] - d.start_W).norm();
    if (gap < nearest) nearest = gap, pulled = i;
  }
  ASSERT_LT(nearest, 1e-8);  // the scene's 9 significant digits
  EXPECT_LT((folded[pulled] + d.travel * d.direction_W - deployed[pulled]).norm(), 1e-8);
}

TEST(ConeFoldGathered, BadOptionsAreRefused) {
  test::TempDir dir;
  for (const auto& [bad, named] :
       {std::pair{"--fold-to-gathered 0.5", "--fold-to-gathered"},  // closed ends
        {"--top open --base open --fold-to-gathered 1", "--fold-to-gathered"},
        {"--top open --base open --fold-to-gathered -0.1", "--fold-to-gathered"},
        {"--top open --base open --fold-to-gathered 0.5 --gathered 0.5", "--fold-to-gathered"},
        {"--top open --base open --fold-to-gathered 0.5 --stowed 150", "--fold-to-gathered"},
        {"--top open --base open --fold-to-gathered 0.5 --fold-fraction 0.5", "--fold-fraction"}}) {
    test::expect_refused(dir, std::string("gen cone ") + bad + " --out l.yaml", named);
  }
}

}  // namespace cone_fold_gathered_test
}  // namespace finseg
