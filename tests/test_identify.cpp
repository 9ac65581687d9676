// Identification (paper section 3): the discrete chain's tip compliance against the sheet
// generator, and round trips from known laws through noisy synthetic test data.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "elements/crease_laws/measured.hpp"
#include "generators/sheet.hpp"
#include "identification/bending.hpp"
#include "identification/crease.hpp"
#include "solvers/solver.hpp"
#include "test_paths.hpp"

namespace finseg {
namespace identify_test {

// Tip deflection of the generator's clamped strip under a small tip force, divided by the
// continuum L^3/(3EI): must equal the closed form 1 - 1/(4N^2) of the discrete chain.
TEST(IdentifyBending, ChainComplianceMatchesSheetGenerator) {
  for (int n : {1, 2, 3, 8, 16}) {
    SheetSpec s;
    s.length = 0.1;
    s.width = 0.02;
    s.thickness = 2e-4;
    s.youngs_modulus = 4e9;
    s.cells_along = n;
    s.clamp_start = true;
    const double EI = 3e-5;
    s.overrides.bending_rigidity = EI;
    s.overrides.shear_rigidity = 1e9;  // Euler-Bernoulli: no shear compliance
    s.overrides.axial_rigidity = 1e9;
    Model m = build_sheet_model(s);
    const MaterialPoint tip = locate_material_point(m, s.length, 0.5 * s.width);
    const double P = 1e-6 * EI / (s.length * s.length);  // deep in the linear regime
    m.loads.push_back({tip.body, tip.r_B, Vec3(0, 0, -P), Vec3::Zero(), false});
    State st = initial_state(m);
    SolverSettings set;
    set.kind = SolverKind::Static;
    const SolverStats stats = run_solver(m, st, set, [](const State&, const BodyForces&) {});
    ASSERT_EQ(stats.status, "ok") << stats.message;
    const double x = -(st.p_W[tip.body] + st.R_WB[tip.body] * tip.r_B).z();
    const double ratio = x / (P * std::pow(s.length, 3) / (3 * EI));
    EXPECT_NEAR(ratio / chain_compliance_factor(n), 1.0, 1e-5) << "N = " << n;
  }
  EXPECT_DOUBLE_EQ(chain_compliance_factor(1), 0.75);
}

TEST(IdentifyBending, RoundTripWithNoise) {
  const double EI = 2.4e-5, L = 0.12;
  std::mt19937 rng(12345);
  std::normal_distribution<double> noise(0.0, 0.01);  // 1 % of each reading
  std::ostringstream csv;
  csv << "# length_m: 0.12\n# width_m: 0.04\n# thickness_m: 0.0001\nforce_N,tip_displacement_mm\n";
  for (int i = 1; i <= 12; ++i) {
    const double F = 2e-4 * i;
    const double x = F * L * L * L / (3 * EI) * (1 + noise(rng));
    csv << fmt::format("{:.6g},{:.6g}\n", F, x * 1e3);
  }
  std::istringstream in(csv.str());
  const CantileverData d = parse_cantilever_data(in, "cantilever.csv");
  ASSERT_TRUE(d.length && d.width && d.thickness);
  EXPECT_DOUBLE_EQ(*d.length, 0.12);
  const BendingIdentification r = identify_bending(d, *d.length, 10, d.width, d.thickness);
  EXPECT_NEAR(r.EI_continuum / EI, 1.0, 0.01);
  EXPECT_NEAR(r.EI_chain / r.EI_continuum, 1 - 1.0 / 400, 1e-15);
  EXPECT_NEAR(r.joint_stiffness, r.EI_chain / (L / 10), 1e-15 * r.joint_stiffness);
  EXPECT_NEAR(*r.youngs_modulus, 12 * r.EI_continuum / (0.04 * 1e-12), 1e-6 * *r.youngs_modulus);
}

TEST(IdentifyBending, BadInput) {
  auto parse = [](const std::string& t) {
    std::istringstream in(t);
    return parse_cantilever_data(in, "c.csv");
  };
  EXPECT_THROW(parse("force_N\n1\n"), InputError);
  EXPECT_THROW(parse("force_N,tip_displacement_m\n1,x\n"), InputError);
  EXPECT_THROW(parse("force_N,tip_displacement_m\n-1,0.1\n"), InputError);
  EXPECT_THROW(parse("# length_m: -2\nforce_N,tip_displacement_m\n1,0.1\n"), InputError);
  const CantileverData d = parse("force_N,tip_displacement_m\n0.1,0.01\n");
  EXPECT_THROW(identify_bending(d, 0.0, 4), InputError);
  EXPECT_THROW(identify_bending(d, 0.1, 0), InputError);
}

// A smooth non-polynomial crease law: M(theta) = A (exp(b (theta - theta_r)) - 1).
struct ExpLaw {
  double A, b, rest_deg;
  double M(double deg) const { return A * (std::exp(b * (deg - rest_deg) * kDegToRad) - 1); }
};

TEST(IdentifyCrease, RoundTripWithNoise) {
  // Two pressing times, two openings each, every 5 deg from 20 to 160 deg (the rest angles
  // lie 2-8 deg below the first point); 20 repeats with 1 % noise on the force.
  const std::vector<std::tuple<double, int, ExpLaw>> truth = {{30, 1, {4e-4, 1.2, 15}},
                                                              {30, 2, {6e-4, 0.9, 12}},
                                                              {120, 1, {7e-4, 1.1, 18}},
                                                              {120, 2, {9e-4, 0.8, 14}}};
  const double lever = 0.03;
  std::mt19937 rng(2024);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::ostringstream csv;
  csv << "angle_deg,force_N,lever_m,pressing_time_s,opening,repeat\n";
  for (const auto& [p, n, law] : truth) {
    for (int r = 1; r <= 20; ++r) {
      for (double deg = 20; deg <= 160; deg += 5) {
        const double F = law.M(deg) / lever * (1 + noise(rng));
        csv << fmt::format("{},{:.6g},{},{},{},{}\n", deg, F, lever, p, n, r);
      }
    }
  }
  std::istringstream in(csv.str());
  const CreaseData flap = parse_crease_data(in, "flap.csv");
  const CreaseIdentification id = identify_crease(flap, SplineEnds::NotAKnot);
  ASSERT_EQ(id.curves.size(), 4u);
  EXPECT_EQ(id.curves[0].repeats, 20);

  // Through the file a scene would reference, back into a law.
  const auto dir = std::filesystem::temp_directory_path() / "finseg_identify_crease_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "creases.csv").string();
  write_crease_data(path, id.data);
  const CreaseData back = read_crease_data(path);
  std::filesystem::remove_all(dir);
  double worst = 0;
  for (const auto& [p, n, law] : truth) {
    MeasuredLawOptions o;
    o.pressing_time = p;
    o.openings_before = n - 1;
    const MeasuredCreaseLaw identified(back, o);
    for (double deg = 20; deg <= 160; deg += 1) {
      const double M = -identified.evaluate(kPi - deg * kDegToRad, ElementHistory{}, 0).moment;
      worst = std::max(worst, std::abs(M / law.M(deg) - 1));
    }
  }
  EXPECT_LT(worst, 0.01);
  std::printf("crease identification round trip: worst relative moment error %.3g\n", worst);
  // The summary's secant stiffness follows eq. 20 from the identified curve.
  const CreaseCurveSummary& s = id.curves[0];
  EXPECT_NEAR(s.secant_stiffness,
              id.data.curves[0].moment.back() / ((s.theta_max_deg - s.rest_deg) * kDegToRad),
              1e-15);
}

TEST(IdentifyCli, CreaseCommandWritesDataFile) {
  const auto dir = std::filesystem::temp_directory_path() / "finseg_identify_cli_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "flap.csv") << "angle_deg,force_N\n20,0.01\n60,0.03\n100,0.06\n140,0.1\n";
  const std::string out = (dir / "creases.csv").string();
  const std::string cmd =
      fmt::format("{} identify crease {} --lever 0.05 --out {} --no-plot > {}", FINSEG_BINARY,
                  (dir / "flap.csv").string(), out, (dir / "log.txt").string());
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const CreaseData d = read_crease_data(out);
  ASSERT_EQ(d.curves.size(), 1u);
  EXPECT_NEAR(d.curves[0].moment[2], 0.06 * 0.05, 1e-15);
  std::ofstream(dir / "cant.csv") << "# length_m: 0.1\nforce_N,tip_displacement_m\n0.001,0.002\n";
  const std::string cmd2 = fmt::format("{} identify bending {} --segments 4 --out {} > {}",
                                       FINSEG_BINARY, (dir / "cant.csv").string(),
                                       (dir / "bend.yaml").string(), (dir / "log2.txt").string());
  ASSERT_EQ(std::system(cmd2.c_str()), 0);
  // Former defect: --out wrote key: value lines, not the scene fragment the docs describe.
  // The fragment appended to a 4-cell cantilever scene reproduces the measured compliance
  // c = 2 m/N: tip deflection F c for F = 1e-5 N (geometric nonlinearity ~ (2e-4)^2).
  const std::string gen = fmt::format(
      "{} gen cantilever --segments 4 --length 0.1 --tip-force 0,0,-1e-5 --out {} > {} 2>&1 && "
      "cat {} >> {} && {} run {} --out {} --quiet > {} 2>&1",
      FINSEG_BINARY, (dir / "cant.yaml").string(), (dir / "log3.txt").string(),
      (dir / "bend.yaml").string(), (dir / "cant.yaml").string(), FINSEG_BINARY,
      (dir / "cant.yaml").string(), (dir / "run").string(), (dir / "log4.txt").string());
  ASSERT_EQ(std::system(gen.c_str()), 0);
  std::ifstream tip(dir / "run/tip.csv");
  std::string line, last;
  while (std::getline(tip, line)) last = line;
  const double z = std::stod(last.substr(last.rfind(',') + 1));
  EXPECT_NEAR(z / (-1e-5 * 2.0), 1.0, 1e-4) << last;
  std::filesystem::remove_all(dir);
}

std::string run_output(const std::string& cmd) {
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  char buf[4096];
  while (p && fgets(buf, sizeof buf, p)) out += buf;
  if (p) {
    EXPECT_EQ(pclose(p), 0) << cmd;
  }
  return out;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(IdentifyCli, CreaseTableColumnsAreTheDocumentedOnesAndCurvesHaveTheirOwnColour) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("finseg_identify_doc_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string data = std::string(FINSEG_SOURCE_DIR) + "/examples/creases/flap_test.csv";
  const std::string out = run_output(fmt::format(
      "{} identify crease {} --out {} 2>&1", FINSEG_BINARY, data, (dir / "creases.csv").string()));
  // Former defect: the worked example in docs/crease-data.md named other columns. Its
  // header line is quoted there verbatim.
  std::istringstream lines(out);
  std::string line, header;
  while (std::getline(lines, line)) {
    if (line.find("pressed_s") != std::string::npos) header = line;
  }
  ASSERT_FALSE(header.empty()) << out;
  const std::string doc = read_text(std::string(FINSEG_SOURCE_DIR) + "/docs/crease-data.md");
  EXPECT_NE(doc.find(header), std::string::npos) << "undocumented table header:\n" << header;
  // Former defect: a curve's line and its points had different colours, and colours
  // repeated across curves. 12 curves: line and points share one linetype, all differ.
  const std::string gp = read_text(dir / "creases.csv.svg.gp");
  std::vector<int> lt;
  const std::size_t plot = gp.find("\nplot ");
  ASSERT_NE(plot, std::string::npos) << gp;
  for (std::size_t at = gp.find(" lt ", plot); at != std::string::npos;
       at = gp.find(" lt ", at + 1)) {
    lt.push_back(std::stoi(gp.substr(at + 4)));
  }
  ASSERT_EQ(lt.size(), 24u) << gp;
  std::set<int> colours;
  for (std::size_t k = 0; k < 12; ++k) {
    EXPECT_EQ(lt[2 * k], lt[2 * k + 1]) << k;
    colours.insert(lt[2 * k]);
  }
  EXPECT_EQ(colours.size(), 12u);
  std::filesystem::remove_all(dir);
}

}  // namespace identify_test
}  // namespace finseg
