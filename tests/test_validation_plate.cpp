// Plates cut from crease patterns against Kirchhoff plate theory: a square plate under
// uniform pressure, simply supported and clamped, centre deflection against the classical
// coefficients w = alpha q a^4 / D (simply supported: Navier's series, alpha = 0.00406235;
// clamped: alpha = 0.00126532, Taylor and Govindjee 2004; both independent of nu for given
// D), within 1 % with the error shrinking under refinement. The plate is the middle face of
// a pattern whose four side strips are clamped; its sides to them are plate joints
// (clamped) or creases of zero stiffness (hinges: simply supported).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "elements/crease_law.hpp"
#include "generators/pattern_sheet.hpp"
#include "generators/sheet.hpp"
#include "patterns/fold_format.hpp"
#include "patterns/segment_mesh.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/solver.hpp"
#include "test_paths.hpp"

namespace finseg {
namespace validation_plate_test {

constexpr double kA = 0.1, kT = 1e-3, kE = 1e9, kNu = 0.3, kRho = 1000;
constexpr double kD = kE * kT * kT * kT / (12 * (1 - kNu * kNu));
constexpr double kQ = 1e-2 * kT * kD / (0.004 * kA * kA * kA * kA);  // w about t / 100: linear

// The square [0, a]^2 (face 0) and four clamped strips of width a/4 around it.
CreasePattern framed_square(EdgeAssignment support) {
  const double a = kA, b = kA / 4;
  CreasePattern p;
  p.vertices_flat_m = {{0, 0},     {a, 0},     {a, a},     {0, a},     {0, -b}, {a, -b},
                       {a + b, 0}, {a + b, a}, {a, a + b}, {0, a + b}, {-b, a}, {-b, 0}};
  p.faces = {{0, 1, 2, 3}, {4, 5, 1, 0}, {1, 6, 7, 2}, {3, 2, 8, 9}, {11, 0, 3, 10}};
  p.edges = edges_from_faces(p.faces);
  for (PatternEdge& e : p.edges) {
    if (e.assignment == EdgeAssignment::Flat) e.assignment = support;
  }
  derive_edge_faces(p, "<plate>");
  return p;
}

struct PlateResult {
  double alpha = 0;  // w_centre D / (q a^4)
  std::string status;
};

PlateResult centre_deflection(const Model& m);

// Centre deflection coefficient with n x n cells on the plate (n odd: a cell at the centre).
PlateResult square_plate(EdgeAssignment support, int n) {
  PatternSheetSpec spec;
  spec.thickness = kT;
  spec.youngs_modulus = kE;
  spec.poisson_ratio = kNu;
  spec.density = kRho;
  spec.subdivisions = n;
  spec.fixed_faces = {1, 2, 3, 4};
  spec.mountain_law = std::make_shared<LinearCreaseLaw>(0.0, 0.0);  // a hinge
  Model m = build_pattern_model(framed_square(support), spec);
  PressureDef load;
  load.name = "q";
  for (std::size_t b = 0; b < m.bodies.size(); ++b) {
    if (m.bodies[b].panel == 0) load.bodies.push_back(static_cast<int>(b));
  }
  load.pressure = kQ;  // on +z: pushes towards -z
  m.pressures = {load};
  return centre_deflection(m);
}

PlateResult centre_deflection(const Model& m) {
  State s = initial_state(m);
  SolverSettings set;
  set.kind = SolverKind::Static;
  const SolverStats st = run_solver(m, s, set, nullptr);
  const MaterialPoint c = locate_material_point(m, kA / 2, kA / 2);
  const double w = -(s.p_W[c.body] + s.R_WB[c.body] * c.r_B).z();
  return {w * kD / (kQ * kA * kA * kA * kA), st.status};
}

void expect_converges(EdgeAssignment support, double alpha, std::vector<int> ns) {
  double last = 1;
  for (int n : ns) {
    const PlateResult r = square_plate(support, n);
    ASSERT_EQ(r.status, "ok") << n;
    const double err = std::abs(r.alpha / alpha - 1);
    EXPECT_LT(err, 0.7 * last) << "n = " << n << ": alpha " << r.alpha;
    last = err;
    ::testing::Test::RecordProperty(fmt::format("n{}_rel_error", n), fmt::format("{:.3e}", err));
  }
  EXPECT_LT(last, 0.01);
}

TEST(PlateValidation, SimplySupportedSquarePlateUnderUniformPressure) {
  expect_converges(EdgeAssignment::Mountain, 0.00406235, {5, 9, 17});
}

TEST(PlateValidation, ClampedSquarePlateUnderUniformPressure) {
  expect_converges(EdgeAssignment::Join, 0.00126532, {15, 31, 63});
}

// The same plate from a FOLD file through a scene: the same deflection to round-off.
TEST(PlateValidation, TheSamePlateReadFromAFoldFileThroughASceneGivesTheSameAnswer) {
  const test::TempDir dir;
  write_fold((dir.path() / "plate.fold").string(), framed_square(EdgeAssignment::Mountain));
  const std::string yaml = fmt::format(
      "material: {{youngs_modulus: {}, poisson_ratio: {}, density: {}}}\n"
      "sheet: {{thickness: {}}}\n"
      "pattern: {{file: plate.fold, subdivisions: 5, mountain_law: {{type: linear, "
      "stiffness: 0, rest_angle_deg: 0}}}}\n"
      "fixtures: {{panels: [2, 3, 4, 5]}}\n"
      "pressures: [{{panels: [1], side: +z, pressure: {}}}]\n"
      "solver: {{type: static}}\n",
      kE, kNu, kRho, kT, kQ);
  const Scene scene = parse_scene(yaml, (dir.path() / "plate.yaml").string());
  EXPECT_EQ(scene.pattern_file, (dir.path() / "plate.fold").string());
  const PlateResult from_scene = centre_deflection(scene.model);
  const PlateResult from_api = square_plate(EdgeAssignment::Mountain, 5);
  ASSERT_EQ(from_scene.status, "ok");
  EXPECT_NEAR(from_scene.alpha / from_api.alpha, 1, 1e-12);
  // A pattern with mountain creases and no law for them is refused, naming the scene key.
  const std::string no_law = yaml.substr(0, yaml.find("pattern:")) +
                             "pattern: {file: plate.fold}\n" + yaml.substr(yaml.find("fixtures:"));
  try {
    parse_scene(no_law, (dir.path() / "plate.yaml").string());
    ADD_FAILURE() << "no crease law accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pattern.mountain_law"), std::string::npos) << e.what();
  }
  EXPECT_THROW(
      parse_scene(yaml + "discretisation: {segments: 4}\n", (dir.path() / "plate.yaml").string()),
      InputError);
}

// examples/plate: the README's simply supported plate, 2.5 Pa: Navier's series gives the
// centre 0.00406235 q a^4 / D down.
TEST(PlateValidation, ExamplePlateSceneMatchesNavier) {
  const Scene scene = read_scene(std::string(FINSEG_SOURCE_DIR) + "/examples/plate/plate.yaml");
  State s = initial_state(scene.model);
  const SolverStats st = run_solver(scene.model, s, scene.solver, nullptr);
  ASSERT_EQ(st.status, "ok") << st.message;
  const MaterialPoint c = locate_material_point(scene.model, 0.05, 0.05);
  const double w = -(s.p_W[c.body] + s.R_WB[c.body] * c.r_B).z();
  const double D = 1e9 * 1e-9 / (12 * (1 - 0.09));
  EXPECT_NEAR(w / (0.00406235 * 2.5 * 1e-4 / D), 1, 2e-3) << w;
}

}  // namespace validation_plate_test
}  // namespace finseg
