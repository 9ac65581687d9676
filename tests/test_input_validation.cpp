// Regression tests for inputs that used to give silent wrong results, hangs or crashes
// (issue 14, items 3 and 6): every one must now be refused where it enters, with the file,
// the scene field and the allowed range, or stop the run with a diagnosis.
#include <gtest/gtest.h>

#include <Eigen/SparseCore>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "cli_test_util.hpp"
#include "comparison/compare.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
#include "elements/crease_laws/crease_data.hpp"
#include "generators/sheet.hpp"
#include "identification/bending.hpp"
#include "identification/crease.hpp"
#include "scene/scene_parts.hpp"
#include "scene/scene_reader.hpp"
#include "solvers/linear_solve.hpp"
#include "solvers/solver.hpp"
#include "solvers/step_limits.hpp"

namespace finseg {
namespace input_validation_test {

// A small general sheet: a cantilever of 4 segments under a tip load.
const char* kSheet = R"(material:
  youngs_modulus: 4.0e9
  density: 800
sheet:
  length: 0.1
  width: 0.02
  thickness: 0.0001
discretisation:
  segments: 4
fixtures:
  clamp_start: true
loads:
  - {at: {s: 0.1, y: 0.01}, force: [0, 0, -0.001]}
probes:
  - {name: tip, type: point, at: {s: 0.1, y: 0.01}}
solver:
  type: static
)";

// A zigzag strip of 6 panels, 1 segment per panel (fast to build).
const char* kZigzag = R"(material: {youngs_modulus: 4.0e9, density: 800}
sheet: {length: 0.48, width: 0.04, thickness: 0.0001}
discretisation: {segments: 1}
zigzag: {panels: 6, fold_angle_deg: 80}
)";

std::string replaced(std::string text, const std::string& what, const std::string& with) {
  const auto at = text.find(what);
  EXPECT_NE(at, std::string::npos) << what;
  if (at != std::string::npos) text.replace(at, what.size(), with);
  return text;
}

