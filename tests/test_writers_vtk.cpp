// VTK series writer: the files parse back to the boxes that went in (corner positions from
// the box geometry worked out by hand), the collection lists every frame, nothing partial
// is left behind, and bad input is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "vtk_read_util.hpp"
#include "writer_test_model.hpp"
#include "writers/vtk.hpp"

namespace fs = std::filesystem;
using namespace finseg;

namespace writers_vtk_test {

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string attr(const std::string& xml, const std::string& name) {
  return writer_test::xml_attr(xml, name);
}

/// The values of a DataArray, decoded from the binary appended section.
std::vector<double> data_array(const std::string& xml, const std::string& name) {
  return vtk_read::array(xml, name);
}

Model two_box_model() {
  Model m;
  BodyDef a;
  set_box(a, Vec3(2.0, 1.0, 0.5), 1.0);
  a.panel = 3;
  BodyDef b;
  set_box(b, Vec3(1.0, 1.0, 1.0), 1.0);
  b.fixed = true;
  m.bodies = {a, b};
  return m;
}

TEST(VtkWriter, BoxesParseBackWithHandComputedCorners) {
  const Model m = two_box_model();
  Frame f;
  f.t = 0.25;
  // Body 0 turned 90 deg about world z: its x axis points along world y.
  Mat3 Rz;
  Rz << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  f.p_W = {Vec3(1, 2, 3), Vec3(-5, 0, 0)};
  f.R_WB = {Rz, Mat3::Identity()};
  const writer_test::TempDir tmp("vtk_boxes");
  const fs::path dir = tmp / "out";  // not there yet: the writer creates it
  write_vtk_series(dir.string(), "run", m, {f});

  const std::string vtu = slurp(dir / "run_00000.vtu");
  EXPECT_NE(vtu.find("type=\"UnstructuredGrid\""), std::string::npos);
  EXPECT_EQ(attr(vtu, "NumberOfPoints"), "16");
  EXPECT_EQ(attr(vtu, "NumberOfCells"), "2");
  const std::vector<double> pts = data_array(vtu, "position_m");
  ASSERT_EQ(pts.size(), 48u);
  // Corner 0 of body 0 is (-1, -0.5, -0.25) in B; Rz maps it to (0.5, -1, -0.25).
  EXPECT_NEAR(pts[0], 1.5, 1e-12);
  EXPECT_NEAR(pts[1], 1.0, 1e-12);
  EXPECT_NEAR(pts[2], 2.75, 1e-12);
  // Corner 6 of body 0 is (+1, +0.5, +0.25) in B -> (-0.5, 1, 0.25) + p.
  EXPECT_NEAR(pts[18], 0.5, 1e-12);
  EXPECT_NEAR(pts[19], 3.0, 1e-12);
  EXPECT_NEAR(pts[20], 3.25, 1e-12);
  // Corner 0 of the unit cube at (-5, 0, 0).
  EXPECT_NEAR(pts[24], -5.5, 1e-12);
  EXPECT_NEAR(pts[25], -0.5, 1e-12);
  EXPECT_NEAR(pts[26], -0.5, 1e-12);

  // VTK_HEXAHEDRON ordering: (p1-p0) x (p3-p0) points towards the top face (p4), so
  // ParaView shows the boxes right side out; the triple product is the box volume.
  for (int c = 0; c < 2; ++c) {
    auto P = [&](int k) {
      return Vec3(pts[24 * c + 3 * k], pts[24 * c + 3 * k + 1], pts[24 * c + 3 * k + 2]);
    };
    const double vol = (P(1) - P(0)).cross(P(3) - P(0)).dot(P(4) - P(0));
    EXPECT_NEAR(vol, segment_area(m.bodies[c]) * m.bodies[c].thickness, 1e-12) << "cell " << c;
  }

  const std::vector<double> conn = data_array(vtu, "connectivity");
  ASSERT_EQ(conn.size(), 16u);
  for (int k = 0; k < 16; ++k) EXPECT_EQ(conn[k], k);
  EXPECT_EQ(data_array(vtu, "offsets"), (std::vector<double>{8, 16}));
  EXPECT_EQ(data_array(vtu, "types"), (std::vector<double>{12, 12}));
  EXPECT_EQ(data_array(vtu, "body"), (std::vector<double>{0, 1}));
  EXPECT_EQ(data_array(vtu, "panel"), (std::vector<double>{4, 1}));  // from 1, as in scenes
  EXPECT_EQ(data_array(vtu, "fixed"), (std::vector<double>{0, 1}));
  // No contact points in any frame: no contact files.
  EXPECT_FALSE(fs::exists(dir / "run_contacts.pvd"));
}

TEST(VtkWriter, CollectionListsEveryFrameWithItsTime) {
  const auto s = writer_test::make_zigzag_scene(12);
  const writer_test::TempDir tmp("vtk_series");
  const fs::path dir = tmp.path();
  write_vtk_series(dir.string(), "zig", s.model, s.frames);

  const std::string pvd = slurp(dir / "zig.pvd");
  EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
  std::size_t n = 0;
  for (std::size_t at = pvd.find("<DataSet "); at != std::string::npos;
       at = pvd.find("<DataSet ", at + 1), ++n) {
    ASSERT_LT(n, s.frames.size());
    EXPECT_DOUBLE_EQ(std::stod(writer_test::xml_attr(pvd, "timestep", at)), s.frames[n].t);
    EXPECT_EQ(writer_test::xml_attr(pvd, "part", at), "0");
    const fs::path file = dir / writer_test::xml_attr(pvd, "file", at);
    ASSERT_TRUE(fs::exists(file)) << file;
    const std::string vtu = slurp(file);
    EXPECT_EQ(attr(vtu, "NumberOfCells"), std::to_string(s.model.bodies.size()));
  }
  EXPECT_EQ(n, s.frames.size());

  // Half of the frames have a contact point: a contact series for every frame.
  const std::string cpvd = slurp(dir / "zig_contacts.pvd");
  for (std::size_t f = 0; f < s.frames.size(); ++f) {
    char name[64];
    std::snprintf(name, sizeof name, "zig_contacts_%05zu.vtu", f);
    EXPECT_NE(cpvd.find(name), std::string::npos) << name;
    const std::string vtu = slurp(dir / name);
    EXPECT_EQ(attr(vtu, "NumberOfPoints"), std::to_string(s.frames[f].contact_points_W.size()));
  }
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().string().find(".partial"), std::string::npos) << e.path();
  }
}

TEST(VtkWriter, RefusesFramesThatDoNotFitTheModel) {
  auto s = writer_test::make_zigzag_scene(3);
  s.frames[1].p_W.pop_back();
  const writer_test::TempDir tmp("vtk_bad");
  const fs::path dir = tmp.path();
  EXPECT_THROW(write_vtk_series(dir.string(), "bad", s.model, s.frames), InputError);
  EXPECT_FALSE(fs::exists(dir / "bad.pvd"));
  s = writer_test::make_zigzag_scene(3);
  s.frames[2].R_WB[0](0, 0) = std::nan("");
  EXPECT_THROW(write_vtk_series(dir.string(), "bad", s.model, s.frames), InputError);
}

}  // namespace writers_vtk_test
