// Crease data files and the scene's crease-law section: parsing, averaging of repeats,
// validation messages with file and line, round trip through the writer.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "elements/crease_laws/crease_data.hpp"
#include "elements/crease_laws/measured.hpp"
#include "scene/sections.hpp"

namespace finseg {
namespace crease_data_test {

CreaseData parse(const std::string& text, std::optional<double> lever = std::nullopt) {
  std::istringstream in(text);
  return parse_crease_data(in, "c.csv", lever);
}

// Expects an InputError whose field starts with `field` and whose message contains `part`.
void expect_error(const std::string& text, const std::string& field, const std::string& part) {
  try {
    parse(text);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "c.csv");
    EXPECT_EQ(e.field().rfind(field, 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(CreaseData, ReadsCurvesGroupedAndSorted) {
  const CreaseData d = parse(
      "# flap test\n"
      "angle_deg,moment_Nm,pressing_time_s,opening\n"
      "10,0.001,60,2\n20,0.002,60,2\n30,0.0035,60,2\n"
      "10,0.0005,60,1\n20,0.001,60,1\n30,0.002,60,1\n"
      "\n"
      "10,0.0001,30,1\n20,0.0002,30,1\n30,0.0003,30,1\n");
  ASSERT_EQ(d.curves.size(), 3u);
  EXPECT_EQ(d.pressing_times(), (std::vector<double>{30, 60}));
  EXPECT_EQ(d.curves[0].pressing_time, 30);
  EXPECT_EQ(d.curves[1].opening, 1);
  EXPECT_EQ(d.curves[2].opening, 2);
  EXPECT_EQ(d.curves[2].moment, (std::vector<double>{0.001, 0.002, 0.0035}));
  EXPECT_EQ(d.curves[1].first_line, 6);
}

TEST(CreaseData, ForceTimesLeverAndDefaults) {
  const CreaseData d = parse(
      "angle_deg,force_N,lever_m\n"
      "10,0.1,0.05\n40,0.2,0.05\n80,0.3,0.04\n");
  ASSERT_EQ(d.curves.size(), 1u);
  EXPECT_EQ(d.curves[0].opening, 1);
  EXPECT_EQ(d.curves[0].pressing_time, 0);
  EXPECT_NEAR(d.curves[0].moment[2], 0.3 * 0.04, 1e-17);
  const CreaseData e = parse("angle_deg,force_N\n10,0.1\n40,0.2\n80,0.3\n", 0.02);
  EXPECT_NEAR(e.curves[0].moment[1], 0.2 * 0.02, 1e-17);
}

TEST(CreaseData, RepeatsAreAveraged) {
  // Same angles: pointwise mean.
  const CreaseData d = parse(
      "angle_deg,moment_Nm,repeat\n"
      "10,1,1\n20,2,1\n30,3,1\n"
      "10,3,2\n20,4,2\n30,6,2\n");
  ASSERT_EQ(d.curves.size(), 1u);
  EXPECT_EQ(d.curves[0].repeats, 2);
  EXPECT_EQ(d.curves[0].moment, (std::vector<double>{2, 3, 4.5}));
  // Different angles: each repeat's not-a-knot spline on the common range; cubic data are
  // reproduced exactly, so the mean of two cubics is their mean everywhere.
  auto p = [](double x) { return 1 + 0.1 * x + 0.002 * x * x + 1e-5 * x * x * x; };
  auto q = [](double x) { return 2 + 0.05 * x - 0.001 * x * x + 2e-5 * x * x * x; };
  std::string text = "angle_deg,moment_Nm,repeat\n";
  for (double x : {0.0, 15.0, 40.0, 70.0, 100.0}) text += fmt::format("{},{:.17g},1\n", x, p(x));
  for (double x : {10.0, 30.0, 50.0, 90.0, 120.0}) text += fmt::format("{},{:.17g},2\n", x, q(x));
  const CreaseData r = parse(text);
  const CreaseCurve& c = r.curves[0];
  EXPECT_EQ(c.angle_deg, (std::vector<double>{10, 15, 30, 40, 50, 70, 90, 100}));
  for (size_t i = 0; i < c.angle_deg.size(); ++i) {
    const double x = c.angle_deg[i];
    EXPECT_NEAR(c.moment[i], 0.5 * (p(x) + q(x)), 1e-12) << x;
  }
}

TEST(CreaseData, ValidationNamesFileLineAndColumn) {
  expect_error("angle_deg,moment_Nm\n10,1\n30,2\n20,3\n", "line 4: angle_deg", "increase");
  expect_error("angle_deg,moment_Nm\n10,1\n30,2\n30,3\n", "line 4: angle_deg", "repeat");
  expect_error("angle_deg,moment_Nm\n10,1\n30,2\n", "line 2: angle_deg", "need >= 3");
  expect_error("angle_deg,moment_Nm\n10,1\n30,nan\n40,3\n", "line 3: moment_Nm", "finite");
  expect_error("angle_deg,moment_Nm\n10,1\n30,x\n40,3\n", "line 3: moment_Nm", "not a number");
  expect_error("angle_deg,moment_Nm\n10,1\n30,-2\n40,3\n", "line 3: moment_Nm", ">= 0");
  expect_error("angle_deg,force_N,lever_m\n10,1,0.1\n30,-2,0.1\n40,3,0.1\n", "line 3: force_N",
               ">= 0");
  expect_error("angle_deg,moment_Nm,opening\n10,1,1\n20,1,1\n30,1,1\n10,1,3\n20,1,3\n30,1,3\n",
               "line 5: opening", "opening 2 is missing");
  expect_error("angle_deg,moment_Nm,opening\n10,1,0\n", "line 2: opening", "integer 1, 2");
  expect_error("angle_deg,moment_Nm,opening\n10,1,1.5\n", "line 2: opening", "integer 1, 2");
  expect_error("moment_Nm\n1\n", "line 1: header", "missing column angle_deg");
  expect_error("angle_deg\n1\n", "line 1: header", "moment_Nm or force_N");
  expect_error("angle_deg,force_N\n1,1\n", "line 1: header", "lever_m");
  expect_error("angle_deg,moment_Nm,colour\n1,1,red\n", "line 1: column 'colour'", "allowed");
  expect_error("angle_deg,moment_Nm\n10,1,3\n", "line 2", "header has 2");
  expect_error("angle_deg,moment_Nm\n400,1\n", "line 2: angle_deg", "0..360");
  expect_error("# nothing\n", "header", "no header");
}

TEST(CreaseData, WriteReadRoundTrip) {
  CreaseData d;
  d.source = "x";
  CreaseCurve c;
  c.pressing_time = 12.5;
  c.opening = 1;
  c.angle_deg = {10.25, 33.0, 47.125};
  c.moment = {1.0 / 3, 2.0 / 7, 0.1};
  d.curves = {c};
  std::ostringstream out;
  write_crease_data(out, d, {"made by a test"});
  const CreaseData r = parse(out.str());
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_EQ(r.curves[0].angle_deg, c.angle_deg);
  EXPECT_EQ(r.curves[0].moment, c.moment);
  EXPECT_EQ(r.curves[0].pressing_time, 12.5);
}

class SceneCreaseLaw : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("finseg_crease_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    std::ofstream(dir_ / "creases.csv") << "angle_deg,moment_Nm,pressing_time_s,opening\n"
                                           "10,0.001,30,1\n60,0.002,30,1\n120,0.004,30,1\n"
                                           "10,0.002,90,1\n60,0.004,90,1\n120,0.008,90,1\n";
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  YamlContext ctx() const { return {(dir_ / "scene.yaml").string(), "sheet.folds[0].law"}; }
  std::filesystem::path dir_;
};

TEST_F(SceneCreaseLaw, Linear) {
  const auto law =
      read_crease_law(YAML::Load("{type: linear, stiffness: 0.02, rest_angle_deg: 150}"), ctx());
  const double phi = 100 * kDegToRad;
  EXPECT_NEAR(law->evaluate(phi, {}, 0).moment, 0.02 * (phi - 150 * kDegToRad), 1e-16);
}

TEST_F(SceneCreaseLaw, MeasuredRelativeFileInterpolatedPressingTime) {
  const auto law = read_crease_law(
      YAML::Load("{type: measured, file: creases.csv, pressing_time: 60, ends: natural}"), ctx());
  // At a knot both curves pass through their data: the mean of 0.002 and 0.004 at 60 deg.
  EXPECT_NEAR(law->evaluate(kPi - 60 * kDegToRad, {}, 0).moment, -0.003, 1e-15);
}

TEST_F(SceneCreaseLaw, Relaxation) {
  const auto law =
      read_crease_law(YAML::Load("{type: linear, stiffness: 0.02, rest_angle_deg: 150, relaxation: "
                                 "{coefficient_deg: 2, time_constant_s: 10, age_s: 100}}"),
                      ctx());
  const double delta = 2 * kDegToRad * std::log((1 + 110.0 / 10) / (1 + 100.0 / 10));
  EXPECT_NEAR(law->rest_angle({}, 10), 150 * kDegToRad - delta, 1e-14);
}

TEST_F(SceneCreaseLaw, BadInputNamesField) {
  auto field_of = [&](const std::string& yaml) {
    try {
      read_crease_law(YAML::Load(yaml), ctx());
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("no error");
  };
  const std::string f = "sheet.folds[0].law";
  EXPECT_EQ(field_of("{type: springy}"), f + ".type");
  EXPECT_EQ(field_of("{type: linear, stiffness: 1}"), f + ".rest_angle_deg");
  EXPECT_EQ(field_of("{type: linear, stiffness: -1, rest_angle_deg: 0}"), f + ".stiffness");
  EXPECT_EQ(field_of("{type: linear, stiffness: 1, rest_angle_deg: 0, colour: red}"),
            f + ".colour");
  EXPECT_EQ(field_of("{type: measured, file: creases.csv}"), f + ".pressing_time");
  EXPECT_EQ(field_of("{type: measured, file: creases.csv, pressing_time: 200}"),
            f + ".pressing_time");
  EXPECT_EQ(field_of("{type: measured, file: creases.csv, pressing_time: 30, ends: cubic}"),
            f + ".ends");
  EXPECT_EQ(field_of("{type: measured, file: missing.csv, pressing_time: 30}"), "file");
  EXPECT_EQ(field_of("{type: linear, stiffness: 1, rest_angle_deg: 0, relaxation: "
                     "{coefficient_deg: 1, time_constant_s: 0}}"),
            f + ".relaxation.time_constant_s");
  EXPECT_EQ(field_of("{type: linear, stiffness: 1, rest_angle_deg: 0, opened_above_deg: 20, "
                     "closed_below_deg: 40}"),
            f);
}

}  // namespace crease_data_test
}  // namespace finseg
