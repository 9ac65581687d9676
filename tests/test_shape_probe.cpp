// Shape probes (docs/scene.md): how far a run's bodies are from a named further folded frame
// of the pattern, after the best rigid fit. Checked against closed forms on a flat grid: a
// rigidly moved copy is at distance 0, a copy scaled by 1 + e about any point at e times the
// RMS distance of the bodies' centroids from their mean (the fit of a scaled copy is the
// identity turn, the centroids' translation); the frames read back from a FOLD file, and a
// probe naming no shape of the model is refused with the shapes it has.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "core/so3.hpp"
#include "generators/pattern_sheet.hpp"
#include "patterns/fold_format.hpp"
#include "patterns/grid_pattern.hpp"
#include "probes/recorder.hpp"
#include "scene/scene_reader.hpp"

namespace finseg {
namespace shape_probe_test {

// A 4 x 3 grid of 20 x 10 mm faces, flat, with two further folded frames: the sheet turned
// and moved rigidly ("moved") and scaled by 1 + e about the point c ("grown").
CreasePattern grid_with_shapes(double e, const Vec3& c) {
  CreasePattern p = grid_crease_pattern(4, 3, 0.02, 0.01);
  const Mat3 R = so3_exp<double>(Vec3(0.3, -0.2, 0.5));
  const Vec3 t(0.1, -0.05, 0.2);
  PatternShape moved{"moved", {}}, grown{"grown", {}};
  for (const Vec2& v : p.vertices_flat_m) {
    const Vec3 x(v.x(), v.y(), 0);
    p.vertices_folded_m.push_back(x);
    moved.vertices_m.push_back(R * x + t);
    grown.vertices_m.push_back(c + (1 + e) * (x - c));
  }
  p.shapes = {moved, grown};
  return p;
}

// The last row of a shape probe recorded once at the model's start.
std::vector<double> probe_at_start(Model m, int shape) {
  ProbeDef probe;
  probe.name = "shape";
  probe.kind = ProbeKind::Shape;
  probe.shape = shape;
  m.probes = {probe};
  SolverSettings settings;
  RunRecorder rec(m, settings, {});
  BodyForces f;
  f.f_W.assign(m.bodies.size(), Vec3::Zero());
  f.tau_W.assign(m.bodies.size(), Vec3::Zero());
  rec.record(initial_state(m), f);
  return rec.tables().front().rows.back();
}

TEST(ShapeProbe, RigidCopyIsAtZeroAndAScaledCopyAtTheClosedForm) {
  const double e = 0.01;
  for (const int n : {1, 3}) {
    PatternSheetSpec spec;
    spec.subdivisions = n;
    const Model m = build_pattern_model(grid_with_shapes(e, Vec3(0.013, 0.004, 0.0)), spec);
    ASSERT_EQ(m.shapes.size(), 2u);
    EXPECT_EQ(m.shapes[0].name, "moved");
    ASSERT_EQ(m.shapes[1].p_W.size(), m.bodies.size());
    const std::vector<double> moved = probe_at_start(m, 0);
    EXPECT_LT(moved[1], 1e-14);
    EXPECT_LT(moved[2], 1e-14);
    Vec3 mean = Vec3::Zero();
    for (const BodyDef& b : m.bodies) mean += b.p0_W;
    mean /= static_cast<double>(m.bodies.size());
    double sum = 0, largest = 0;
    for (const BodyDef& b : m.bodies) {
      sum += (b.p0_W - mean).squaredNorm();
      largest = std::max(largest, (b.p0_W - mean).norm());
    }
    const std::vector<double> grown = probe_at_start(m, 1);
    EXPECT_NEAR(grown[1], e * std::sqrt(sum / static_cast<double>(m.bodies.size())), 1e-14);
    EXPECT_NEAR(grown[2], e * largest, 1e-14);
  }
}

TEST(ShapeProbe, FramesReadBackFromAFoldFileAndAScenesProbeNamesOne) {
  test::TempDir dir;
  write_fold(dir / "grid.fold", grid_with_shapes(0.01, Vec3::Zero()));
  const CreasePattern back = read_fold(dir / "grid.fold");
  ASSERT_EQ(back.shapes.size(), 2u);
  EXPECT_EQ(back.shapes[1].title, "grown");
  EXPECT_NEAR(back.shapes[1].vertices_m[6].x(), 1.01 * 0.02, 1e-15);  // vertex (1, 1)
  const std::string scene = R"(material: {youngs_modulus: 3e9, density: 800}
sheet: {thickness: 1e-4}
pattern: {file: grid.fold, subdivisions: 1}
fixtures: {panels: [1]}
probes:
  - {name: s, type: shape, shape: )";
  test::spit(dir / "ok.yaml", scene + "grown}\n");
  const Scene s = read_scene(dir / "ok.yaml");
  ASSERT_EQ(s.model.probes.size(), 1u);
  EXPECT_EQ(s.model.probes[0].kind, ProbeKind::Shape);
  EXPECT_EQ(s.model.probes[0].shape, 1);
  test::spit(dir / "bad.yaml", scene + "deployed}\n");
  try {
    read_scene(dir / "bad.yaml");
    FAIL() << "a probe naming no shape was accepted";
  } catch (const InputError& err) {
    const std::string what = err.what();
    EXPECT_NE(what.find("probes[0].shape"), std::string::npos) << what;
    EXPECT_NE(what.find("'moved', 'grown'"), std::string::npos) << what;
  }
}

}  // namespace shape_probe_test
}  // namespace finseg
