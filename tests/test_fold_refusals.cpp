// Each refusal rule of docs/fold.md: one small hand-written bad file, the message must name
// the file, the field with the index, and the reason.
#include "pattern_test_util.hpp"

namespace finseg::test {
namespace fold_refusals_test {

using nlohmann::json;

class FoldRefusal : public ::testing::Test {
 protected:
  TempDir dir;
  json f = two_squares();
  void refused(const std::string& field, const std::string& why, std::optional<double> u = {}) {
    expect_refused(dir, f, field, why, u);
  }
};

TEST_F(FoldRefusal, BaseFileIsAccepted) {
  spit(dir / "good.fold", f.dump());
  const CreasePattern p = read_fold(dir / "good.fold");
  EXPECT_EQ(p.edges[6].faces[0], 0);  // 1 -> 4 runs counter-clockwise around face 0
  EXPECT_EQ(p.edges[6].faces[1], 1);
  EXPECT_NEAR(p.vertices_flat_m[2].x(), 2e-3, 1e-18);
}

TEST_F(FoldRefusal, MissingRequiredFields) {
  f.erase("vertices_coords");
  refused("vertices_coords", "required");
  f = two_squares();
  f.erase("faces_vertices");
  refused("faces_vertices", "required");
}

TEST_F(FoldRefusal, WrongTypes) {
  f["vertices_coords"] = "abc";
  refused("vertices_coords", "must be an array");
  f = two_squares();
  f["vertices_coords"][3] = json::array({2, "1"});
  refused("vertices_coords[3]", "must be a number");
  f = two_squares();
  f["faces_vertices"][1] = "x";
  refused("faces_vertices[1]", "array of vertex indices");
  f = two_squares();
  f["faces_vertices"][0][2] = 4.5;
  refused("faces_vertices[0]", "not a vertex index");
  f = two_squares();
  f["edges_vertices"][2] = json::array({2});
  refused("edges_vertices[2]", "pair");
  f = two_squares();
  f["frame_unit"] = 3;
  refused("frame_unit", "must be a string");
}

TEST_F(FoldRefusal, InvalidJsonAndNumbersBeyondDouble) {
  spit(dir / "bad.fold", "{\"vertices_coords\": [[0, 0], ");
  EXPECT_THROW(read_fold(dir / "bad.fold"), InputError);
  spit(dir / "bad.fold", R"({"frame_unit": "m", "vertices_coords": [[1e999, 0]]})");
  try {
    read_fold(dir / "bad.fold");
    ADD_FAILURE() << "1e999 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "json");
    EXPECT_NE(std::string(e.what()).find("overflow"), std::string::npos) << e.what();
  }
}

TEST_F(FoldRefusal, MixedDimensions) {
  f["vertices_coords"][2] = json::array({2, 0, 0});
  refused("vertices_coords[2]", "mixed 2-D/3-D");
}

TEST_F(FoldRefusal, IndicesOutOfRange) {
  f["faces_vertices"][1][2] = 9;
  f["edges_vertices"][2] = json::array({2, 9});
  refused("faces_vertices[1]", "vertex 9 out of range 0..5");
  f = two_squares();
  f["edges_vertices"][6] = json::array({1, 6});
  refused("edges_vertices[6]", "vertex 6 out of range");
  f = two_squares();
  f["edges_vertices"][6] = json::array({4, 4});
  refused("edges_vertices[6]", "both ends are vertex 4");
  f = two_squares();
  f["faces_vertices"] = json::array();
  refused("faces_vertices", "no faces");
}

TEST_F(FoldRefusal, DegenerateFaceLoops) {
  f["faces_vertices"][0] = json::array({0, 1});
  refused("faces_vertices[0]", "2 vertices; a face needs at least 3");
  f = two_squares();
  f["faces_vertices"][0] = json::array({0, 1, 4, 1});
  refused("faces_vertices[0]", "vertex 1 appears twice");
}

TEST_F(FoldRefusal, NonPlanarFoldedFace) {
  // Folded 90 degrees about the crease, then vertex 3 lifted out of face 1's plane.
  json coords = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}, {0, 1, 0}};
  f["file_frames"] = {{{"frame_classes", {"foldedForm"}}, {"vertices_coords", coords}}};
  spit(dir / "good.fold", f.dump());
  EXPECT_NO_THROW(read_fold(dir / "good.fold"));
  f["file_frames"][0]["vertices_coords"][3] = json::array({1.01, 1, 1});
  refused("faces_vertices[1]", "not planar when folded");
}

