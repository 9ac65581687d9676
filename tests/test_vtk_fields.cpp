// VTK point and cell data, read back from the binary appended, zlib-compressed files with
// an independent decoder (vtk_read_util.hpp) and checked against closed forms: corner
// displacements and velocities of a moved rigid box, the loads of a crease element turned
// and stretched by known amounts, contact arrays, the block format, and mode shapes.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "core/error.hpp"
#include "core/so3.hpp"
#include "elements/assemble.hpp"
#include "elements/crease_law.hpp"
#include "probes/recorder.hpp"
#include "solvers/modes.hpp"
#include "vtk_read_util.hpp"
#include "writer_test_model.hpp"
#include "writers/frame_check.hpp"
#include "writers/vtk.hpp"
#include "writers/vtk_appended.hpp"

namespace finseg {
namespace vtk_fields_test {

namespace fs = std::filesystem;

BodyDef box(const Vec3& size, const Vec3& p0) {
  BodyDef b;
  set_box(b, size, 2e-3);
  b.p0_W = p0;
  return b;
}

std::string frame_file(const fs::path& dir) {
  return vtk_read::slurp(dir / "f_00000.vtu");
}

TEST(VtkFields, DisplacementAndVelocityOfAMovedBox) {
  Model m;
  m.bodies = {box(Vec3(0.04, 0.02, 0.001), Vec3(0.1, 0.2, 0.3))};
  m.bodies[0].R0_WB = so3_exp<double>(Vec3(0.3, 0, 0));
  const Vec3 shift(0.01, -0.02, 0.005), v(1, 2, 3), w(-0.5, 0.25, 2);
  const Mat3 R = so3_exp<double>(Vec3(0.1, -0.7, 0.4));
  Frame f;
  f.p_W = {m.bodies[0].p0_W + shift};
  f.R_WB = {m.bodies[0].R0_WB};  // a pure translation first
  f.v_W = {v};
  f.w_W = {w};
  const writer_test::TempDir tmp("vtk_fields_move");
  write_vtk_series(tmp.path().string(), "f", m, {f});
  std::string vtu = frame_file(tmp.path());
  int comps = 0;
  const std::vector<double> u = vtk_read::array(vtu, "displacement_m", &comps);
  EXPECT_EQ(comps, 3);
  ASSERT_EQ(u.size(), 24u);
  for (int k = 0; k < 24; ++k) EXPECT_NEAR(u[k], shift[k % 3], 1e-15) << k;

  // Turned as well: each corner moves from p0 + R0 c to p + R c, and moves at v + w x R c.
  f.R_WB = {R};
  write_vtk_series(tmp.path().string(), "f", m, {f});
  vtu = frame_file(tmp.path());
  const std::vector<double> u2 = vtk_read::array(vtu, "displacement_m");
  const std::vector<double> vel = vtk_read::array(vtu, "velocity_m_s");
  const std::vector<Vec3> c0 =
      prism_corners_W(m.bodies[0].outline_B, m.bodies[0].thickness, Vec3::Zero(), Mat3::Identity());
  ASSERT_EQ(vel.size(), 24u);
  for (int c = 0; c < 8; ++c) {
    const Vec3 exp_u = f.p_W[0] + R * c0[c] - (m.bodies[0].p0_W + m.bodies[0].R0_WB * c0[c]);
    const Vec3 exp_v = v + w.cross(R * c0[c]);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(u2[3 * c + i], exp_u[i], 1e-15);
      EXPECT_NEAR(vel[3 * c + i], exp_v[i], 1e-14);
    }
  }
}

// Body 1 hinged to the fixed body 0 by a linear crease (stiffness k, rest 0) at their common
// edge; turned by beta about that edge and shifted by d: the element's spring force is K d,
// its moment about P+ the crease moment k beta, the opening angle 180 - beta.
TEST(VtkFields, SegmentArraysOfATurnedAndStretchedCrease) {
  const double a = 0.02, k = 3e-3, beta = 0.4;
  const Vec3 d(1e-4, -2e-4, 3e-4);
  Model m;
  m.bodies = {box(Vec3(a, 0.01, 1e-4), Vec3(-a / 2, 0, 0)),
              box(Vec3(a, 0.01, 1e-4), Vec3(a / 2, 0, 0))};
  m.bodies[0].fixed = true;
  ElementDef e;
  e.outer = 0;
  e.inner = 1;
  e.c_outer_B = Vec3(a / 2, 0, 0);
  e.c_inner_B = Vec3(-a / 2, 0, 0);
  e.K << 10, 20, 30, 1, 0, 1;
  e.crease = 0;
  m.elements = {e};
  m.creases.push_back({std::make_shared<LinearCreaseLaw>(k, 0.0), 0.0});
  m.finalize_dofs();
  State s = initial_state(m);
  const Mat3 R = so3_exp<double>(Vec3(0, beta, 0));
  s.R_WB[1] = R;
  s.p_W[1] = d + R * Vec3(a / 2, 0, 0);
  BodyForces forces;
  compute_forces(m, s, forces);

  SolverSettings set;
  set.kind = SolverKind::Static;
  RunRecorder rec(m, set, {true, false, {}});
  rec.record(s, forces);
  const writer_test::TempDir tmp("vtk_fields_crease");
  write_vtk_series(tmp.path().string(), "f", m, rec.frames());
  const std::string vtu = frame_file(tmp.path());

  const std::vector<double> F = vtk_read::array(vtu, "force_N");
  const std::vector<double> M = vtk_read::array(vtu, "moment_Nm");
  ASSERT_EQ(F.size(), 6u);
  for (int b = 0; b < 2; ++b) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_DOUBLE_EQ(F[3 * b + i], forces.f_W[b][i]);
      EXPECT_DOUBLE_EQ(M[3 * b + i], forces.tau_W[b][i]);
    }
  }
  const double spring = Vec3(10 * d.x(), 20 * d.y(), 30 * d.z()).norm();
  for (double x : vtk_read::array(vtu, "element_force_N")) EXPECT_NEAR(x, spring, 1e-12);
  for (double x : vtk_read::array(vtu, "element_moment_Nm")) EXPECT_NEAR(x, k * beta, 1e-12);
  for (double x : vtk_read::array(vtu, "crease_opening_deg")) {
    EXPECT_NEAR(x, 180 - beta / kDegToRad, 1e-10);
  }
  for (double x : vtk_read::array(vtu, "crease_moment_Nm")) EXPECT_NEAR(x, k * beta, 1e-14);
  EXPECT_EQ(vtk_read::array(vtu, "contact_normal_N"), (std::vector<double>{0, 0}));
  EXPECT_EQ(vtk_read::array(vtu, "panel").size(), 2u);
}