// Expects parse_scene(yaml) to throw InputError on `field` with `part` in the message.
void expect_refused(const std::string& yaml, const std::string& field, const std::string& part) {
  try {
    parse_scene(yaml, "s.yaml");
    ADD_FAILURE() << "accepted:\n" << yaml;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "s.yaml") << e.what();
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

std::string bom_crlf(const std::string& text) {
  std::string out = "\xEF\xBB\xBF";
  for (char c : text) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
  return out;
}

std::string cr_only(const std::string& text) {
  std::string out = text;
  for (char& c : out) c = c == '\n' ? '\r' : c;
  return out;
}

TEST(TextNormalize, BomCrlfAndCrBecomeLf) {
  EXPECT_EQ(normalize_text("\xEF\xBB\xBF"
                           "a,b\r\n1,2\r\n"),
            "a,b\n1,2\n");
  EXPECT_EQ(normalize_text("a\rb\r\rc"), "a\nb\n\nc");
  EXPECT_EQ(normalize_text("a\r\n\r\nb\n"), "a\n\nb\n");
  EXPECT_EQ(normalize_text("x\xEF\xBB\xBF"), "x\xEF\xBB\xBF");  // only a leading BOM
}

// Scene YAML: the same scene saved with BOM + CRLF, or with CR line ends, reads the same.
TEST(TextNormalize, SceneFileWithBomAndCrlf) {
  const test::TempDir dir;
  for (const std::string& text : {bom_crlf(kSheet), cr_only(kSheet)}) {
    test::spit(dir / "s.yaml", text);
    const Scene s = read_scene(dir / "s.yaml");
    EXPECT_EQ(s.model.bodies.size(), 5u);  // 4 segments + the clamp
    EXPECT_EQ(s.model.sheet.thickness, 1e-4);
  }
}

TEST(TextNormalize, CreaseCsvWithBomAndCrlf) {
  const std::string csv = "# flap\nangle_deg,moment_Nm\n10,0.001\n20,0.002\n30,0.0035\n40,0.005\n";
  for (const std::string& text : {bom_crlf(csv), cr_only(csv)}) {
    std::istringstream in(text);
    const CreaseData d = parse_crease_data(in, "c.csv", std::nullopt);
    ASSERT_EQ(d.curves.size(), 1u);
    EXPECT_EQ(d.curves[0].angle_deg.size(), 4u);
    EXPECT_EQ(d.curves[0].moment.back(), 0.005);
  }
}

TEST(TextNormalize, CantileverCsvWithBomAndCrlf) {
  const std::string csv = "# length_m: 0.12\nforce_N,tip_displacement_mm\n0.001,1\n0.002,2\n";
  for (const std::string& text : {bom_crlf(csv), cr_only(csv)}) {
    std::istringstream in(text);
    const CantileverData d = parse_cantilever_data(in, "b.csv");
    EXPECT_EQ(d.length, 0.12);
    ASSERT_EQ(d.force.size(), 2u);
    EXPECT_EQ(d.deflection[1], 2e-3);
  }
}

TEST(TextNormalize, MeasuredCurveCsvWithBomAndCrlf) {
  const test::TempDir dir;
  const std::string csv = "pull_mm,force_N\n0,0\n1,0.1\n2,0.15\n3,0.2\n4,0.22\n";
  for (const std::string& text : {bom_crlf(csv), cr_only(csv)}) {
    test::spit(dir / "e.csv", text);
    const ForceCurve c = read_force_curve(dir / "e.csv");
    EXPECT_EQ(c.x_column, "pull_mm");
    ASSERT_EQ(c.x.size(), 5u);
    EXPECT_EQ(c.force.back(), 0.22);
  }
}

// Duplicate keys: yaml-cpp keeps both, and the first used to win silently.
TEST(DuplicateKeys, RefusedWithBothLines) {
  expect_refused(
      replaced(kSheet, "  thickness: 0.0001\n", "  thickness: 0.0001\n  thickness: -5\n"),
      "sheet.thickness", "lines 7 and 8");
  expect_refused(std::string(kSheet) + "solver: {type: explicit}\n", "solver", "lines 16 and 18");
  expect_refused(
      replaced(kSheet, "{name: tip, type: point,", "{name: tip, name: tap, type: point,"),
      "probes[0].name", "given twice");
  expect_refused(
      replaced(kSheet, "at: {s: 0.1, y: 0.01}, force", "at: {s: 0.1, s: 0.05, y: 0.01}, force"),
      "loads[0].at.s", "given twice");
  expect_refused(std::string(kZigzag) +
                     "contact: {stiffness: 1.0e3, friction: {mu_static: 0.5, mu_static: 0.1}}\n",
                 "contact.friction.mu_static", "given twice");
}

// 1e-320 Pa used to hang Eigen's SparseLU; subnormal numbers are refused everywhere.
TEST(NumberRules, SubnormalRefusedEverywhere) {
  expect_refused(replaced(kSheet, "youngs_modulus: 4.0e9", "youngs_modulus: 1e-320"),
                 "material.youngs_modulus", "smallest normal number");
  expect_refused(std::string(kSheet) + "stiffness: {bending_rigidity: 1e-320}\n",
                 "stiffness.bending_rigidity", "smallest normal number");
  expect_refused(replaced(kSheet, "force: [0, 0, -0.001]", "force: [0, 0, -1e-310]"),
                 "loads[0].force[2]", "smallest normal number");
  expect_refused(std::string(kZigzag) +
                     "contact: {stiffness: 1.0e3, friction: {tangential_damping: 4e-315}}\n",
                 "contact.friction.tangential_damping", "smallest normal number");
  EXPECT_THROW(parse_number("1e-320", "f.csv", "line 2: x"), InputError);
  EXPECT_THROW(parse_number("1e309", "f.csv", "line 2: x"), InputError);
  EXPECT_EQ(parse_number("2.5e-308", "f.csv", "x"), 2.5e-308);  // normal: kept
  EXPECT_EQ(parse_number("0", "f.csv", "x"), 0.0);
}

TEST(NumberRules, PhysicalRangesOfMaterialAndSheet) {
  expect_refused(replaced(kSheet, "youngs_modulus: 4.0e9", "youngs_modulus: 1e-300"),
                 "material.youngs_modulus", "[100, 1e+13] Pa");
  expect_refused(replaced(kSheet, "density: 800", "density: 1e300"), "material.density", "kg/m^3");
  expect_refused(replaced(kSheet, "thickness: 0.0001", "thickness: 5"), "sheet.thickness",
                 "[1e-10, 1] m");
  expect_refused(replaced(kSheet, "length: 0.1", "length: 1e-300"), "sheet.length", "m");
}

// A subnormal matrix (from any source) gives "no solution", not an endless factorisation.
TEST(NumberRules, SparseSolveOfSubnormalOrNonFiniteMatrixReturns) {
  Eigen::SparseMatrix<double> A(2, 2);
  A.insert(0, 0) = 1e-320;
  A.insert(1, 1) = 1e-320;
  Eigen::VectorXd b = Eigen::VectorXd::Ones(2), x;
  EXPECT_FALSE(sparse_solve(A, b, x));
  A.coeffRef(0, 0) = NAN;
  EXPECT_FALSE(sparse_solve(A, b, x));
}

// Step counts past a long (dt 1e-19 over 1 s) used to end with status ok and no step.
TEST(StepLimits, RefusedAtReadTimeWithTheCount) {
  expect_refused(replaced(kSheet, "type: static", "type: explicit\n  dt: 1e-19"), "solver.dt",
                 "1e+19 steps; at most 1e+09");
  expect_refused(replaced(kSheet, "type: static", "type: explicit\n  t_end: 1e14\n  dt: 1e-4"),
                 "solver.dt", "at most 1e+09");
  expect_refused(replaced(kSheet, "type: static", "type: implicit\n  output_interval: 1e-12"),
                 "solver.output_interval", "at most 1e+06");
  expect_refused(replaced(kSheet, "type: static", "type: implicit\n  t_end: 1e14\n  dt_max: 1e-3"),
                 "solver.dt_max", "at most 1e+09");
}

// Modified Newton's options (docs/scene.md): the range named, a word that is no boolean refused.
TEST(SolverOptions, JacobianReuseKeysValidated) {
  expect_refused(replaced(kSheet, "type: static", "type: implicit\n  jacobian_max_age: 0"),
                 "solver.jacobian_max_age", "1000");
  expect_refused(replaced(kSheet, "type: static", "type: implicit\n  jacobian_reuse: often"),
                 "solver.jacobian_reuse", "true or false");
  const Scene scene =
      parse_scene(replaced(kSheet, "type: static",
                           "type: implicit\n  jacobian_reuse: false\n  jacobian_max_age: 5"),
                  "s.yaml");
  EXPECT_FALSE(scene.solver.jacobian_reuse);
  EXPECT_EQ(scene.solver.jacobian_max_age, 5);
}

// Newton's tolerance, a fraction of the local error tolerance: (0, 1] (docs/scene.md).
TEST(SolverOptions, NewtonToleranceValidated) {
  for (const char* bad : {"0", "-0.1", "1.5"}) {
    expect_refused(
        replaced(kSheet, "type: static", std::string("type: implicit\n  newton_tolerance: ") + bad),
        "solver.newton_tolerance", "(0, 1]");
  }
  const Scene scene = parse_scene(
      replaced(kSheet, "type: static", "type: implicit\n  newton_tolerance: 0.01"), "s.yaml");
  EXPECT_EQ(scene.solver.newton_tolerance, 0.01);
  EXPECT_EQ(parse_scene(kSheet, "s.yaml").solver.newton_tolerance, 1e-3);
}

// Newton iterations per solve: each solver's own unless the scene names them (docs/scene.md).
TEST(SolverOptions, NewtonIterationsPerSolverUnlessGiven) {
  EXPECT_EQ(newton_iterations(parse_scene(kSheet, "s.yaml").solver), 50);
  EXPECT_EQ(newton_iterations(
                parse_scene(replaced(kSheet, "type: static", "type: implicit"), "s.yaml").solver),
            10);
  const Scene given = parse_scene(
      replaced(kSheet, "type: static", "type: implicit\n  max_iterations: 30"), "s.yaml");
  EXPECT_EQ(newton_iterations(given.solver), 30);
  expect_refused(replaced(kSheet, "type: static", "type: implicit\n  max_iterations: 0"),
                 "solver.max_iterations", "100000");
}

TEST(StepLimits, PullStepRefusedAtReadTime) {
  expect_refused(replaced(kZigzag, "fold_angle_deg: 80}", "fold_angle_deg: 80, pull_step: 1e-11}"),
                 "zigzag.pull_step", "at most 1e+09");
}

// Inside the solvers, where the step comes from the model: a divergence with a diagnosis.
TEST(StepLimits, SolverStopsWhenTimeDoesNotAdvance) {
  EXPECT_THROW(require_step_advances(1e10, 1e-19, "test"), DivergenceError);
  EXPECT_NO_THROW(require_step_advances(0, 1e-19, "test"));
  EXPECT_THROW(solver_step_count(1e14, 1e-6, "test"), DivergenceError);
  EXPECT_EQ(solver_step_count(1, 0.25, "test"), 4);

  Scene s = parse_scene(kSheet, "s.yaml");
  State st = initial_state(s.model);
  st.t = 1e10;  // a step of 1e-9 s no longer changes t
  SolverSettings set;
  set.kind = SolverKind::Implicit;
  set.t_end = 1e10 + 1e-3;
  set.dt = 1e-9;
  set.dt_max = 1e-9;
  const SolverStats stats = run_solver(s.model, st, set, [](const State&, const BodyForces&) {});
  EXPECT_EQ(stats.status, "diverged");
  EXPECT_NE(stats.message.find("does not advance"), std::string::npos) << stats.message;
}

// A sheet cut into rows is a plate: of the identified rigidities it takes the bending one.
TEST(SheetRows, BeamOverridesRefusedForAPlate) {
  const std::string rows = replaced(kSheet, "segments: 4", "segments: 4\n  segments_across: 2");
  expect_refused(rows + "stiffness: {twist_rigidity: 1e-6}\n", "stiffness.twist_rigidity",
                 "segments_across: 1");
  expect_refused(rows + "stiffness: {bending_rigidity: 1e-5, axial_rigidity: 1e3}\n",
                 "stiffness.axial_rigidity", "segments_across: 1");
}

// 10^6 x 10^5 segments used to end in a bare std::bad_alloc after 4.6 GB.
TEST(MemoryEstimate, HugeModelsRefusedBeforeBuilding) {
  expect_refused(replaced(kSheet, "segments: 4", "segments: 1000000\n  segments_across: 100000"),
                 "discretisation.segments x segments_across", "GiB");
  const auto free = available_memory_bytes();
  ASSERT_TRUE(free.has_value());
  EXPECT_GT(*free, 0);
  // Just over what is free, by the estimate's own lower bound of 16 KiB per one-row segment.
  const double too_many = std::ceil(*free / (16.0 * 1024) * 1.01);
  if (too_many < 1e8) {
    EXPECT_THROW(check_model_memory(too_many, 1, "s.yaml", "discretisation.segments"), InputError);
  }
  EXPECT_NO_THROW(check_model_memory(4096, 1, "s.yaml", "discretisation.segments"));
}

// identify bending used to print NaN / inf with exit 0 for 1e308 readings.
TEST(IdentifyOverflow, RefusedWithLineAndColumn) {
  std::istringstream in("force_N,tip_displacement_m\n0.001,0.001\n1e308,0.002\n");
  const CantileverData d = parse_cantilever_data(in, "b.csv");
  try {
    identify_bending(d, 0.1, 8);
    ADD_FAILURE() << "accepted 1e308 N";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "b.csv");
    EXPECT_EQ(e.field(), "line 3: force_N, tip displacement") << e.what();
  }
  std::istringstream tiny("force_N,tip_displacement_m\n1e-300,1e-300\n");
  EXPECT_THROW(identify_bending(parse_cantilever_data(tiny, "b.csv"), 0.1, 8), InputError);
  std::istringstream ok("force_N,tip_displacement_m\n0.001,0.001\n");
  EXPECT_THROW(identify_bending(parse_cantilever_data(ok, "b.csv"), 0.1, 8, 0.02, 1e-200),
               InputError);
}