TEST_F(FoldRefusal, NonConvexFace) {
  f["vertices_coords"][4] = json::array({0.4, 0.4});
  refused("faces_vertices[0]", "not convex at vertex 4");
  const json spike = {{"frame_unit", "m"},
                      {"vertices_coords", {{0, 0}, {2, 0}, {1, 0}, {1, 1}}},
                      {"faces_vertices", {{0, 1, 2, 3}}}};
  expect_refused(dir, spike, "faces_vertices[0]", "not convex at vertex 1");
  const json star = {{"frame_unit", "m"},
                     {"vertices_coords", {{0, 0}, {2, 0}, {0.5, 1.5}, {1, -0.5}, {1.5, 1.5}}},
                     {"faces_vertices", {{0, 1, 2, 3, 4}}}};
  expect_refused(dir, star, "faces_vertices[0]", "winds around more than once");
}

TEST_F(FoldRefusal, ZeroAreaAndClockwiseFaces) {
  const json sliver = {{"frame_unit", "m"},
                       {"vertices_coords", {{0, 0}, {1, 0}, {2, 0}}},
                       {"faces_vertices", {{0, 1, 2}}}};
  expect_refused(dir, sliver, "faces_vertices[0]", "zero area");
  const json clockwise = {{"frame_unit", "m"},
                          {"vertices_coords", {{0, 0}, {1, 0}, {0, 1}}},
                          {"faces_vertices", {{0, 2, 1}}}};
  expect_refused(dir, clockwise, "faces_vertices[0]", "clockwise");
  f["faces_vertices"][1] = json::array({4, 3, 2, 1});  // flipped next to a CCW face
  refused("edges_vertices[6]", "faces 0 and 1 both run it 1 -> 4");
}

TEST_F(FoldRefusal, DanglingEdge) {
  f["vertices_coords"].push_back(json::array({3, 0}));
  f["edges_vertices"].push_back(json::array({2, 6}));
  f["edges_assignment"].push_back("B");
  f["edges_foldAngle"].push_back(0);
  refused("edges_vertices[7]", "dangling");
}

TEST_F(FoldRefusal, NonManifoldEdge) {
  f["vertices_coords"].push_back(json::array({1, 2}));
  f["faces_vertices"].push_back(json::array({4, 1, 6}));
  for (const json& e : {json::array({1, 6}), json::array({6, 4})}) {
    f["edges_vertices"].push_back(e);
    f["edges_assignment"].push_back("B");
    f["edges_foldAngle"].push_back(0);
  }
  refused("edges_vertices[6]", "more than two faces");
}

TEST_F(FoldRefusal, FaceSideThatIsNoEdge) {
  f["edges_vertices"][6] = json::array({0, 4});
  refused("faces_vertices[0]", "side 1 -> 4 is not an edge");
}

TEST_F(FoldRefusal, DuplicateEdge) {
  f["edges_vertices"].push_back(json::array({4, 1}));
  f["edges_assignment"].push_back("V");
  f["edges_foldAngle"].push_back(90);
  refused("edges_vertices[7]", "as edge 6 does already");
}

TEST_F(FoldRefusal, AssignmentAgainstAdjacency) {
  f["edges_assignment"][0] = "M";
  f["edges_foldAngle"][0] = -10;
  refused("edges_assignment[0]", "'M' (a crease) on the sheet's boundary");
  f = two_squares();
  f["edges_assignment"][6] = "B";
  f["edges_foldAngle"][6] = 0;
  refused("edges_assignment[6]", "'B' between two faces");
  f = two_squares();
  f["edges_assignment"][3] = "J";
  refused("edges_assignment[3]", "'J' (join) needs a face on each side");
  for (const char* allowed : {"C", "J", "F", "U"}) {  // interior letters with angle 0
    f = two_squares();
    f["edges_assignment"][6] = allowed;
    f["edges_foldAngle"][6] = 0;
    spit(dir / "good.fold", f.dump());
    EXPECT_NO_THROW(read_fold(dir / "good.fold")) << allowed;
  }
}

TEST_F(FoldRefusal, UnknownAssignmentLetter) {
  f["edges_assignment"][2] = "X";
  refused("edges_assignment[2]", "'X'; allowed: M, V, F, B, U, C, J");
  f = two_squares();
  f["edges_assignment"][6] = "MV";
  refused("edges_assignment[6]", "'MV'");
  f = two_squares();
  f["edges_assignment"].erase(6);
  refused("edges_assignment", "6 entries; edges_vertices has 7");
}