TEST(VtkFields, ContactArraysPerSegmentAndPerPoint) {
  Model m;
  m.bodies = {box(Vec3(0.02, 0.01, 1e-4), Vec3::Zero()), box(Vec3(0.04, 0.01, 1e-4), Vec3::Zero())};
  Frame f;
  f.p_W = {Vec3::Zero(), Vec3::Zero()};
  f.R_WB = {Mat3::Identity(), Mat3::Identity()};
  SegmentFields& s = f.segments;
  s.force_W = s.moment_W = {Vec3::Zero(), Vec3::Zero()};
  s.element_force = s.element_moment = {0, 0};
  s.crease_opening = s.crease_moment = {NAN, NAN};
  s.contact_normal = {0.5, 0.5};
  s.contact_friction = {0.1, 0.1};
  f.contact_points_W = {Vec3(1, 2, 3), Vec3(4, 5, 6)};
  f.contact_normal = {0.2, 0.3};
  f.contact_penetration = {1e-6, 2e-6};
  f.contact_friction = {0.04, 0.06};
  const writer_test::TempDir tmp("vtk_fields_contact");
  write_vtk_series(tmp.path().string(), "f", m, {f});
  const std::string vtu = frame_file(tmp.path());
  const std::vector<double> p = vtk_read::array(vtu, "contact_pressure_Pa");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_DOUBLE_EQ(p[0], 0.5 / (0.02 * 0.01));
  EXPECT_DOUBLE_EQ(p[1], 0.5 / (0.04 * 0.01));
  EXPECT_TRUE(std::isnan(vtk_read::array(vtu, "crease_opening_deg")[0]));
  const std::string c = vtk_read::slurp(tmp / "f_contacts_00000.vtu");
  EXPECT_EQ(vtk_read::array(c, "position_m"), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(vtk_read::array(c, "normal_force_N"), f.contact_normal);
  EXPECT_EQ(vtk_read::array(c, "penetration_m"), f.contact_penetration);
  EXPECT_EQ(vtk_read::array(c, "friction_force_N"), f.contact_friction);

  f.contact_friction.pop_back();  // arrays that do not match the points are refused
  EXPECT_THROW(write_vtk_series(tmp.path().string(), "g", m, {f}), InputError);
}

// VTK's block header: [blocks, block size, partial last size or 0, compressed sizes...].
TEST(VtkFields, ZlibBlocksFollowVtkHeaderLayout) {
  std::string bytes(1050, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 7) % 251);
  const std::string z = vtk_zlib_block(bytes, 100);
  std::uint64_t h[3];
  std::memcpy(h, z.data(), sizeof h);
  EXPECT_EQ(h[0], 11u);
  EXPECT_EQ(h[1], 100u);
  EXPECT_EQ(h[2], 50u);
  EXPECT_EQ(vtk_read::inflate_blocks(z.data()), bytes);
  const std::string full = vtk_zlib_block(bytes.substr(0, 1000), 100);
  std::memcpy(h, full.data(), sizeof h);
  EXPECT_EQ(h[0], 10u);
  EXPECT_EQ(h[2], 0u);  // the last block is full
  EXPECT_EQ(vtk_read::inflate_blocks(full.data()), bytes.substr(0, 1000));
  const std::string none = vtk_zlib_block("", 100);
  std::memcpy(h, none.data(), sizeof h);
  EXPECT_EQ(h[0], 0u);
  EXPECT_EQ(none.size(), 24u);
}