TEST(IdentifyOverflow, CreaseSplineThatOverflowsIsRefused) {
  std::istringstream in("angle_deg,moment_Nm\n10,1e308\n20,1.5e308\n30,1.7e308\n40,1.79e308\n");
  const CreaseData flap = parse_crease_data(in, "flap.csv", std::nullopt);
  try {
    identify_crease(flap, SplineEnds::NotAKnot);
    ADD_FAILURE() << "accepted moments near 1e308 N m";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "flap.csv");
    EXPECT_EQ(e.field(), "curve pressing_time_s 0, opening 1") << e.what();
  }
}

// The command line: each former silent result is now exit 2 with a one-line message, and
// the hang (1e-320 Pa) ends at once.
TEST(InputValidationCli, FormerSilentResultsExitWithTwo) {
  const test::TempDir dir;
  test::spit(dir / "dt.yaml", replaced(kSheet, "type: static", "type: explicit\n  dt: 1e-19"));
  test::spit(dir / "e.yaml", replaced(kSheet, "youngs_modulus: 4.0e9", "youngs_modulus: 1e-320"));
  test::spit(dir / "dup.yaml",
             replaced(kSheet, "  thickness: 0.0001\n", "  thickness: 0.0001\n  thickness: -5\n"));
  test::spit(dir / "b.csv", "force_N,tip_displacement_m\n1e308,1e308\n");
  for (const char* args : {"run dt.yaml --out o --quiet", "run e.yaml --out o --quiet",
                           "run dup.yaml --out o --quiet", "identify bending b.csv --length 0.1"}) {
    const test::CliResult r = test::run_finseg(dir, args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("finseg: error: "), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "o/summary.json"));
}

