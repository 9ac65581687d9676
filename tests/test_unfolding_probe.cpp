// Unfolding probes (docs/scene.md): every crease line's fold angle followed from the run's
// start towards flat or towards a named shape, and the order the lines came half open.
// Checked against closed forms on a strip of three faces whose two creases are turned by
// prescribed angles: each line's opening is the imposed share of its turn, the abscissae
// where they come half and 90 % open are those of the imposed schedules (linear between the
// outputs), the target angle read from a further folded frame is the frame's dihedral angle,
// and each line's pieces lie on its pattern edge. Scenes name the probe, and refuse it where
// it cannot be.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "patterns/fold_format.hpp"
#include "patterns/grid_pattern.hpp"
#include "probes/recorder.hpp"
#include "scene/scene_reader.hpp"

namespace finseg {
namespace unfolding_probe_test {

constexpr double kSide = 0.02;  // m, each face kSide x kSide, creases at x = kSide, 2 kSide

// Where faces B (kSide < x < 2 kSide) and C (x > 2 kSide) are when B is turned by phi1 about
// the first crease line and C by phi2 more about the second (rad, about -y: upwards).
struct StripPose {
  Vec3 p;
  Mat3 R;
};
StripPose strip_pose(const Vec3& flat, double phi1, double phi2) {
  const Mat3 R1 = Eigen::AngleAxisd(phi1, -Vec3::UnitY()).toRotationMatrix();
  const Mat3 R2 = Eigen::AngleAxisd(phi2, -Vec3::UnitY()).toRotationMatrix();
  const Vec3 A1(kSide, 0, 0), A2(2 * kSide, 0, 0);
  if (flat.x() < kSide) return {flat, Mat3::Identity()};
  if (flat.x() < 2 * kSide) return {A1 + R1 * (flat - A1), R1};
  return {A1 + R1 * (A2 + R2 * (flat - A2) - A1), R1 * R2};
}

// Three faces in a row with valley creases between them, flat; with `shape`, a further frame
// "half" where B is turned by 30 degrees and C lies in B's plane.
CreasePattern three_faces(bool shape) {
  CreasePattern p = grid_crease_pattern(3, 1, kSide, kSide);
  for (PatternEdge& e : p.edges) {
    const double x0 = p.vertices_flat_m[e.vertices[0]].x(),
                 x1 = p.vertices_flat_m[e.vertices[1]].x();
    const bool inside = x0 == x1 && x0 > 0 && x0 < 3 * kSide - 1e-12;
    if (inside) e.assignment = EdgeAssignment::Valley;
  }
  if (shape) {
    PatternShape half{"half", {}};
    for (const Vec2& v : p.vertices_flat_m) {
      p.vertices_folded_m.emplace_back(v.x(), v.y(), 0);  // the start: flat
      half.vertices_m.push_back(strip_pose(Vec3(v.x(), v.y(), 0), 30 * kDegToRad, 0).p);
    }
    p.shapes = {half};
  }
  return p;
}

Model strip_model(bool shape, int subdivisions) {
  PatternSheetSpec spec;
  spec.subdivisions = subdivisions;
  spec.valley_law = std::make_shared<LinearCreaseLaw>(1e-3, 0.0);
  return build_pattern_model(three_faces(shape), spec);
}

// The state with the strip's creases turned by phi1 and phi2 (rad).
State turned(const Model& m, double t, double phi1, double phi2) {
  State s = initial_state(m);
  s.t = t;
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const Vec2 c = *m.bodies[i].centroid_M;
    const StripPose q = strip_pose(Vec3(c.x(), c.y(), 0), phi1, phi2);
    s.p_W[i] = q.p;
    s.R_WB[i] = q.R;
  }
  return s;
}

RunRecorder unfolding_recorder(Model& m, int shape) {
  ProbeDef probe;
  probe.name = "unfolding";
  probe.kind = ProbeKind::Unfolding;
  probe.shape = shape;
  m.probes = {probe};
  SolverSettings settings;
  settings.kind = SolverKind::Implicit;  // the abscissa is t_s
  return RunRecorder(m, settings, {});
}

BodyForces no_forces(const Model& m) {
  BodyForces f;
  f.f_W.assign(m.bodies.size(), Vec3::Zero());
  f.tau_W.assign(m.bodies.size(), Vec3::Zero());
  return f;
}

TEST(UnfoldingProbe, LinesOpenInTheOrderAndAtTheTimesOfTheirImposedTurns) {
  for (const int n : {1, 2}) {
    Model m = strip_model(false, n);
    RunRecorder rec = unfolding_recorder(m, -1);
    const auto& lines = rec.unfolding_lines_of(0);
    ASSERT_EQ(lines.size(), 2u);
    // The creases are the FOLD grid's two inside vertical edges, each cut into n sides.
    EXPECT_EQ(lines[0].elements.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(lines[0].sides_M.size(), static_cast<std::size_t>(n));
    for (const UnfoldingLine& l : lines) {
      EXPECT_EQ(l.name.substr(0, 4), "edge");
      EXPECT_EQ(l.target, 0.0);  // towards flat
      double length = 0;
      for (const auto& s : l.sides_M) {
        EXPECT_NEAR(s[0].x(), s[1].x(), 1e-15);
        length += (s[1] - s[0]).norm();
      }
      EXPECT_NEAR(length, kSide, 1e-15);
    }
    const double x1 = lines[0].sides_M[0][0].x(), x2 = lines[1].sides_M[0][0].x();
    const int first = std::abs(x1 - kSide) < 1e-12 ? 0 : 1;  // the line at x = kSide
    EXPECT_NEAR(first == 0 ? x2 : x1, 2 * kSide, 1e-12);
    // Crease 1 opens from 60 deg at a constant rate to flat at t = 1 s, crease 2 from 90 deg
    // to flat at t = 0.4 s: openings t and min(1, t / 0.4); half open at 0.5 and 0.2 s, 90 %
    // at 0.9 and 0.36 s. Outputs every 0.04 s: 0.5 and 0.9 fall between two.
    const BodyForces f = no_forces(m);
    for (int k = 0; k <= 26; ++k) {
      const double t = 0.04 * k;
      const double phi1 = 60 * kDegToRad * (1 - t),
                   phi2 = 90 * kDegToRad * std::max(0.0, 1 - t / 0.4);
      rec.record(turned(m, t, phi1, phi2), f);
      const std::vector<double>& row = rec.tables()[0].rows.back();
      const double open1 = t, open2 = std::min(1.0, t / 0.4);
      const double start1 = rec.tables()[0].rows.front()[kFirstLineColumn + first];
      EXPECT_NEAR(std::abs(start1), 60, 1e-9);
      EXPECT_NEAR(row[kFirstLineColumn + first] / start1, 1 - t, 1e-12) << t;
      EXPECT_NEAR(row[2], 0.5 * (open1 + open2), 1e-12) << t;
      EXPECT_EQ(row[1], (open1 >= 0.5 - 1e-12) + (open2 >= 0.5 - 1e-12)) << t;
    }
    const std::vector<LineOpening> order = unfolding_order(rec.tables()[0].rows, lines);
    ASSERT_EQ(order.size(), 2u);
    EXPECT_EQ(order[0].name, lines[1 - first].name);  // crease 2 first
    EXPECT_NEAR(order[0].half_open_at, 0.2, 1e-9);
    EXPECT_NEAR(order[0].open_at, 0.36, 1e-9);
    EXPECT_NEAR(std::abs(order[0].start_deg), 90, 1e-9);
    EXPECT_NEAR(order[0].final_opening, 1, 1e-12);
    EXPECT_EQ(order[1].name, lines[first].name);
    EXPECT_NEAR(order[1].half_open_at, 0.5, 1e-9);
    EXPECT_NEAR(order[1].open_at, 0.9, 1e-9);
    EXPECT_NEAR(order[1].final_opening, 1.04, 1e-9);  // past flat at t = 1.04 s
    EXPECT_NEAR(order[1].mid_M.x(), kSide, 1e-12);
    EXPECT_NEAR(order[1].mid_M.y(), kSide / 2, 1e-12);
  }
}

TEST(UnfoldingProbe, TargetsAreTheShapesDihedralAnglesAndUnmovedLinesAreLeftOut) {
  Model m = strip_model(true, 2);
  RunRecorder rec = unfolding_recorder(m, 0);
  const auto& lines = rec.unfolding_lines_of(0);
  ASSERT_EQ(lines.size(), 2u);
  const int first = std::abs(lines[0].sides_M[0][0].x() - kSide) < 1e-12 ? 0 : 1;
  EXPECT_NEAR(std::abs(lines[first].target), 30 * kDegToRad, 1e-12);
  EXPECT_NEAR(lines[1 - first].target, 0, 1e-12);
  // From 60 deg (crease 1) and flat (crease 2) towards the shape: crease 1 at 44 deg has come
  // 16 / 30 of its way; crease 2 starts where the shape has it and is not followed.
  const BodyForces f = no_forces(m);
  rec.record(turned(m, 0, 60 * kDegToRad, 0), f);
  rec.record(turned(m, 1, 44 * kDegToRad, 0.5), f);
  const std::vector<double>& row = rec.tables()[0].rows.back();
  EXPECT_NEAR(row[2], 16.0 / 30, 1e-12);  // the mean over the one followed line
  EXPECT_EQ(row[1], 1);
  const std::vector<LineOpening> order = unfolding_order(rec.tables()[0].rows, lines);
  ASSERT_EQ(order.size(), 1u);
  EXPECT_EQ(order[0].name, lines[first].name);
  EXPECT_NEAR(order[0].half_open_at, 0.5 / (16.0 / 30), 1e-9);
  EXPECT_TRUE(std::isnan(order[0].open_at));
  EXPECT_NEAR(std::abs(order[0].target_deg), 30, 1e-9);
}

TEST(UnfoldingProbe, ScenesNameItAndRefuseItWhereItCannotBe) {
  test::TempDir dir;
  write_fold(dir / "strip.fold", three_faces(true));
  const std::string head = R"(material: {youngs_modulus: 3e9, density: 800}
sheet: {thickness: 1e-4}
pattern: {file: strip.fold, subdivisions: 1, valley_law: {type: linear, stiffness: 1e-3, rest_angle_deg: 0}}
fixtures: {panels: [1]}
probes:
  - )";
  test::spit(dir / "ok.yaml", head + "{name: u, type: unfolding}\n  - " +
                                  "{name: v, type: unfolding, shape: half}\n");
  const Scene s = read_scene(dir / "ok.yaml");
  ASSERT_EQ(s.model.probes.size(), 2u);
  EXPECT_EQ(s.model.probes[0].kind, ProbeKind::Unfolding);
  EXPECT_EQ(s.model.probes[0].shape, -1);
  EXPECT_EQ(s.model.probes[1].shape, 0);
  const auto refused = [&](const std::string& probe, const std::string& field,
                           const std::string& why) {
    test::spit(dir / "bad.yaml", head + probe + "\n");
    try {
      read_scene(dir / "bad.yaml");
      ADD_FAILURE() << probe << " was accepted";
    } catch (const InputError& err) {
      const std::string what = err.what();
      EXPECT_NE(what.find(field), std::string::npos) << what;
      EXPECT_NE(what.find(why), std::string::npos) << what;
    }
  };
  refused("{name: u, type: unfolding, shape: deployed}", "probes[0].shape", "'half'");
  refused("{name: u, type: energy, shape: half}", "probes[0].shape", "shape or unfolding");
  // Its order file is one of its files: no other probe may be called u_order.
  refused("{name: u, type: unfolding}\n  - {name: u_order, type: energy}", "probes[1].name",
          "u_order.csv");
  write_fold(dir / "flat.fold", grid_crease_pattern(2, 1, kSide, kSide));
  test::spit(dir / "flat.yaml", R"(material: {youngs_modulus: 3e9, density: 800}
sheet: {thickness: 1e-4}
pattern: {file: flat.fold, subdivisions: 1}
fixtures: {panels: [1]}
probes: [{name: u, type: unfolding}]
)");
  try {
    read_scene(dir / "flat.yaml");
    ADD_FAILURE() << "an unfolding probe on a sheet without creases was accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("no crease"), std::string::npos) << err.what();
  }
}

}  // namespace unfolding_probe_test
}  // namespace finseg