// One free box on a spring in z much softer than every other direction: mode 1 is the
// translation along z at sqrt(kz/m) / 2 pi, so every corner's mode_shape is (0, 0, 1).
TEST(VtkFields, ModeShapeOfABoxOnASoftSpring) {
  Model m;
  m.bodies = {box(Vec3(0.02, 0.02, 0.02), Vec3::Zero()), box(Vec3(0.02, 0.02, 0.02), Vec3::Zero())};
  m.bodies[0].fixed = true;
  ElementDef e;
  e.outer = 0;
  e.inner = 1;
  e.K << 1e4, 1e4, 1.0, 1e3, 1e3, 1e3;
  m.elements = {e};
  m.finalize_dofs();
  const State s = initial_state(m);
  const std::vector<Mode> modes = natural_modes(m, s, 2);
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_NEAR(modes[0].frequency_hz, std::sqrt(1.0 / 2e-3) / (2 * kPi), 1e-9);
  const ModeShape shape = mode_shape(m, s, modes[0]);
  const writer_test::TempDir tmp("vtk_fields_modes");
  write_vtk_modes(tmp.path().string(), "modes", m,
                  Frame{0, s.p_W, s.R_WB, {}, {}, {}, {}, {}, {}, {}},
                  {shape, mode_shape(m, s, modes[1])});
  const std::string vtu = vtk_read::slurp(tmp / "modes_00001.vtu");
  const std::vector<double> u = vtk_read::array(vtu, "mode_shape");
  ASSERT_EQ(u.size(), 48u);
  for (int c = 0; c < 8; ++c) {  // the fixed box does not move
    EXPECT_EQ(u[3 * c + 2], 0.0);
    EXPECT_NEAR(u[24 + 3 * c + 0], 0, 1e-9);
    EXPECT_NEAR(u[24 + 3 * c + 1], 0, 1e-9);
    EXPECT_NEAR(u[24 + 3 * c + 2], 1, 1e-9);
  }
  const std::string pvd = vtk_read::slurp(tmp / "modes.pvd");
  EXPECT_NE(pvd.find("timestep=\"2\" part=\"0\" file=\"modes_00002.vtu\""), std::string::npos);
}

}  // namespace vtk_fields_test
}  // namespace finseg