// Messages: scene fields instead of internal ones, long values cut short.
TEST(Messages, SceneFieldsAndShortQuotes) {
  EXPECT_EQ(scene_field_of_model("bodies[0].mass", false).rfind("material.density", 0), 0u);
  EXPECT_EQ(scene_field_of_model("elements[3].damping", false).rfind("material.damping_time", 0),
            0u);
  EXPECT_EQ(scene_field_of_model("loads[1]", false), "loads[1]");
  const std::string long_name(300, 'x');
  try {
    parse_scene(replaced(kSheet, "type: point", "type: " + long_name), "s.yaml");
    ADD_FAILURE();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.field(), "probes[0].type");
    EXPECT_NE(what.find(std::string(40, 'x') + "...' (300 characters)"), std::string::npos) << what;
    EXPECT_EQ(what.find(std::string(41, 'x')), std::string::npos) << what;
  }
  EXPECT_EQ(quoted("abc"), "'abc'");
}

// Item 6: contact.groups counts panels from 1, like every other scene key, and a panel that
// does not exist is refused (a 0-based list used to shift every group silently).
TEST(Numbering, ContactGroupsFromOneAndValidated) {
  const Scene s = parse_scene(
      std::string(kZigzag) + "contact: {stiffness: 1.0e3, groups: [[1, 2, 3, 4, 5, 6]]}\n",
      "s.yaml");
  ASSERT_EQ(s.model.contact.groups.size(), 1u);
  EXPECT_EQ(s.model.contact.groups[0], (std::vector<int>{0, 1, 2, 3, 4, 5}));
  expect_refused(std::string(kZigzag) + "contact: {stiffness: 1.0e3, groups: [[0, 1]]}\n",
                 "contact.groups[0][0]", "[1, 6]");
  expect_refused(std::string(kZigzag) + "contact: {stiffness: 1.0e3, groups: [[1, 2], [5, 7]]}\n",
                 "contact.groups[1][1]", "[1, 6]");
  expect_refused(std::string(kZigzag) + "contact: {stiffness: 1.0e3, groups: [[1.5]]}\n",
                 "contact.groups[0][0]", "whole number");
}

TEST(Numbering, EveryPanelCreaseAndBodyIndexValidated) {
  expect_refused(std::string(kZigzag) + "fixtures: {panels: [1, 7]}\n", "fixtures.panels", "");
  expect_refused(replaced(kZigzag, "fold_angle_deg: 80}", "fold_angle_deg: 80, pulled_crease: 6}"),
                 "zigzag.pulled_crease", "");
  expect_refused(std::string(kZigzag) + "outputs: {phases: {panels: [2, 9]}}\n",
                 "outputs.phases.panels[1]", "");
  expect_refused(replaced(kSheet, "clamp_start: true", "clamp_start: true\n  panels: [2]"),
                 "fixtures.panels", "");
  expect_refused(replaced(kSheet, "clamp_start: true", "clamp_start: true\n  bodies: [seg_r0_s9]"),
                 "fixtures.bodies[0]", "not a body");
}

}  // namespace input_validation_test
}  // namespace finseg
