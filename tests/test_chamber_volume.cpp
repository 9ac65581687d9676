// Chamber volume by the divergence theorem (docs/pressure.md): closed boxes and an L-shaped
// prism of rectangles against their exact volumes, invariance under rigid motion, the
// pose derivative against finite differences, and open or mis-oriented surfaces refused.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "elements/chamber_volume.hpp"
#include "pressure_test_util.hpp"
#include "solvers/dofs.hpp"

namespace finseg {
namespace chamber_volume_test {

using test::add_plate;

using test::add_box;
using test::kZtoX;
using test::kZtoY;

constexpr double kThick = test::kPlateThickness;

void move_rigidly(State& st, const Mat3& R, const Vec3& t) {
  for (size_t i = 0; i < st.p_W.size(); ++i) {
    st.p_W[i] = R * st.p_W[i] + t;
    st.R_WB[i] = R * st.R_WB[i];
  }
}

TEST(ChamberVolume, BoxOfSixPlates) {
  Model m;
  const auto faces = add_box(m, 0.3, 0.2, 0.7);
  m.finalize_dofs();
  State st = initial_state(m);
  EXPECT_NO_THROW(check_chamber_closed(m, st, faces, "chamber"));
  EXPECT_NEAR(chamber_volume(m, st, faces), 0.3 * 0.2 * 0.7, 1e-16);
  // A cube turned by an arbitrary rotation and moved: same volume to round-off.
  move_rigidly(st, so3_exp(Vec3(0.7, -2.1, 1.3)), Vec3(5, -3, 2));
  EXPECT_NO_THROW(check_chamber_closed(m, st, faces, "chamber"));
  EXPECT_NEAR(chamber_volume(m, st, faces), 0.3 * 0.2 * 0.7, 1e-14);
}

// Cross-section [0,2]x[0,1] u [0,1]x[1,2] in (x, z), extruded over y in [0, 1]: V = 3.
// Not convex, and the long left face meets the two rectangles of each end cap along one
// edge (a T-junction).
TEST(ChamberVolume, LShapedPrismOfTenRectangles) {
  Model m;
  std::vector<ChamberFace> f;
  const auto face = [&](const Vec3& size, const Vec3& p, const Mat3& R, bool plus) {
    f.push_back({add_plate(m, fmt::format("f{}", f.size()), size, p, R), plus});
  };
  const Mat3 I = Mat3::Identity();
  face({2, 1, kThick}, {1, 0.5, 0}, I, false);       // bottom
  face({1, 1, kThick}, {1.5, 0.5, 1}, I, true);      // low top
  face({1, 1, kThick}, {0.5, 0.5, 2}, I, true);      // high top
  face({1, 1, kThick}, {2, 0.5, 0.5}, kZtoX, true);  // right
  face({1, 1, kThick}, {1, 0.5, 1.5}, kZtoX, true);  // step
  face({2, 1, kThick}, {0, 0.5, 1}, kZtoX, false);   // left, full height
  for (const double y : {0.0, 1.0}) {                // end caps, two rectangles each
    face({2, 1, kThick}, {1, y, 0.5}, kZtoY, y > 0);
    face({1, 1, kThick}, {0.5, y, 1.5}, kZtoY, y > 0);
  }
  m.finalize_dofs();
  State st = initial_state(m);
  EXPECT_NO_THROW(check_chamber_closed(m, st, f, "chamber"));
  EXPECT_NEAR(chamber_volume(m, st, f), 3.0, 1e-15);
  move_rigidly(st, so3_exp(Vec3(-0.4, 0.9, 2.5)), Vec3(0.1, 7, -4));
  EXPECT_NO_THROW(check_chamber_closed(m, st, f, "chamber"));
  EXPECT_NEAR(chamber_volume(m, st, f), 3.0, 1e-13);
}

TEST(ChamberVolume, PoseDerivativeMatchesFiniteDifferences) {
  Model m;
  const auto faces = add_box(m, 0.3, 0.2, 0.7);
  m.finalize_dofs();
  State st = initial_state(m);
  move_rigidly(st, so3_exp(Vec3(0.2, 0.5, -0.3)), Vec3(0.4, -0.2, 0.1));
  // Perturb each plate differently so the surface is generic (no longer closed).
  Eigen::VectorXd q(m.num_dofs);
  for (int i = 0; i < m.num_dofs; ++i) q[i] = 0.02 * std::sin(1.7 * i + 0.3);
  apply_pose_increment(m, st, q);
  std::vector<VolumeGradient> grad;
  chamber_volume(m, st, faces, grad);
  ASSERT_EQ(grad.size(), faces.size());
  const double h = 1e-6;
  for (const VolumeGradient& g : grad) {
    for (int c = 0; c < 6; ++c) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(m.num_dofs);
      e[m.dof_of_body[g.body] + c] = h;
      State a = st, b = st;
      apply_pose_increment(m, a, e);
      apply_pose_increment(m, b, -e);
      const double fd = (chamber_volume(m, a, faces) - chamber_volume(m, b, faces)) / (2 * h);
      const double exact = c < 3 ? g.d_dp[c] : g.d_dphi[c - 3];
      EXPECT_NEAR(exact, fd, 1e-6 * (std::abs(fd) + 1e-3)) << "body " << g.body << " dof " << c;
    }
  }
}

void expect_open(const Model& m, const State& st, const std::vector<ChamberFace>& faces,
                 const std::string& field) {
  try {
    check_chamber_closed(m, st, faces, "chamber");
    ADD_FAILURE() << "accepted an open surface";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find("open"), std::string::npos) << e.what();
  }
}

TEST(ChamberVolume, RefusesOpenOrMisorientedSurfaces) {
  Model m;
  auto faces = add_box(m, 0.3, 0.2, 0.7);
  m.finalize_dofs();
  State st = initial_state(m);
  // A missing lid: the first side face's top edge is open.
  std::vector<ChamberFace> no_lid(faces.begin() + 1, faces.end());
  try {
    check_chamber_closed(m, st, no_lid, "chamber");
    ADD_FAILURE() << "accepted a box without lid";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("open"), std::string::npos) << e.what();
  }
  // One face flipped: its edges run the same way as its neighbours'.
  auto flipped = faces;
  flipped[0].outward_plus_z = false;
  expect_open(m, st, flipped, "chamber[0]");
  // One plate moved off its place by 1 mm.
  st.p_W[faces[2].body].x() += 1e-3;
  expect_open(m, st, faces, "chamber[0]");
}

}  // namespace chamber_volume_test
}  // namespace finseg