TEST_F(FoldRefusal, FoldAngleSignAgainstAssignment) {
  f["edges_foldAngle"][6] = -90;
  refused("edges_foldAngle[6]", "-90 deg on 'V'; must be >= 0");
  f = two_squares();
  f["edges_assignment"][6] = "M";
  refused("edges_foldAngle[6]", "90 deg on 'M'; must be <= 0");
  f = two_squares();
  f["edges_foldAngle"][1] = 5;
  refused("edges_foldAngle[1]", "5 deg on 'B'; must be 0");
  f = two_squares();
  f["edges_foldAngle"][6] = 190;
  refused("edges_foldAngle[6]", "allowed range [-180, 180]");
  f = two_squares();
  f["edges_assignment"][6] = "U";  // unknown direction: any sign
  f["edges_foldAngle"][6] = -30;
  spit(dir / "good.fold", f.dump());
  EXPECT_NO_THROW(read_fold(dir / "good.fold"));
}

TEST_F(FoldRefusal, Units) {
  f["frame_unit"] = "furlong";
  refused("frame_unit", "'furlong' unknown");
  f.erase("frame_unit");
  refused("frame_unit", "absent or \"unit\"");
  f["frame_unit"] = "unit";
  refused("frame_unit", "absent or \"unit\"");
  spit(dir / "good.fold", f.dump());
  EXPECT_NEAR(read_fold(dir / "good.fold", 0.25).vertices_flat_m[3].x(), 0.5, 1e-16);
  f["frame_unit"] = "in";
  refused("frame_unit", "'in' but the unit given with the file is 0.001 m", 1e-3);
}

TEST_F(FoldRefusal, UnsupportedVersion) {
  f["file_spec"] = 2;
  refused("file_spec", "finseg reads FOLD version 1.x");
}

TEST_F(FoldRefusal, KeyFrameMustBeTheFlatPattern) {
  f["frame_classes"] = {"foldedForm"};
  refused("frame_classes", "the key frame is a folded form");
  f = two_squares();
  for (json& v : f["vertices_coords"]) v.push_back(0);
  spit(dir / "good.fold", f.dump());
  EXPECT_NO_THROW(read_fold(dir / "good.fold"));  // 3-D with z = 0 is flat
  f["vertices_coords"][2][2] = 0.5;
  refused("vertices_coords[2]", "z != 0");
}

TEST_F(FoldRefusal, FoldedFrameOnAnotherMesh) {
  const json coords = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}, {0, 1, 0}};
  f["file_frames"] = {{{"frame_classes", {"foldedForm"}}, {"vertices_coords", coords}}};
  f["file_frames"][0]["faces_vertices"] = {{0, 1, 4, 5}};
  refused("file_frames[0].faces_vertices", "differs from the key frame's");
  f["file_frames"][0].erase("faces_vertices");
  f["file_frames"][0]["vertices_coords"].erase(5);
  refused("vertices_coords", "folded frame has 5 vertices, the crease pattern 6");
}

TEST_F(FoldRefusal, FurtherFoldedFramesNeedTheirVerticesAndDistinctTitles) {
  const json coords = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}, {0, 1, 0}};
  const json frame = {{"frame_classes", {"foldedForm"}}, {"vertices_coords", coords}};
  json titled = frame;
  titled["frame_title"] = "deployed";
  f["file_frames"] = {frame, titled, titled};
  refused("file_frames[2].frame_title", "'deployed' is the title of an earlier folded frame");
  f["file_frames"][2].erase("frame_title");  // untitled: named by its place
  f["file_frames"][2]["vertices_coords"].erase(5);
  refused("vertices_coords", "folded frame 'file_frames[2]' has 5 vertices, the crease pattern 6");
}

TEST_F(FoldRefusal, EdgeDataWithoutEdges) {
  f.erase("edges_vertices");
  refused("edges_assignment", "given without edges_vertices");
}

TEST_F(FoldRefusal, CrossingEdges) {
  // Two triangles that overlap: the second one's side 3 passes through vertex 1, side 5
  // crosses side 0.
  const json crossing = {{"frame_unit", "m"},
                         {"vertices_coords", {{0, 0}, {2, 0}, {0, 2}, {1, -1}, {3, 1}, {1, 1}}},
                         {"faces_vertices", {{0, 1, 2}, {3, 4, 5}}}};
  expect_refused(dir, crossing, "edges_vertices[3]", "crosses or overlaps edge 0");
}

}  // namespace fold_refusals_test
}  // namespace finseg::test
