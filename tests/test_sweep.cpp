// finseg sweep (issue 15 item 2): sweep files, the factorial and listed cases, the table in
// case order whatever the number of parallel jobs, and failing cases recorded.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "sweep/sweep_plot.hpp"
#include "sweep/sweep_spec.hpp"
#include "sweep/sweep_table.hpp"

namespace finseg {
namespace sweep_test {

using test::run_finseg;
using test::slurp;
using test::spit;
using test::TempDir;

SweepSpec spec_of(const TempDir& dir, const std::string& yaml) {
  spit(dir / "s.yaml", yaml);
  return read_sweep(dir / "s.yaml");
}

TEST(Sweep, FactorialCasesVaryTheLastParameterFastest) {
  const TempDir dir;
  const SweepSpec s = spec_of(dir,
                              "scene: base.yaml\n"
                              "parameters:\n"
                              "  - {path: a.b, values: [1, x, [1, 2]]}\n"
                              "  - {path: c.0, from: 0, to: 1, steps: 3}\n");
  EXPECT_EQ(s.scene, dir / "base.yaml");
  EXPECT_EQ(s.outputs, std::vector<std::string>{"wall_time_s"});
  const auto cases = sweep_cases(s);
  ASSERT_EQ(cases.size(), 9u);
  EXPECT_EQ(cases[0][0].value, "1");
  EXPECT_EQ(cases[0][1].value, "0");
  EXPECT_EQ(cases[1][1].value, "0.5");
  EXPECT_EQ(cases[2][1].value, "1");
  EXPECT_EQ(cases[3][0].value, "x");
  EXPECT_EQ(cases[8][0].value, "[1, 2]");
  EXPECT_EQ(cases[8][1].path, "c.0");
}

TEST(Sweep, ListedCasesTakeTheKthValueOfEach) {
  const TempDir dir;
  const auto cases = sweep_cases(spec_of(dir,
                                         "scene: b.yaml\ncases: listed\nparameters:\n"
                                         "  - {path: p, values: [1, 2]}\n"
                                         "  - {path: q, values: [3, 4]}\n"));
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[1][0].value, "2");
  EXPECT_EQ(cases[1][1].value, "4");
}

TEST(Sweep, BadSweepFilesNameTheField) {
  const TempDir dir;
  const auto field_of = [&](const std::string& yaml) {
    try {
      spec_of(dir, yaml);
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(field_of("parameters: [{path: p, values: [1]}]\n"), "scene");
  EXPECT_EQ(field_of("scene: b.yaml\nparameters: []\n"), "parameters");
  EXPECT_EQ(field_of("scene: b.yaml\ncases: random\nparameters: [{path: p, values: [1]}]\n"),
            "cases");
  EXPECT_EQ(field_of("scene: b.yaml\nparameters: [{path: p, values: [1], from: 0}]\n"),
            "parameters[0].values");
  EXPECT_EQ(field_of("scene: b.yaml\ncases: listed\nparameters:\n"
                     "  - {path: p, values: [1, 2]}\n  - {path: q, values: [1]}\n"),
            "parameters[1].values");
  EXPECT_EQ(field_of("scene: b.yaml\nparameters: [{path: p, from: 0, to: 1, steps: 0}]\n"),
            "parameters[0].steps");
  EXPECT_EQ(field_of("scene: b.yaml\nparameters: [{path: p, values: [1]}]\nextra: 1\n"), "extra");
}

TEST(Sweep, SummaryValuesByDottedKey) {
  const nlohmann::json j = {{"a", {{"b", 2.5}}}, {"s", "ok"}};
  EXPECT_EQ(summary_value(j, "a.b"), 2.5);
  EXPECT_EQ(summary_value(j, "s"), "ok");
  EXPECT_TRUE(summary_value(j, "a.c").is_null());
  EXPECT_TRUE(summary_value(j, "s.x").is_null());
}

// A static cantilever c.yaml and a sweep s.yaml over its thickness (`thicknesses`, a YAML
// list; -1 is refused by the scene) and two tip forces.
void write_cantilever_sweep(const TempDir& dir, const std::string& thicknesses) {
  ASSERT_EQ(run_finseg(dir, "gen cantilever --segments 4 --tip-force 0,0,-1e-3 --out c.yaml").code,
            0);
  spit(dir / "s.yaml",
       "scene: c.yaml\n"
       "parameters:\n"
       "  - {path: sheet.thickness, values: " +
           thicknesses +
           "}\n"
           "  - {path: loads.0.force, values: [[0, 0, -1e-3], [0, 0, -2e-3]]}\n"
           "outputs: [probes.tip.final, stats.newton_iterations]\n");
}

// Four static cantilever cases, two of them with an impossible thickness: the same table with
// one job and with two, the failures recorded with finseg's message, exit status 3.
TEST(Sweep, TableIsTheSameForAnyNumberOfJobsAndKeepsFailures) {
  const TempDir dir;
  write_cantilever_sweep(dir, "[1e-4, -1]");
  const auto one = run_finseg(dir, "sweep s.yaml --out one --jobs 1");
  const auto two = run_finseg(dir, "sweep s.yaml --out two --jobs 2 --quiet");
  EXPECT_EQ(one.code, 3) << one.err;
  EXPECT_EQ(two.code, 3) << two.err;
  const std::string table = slurp(dir / "one/sweep.csv");
  EXPECT_EQ(table, slurp(dir / "two/sweep.csv"));
  const auto lines = [&] {
    std::vector<std::string> l;
    std::size_t at = 0;
    for (std::size_t nl; (nl = table.find('\n', at)) != std::string::npos; at = nl + 1) {
      l.push_back(table.substr(at, nl - at));
    }
    return l;
  }();
  ASSERT_EQ(lines.size(), 5u) << table;
  EXPECT_EQ(lines[0],
            "case,sheet.thickness,loads.0.force,status,probes.tip.final,stats.newton_iterations,"
            "message");
  EXPECT_EQ(lines[1].rfind("1,1e-4,\"[0, 0, -1e-3]\",ok,", 0), 0u) << lines[1];
  EXPECT_EQ(lines[3].rfind("3,-1,\"[0, 0, -1e-3]\",failed,,,", 0), 0u) << lines[3];
  EXPECT_NE(lines[3].find("sheet.thickness"), std::string::npos) << lines[3];
  EXPECT_NE(one.err.find("case_004 4/4 failed"), std::string::npos) << one.err;
  EXPECT_EQ(two.err, "");
}

// The same sweep serially and under `mpirun -n 2` (each rank half of the cases, rank 0 writes
// the table): the same table, byte for byte, failures included, and the same exit status.
TEST(Sweep, MpiRanksGiveTheSameTableAsTheSerialRun) {
  const TempDir dir;
  write_cantilever_sweep(dir, "[1e-4, -1, 2e-4]");
  // Tests run as root in CI; Open MPI refuses that unless told. In the sanitizer build the
  // ranks run without the leak check: Open MPI keeps allocations of its plugins until exit,
  // and once the plugins are unloaded their frames read "<unknown module>", which no
  // suppression can name. finseg's sweep code is leak-checked by the serial runs here.
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string lsan = "LSAN_OPTIONS=detect_leaks=0 ";
  const auto serial = run_finseg(dir, "sweep s.yaml --out serial --jobs 1 --quiet");
  const auto mpi = run_finseg(dir, "sweep s.yaml --out mpi",
                              lsan + "mpirun -n 2 --oversubscribe --allow-run-as-root ");
  EXPECT_EQ(serial.code, 3) << serial.err;
  EXPECT_EQ(mpi.code, 3) << mpi.err << mpi.out;
  const std::string table = slurp(dir / "serial/sweep.csv");
  EXPECT_NE(table.find("\n6,"), std::string::npos) << table;  // six cases
  EXPECT_EQ(slurp(dir / "mpi/sweep.csv"), table);
  // Both ranks ran cases: rank 1 the even-numbered folders (cases 1, 3, 5 from 0).
  EXPECT_NE(mpi.err.find("rank 0: case_001"), std::string::npos) << mpi.err;
  EXPECT_NE(mpi.err.find("rank 1: case_002"), std::string::npos) << mpi.err;
}

// The plot: the first output against the first parameter, a line per value of the others,
// only cases that ran to the end; none when no case has a number.
TEST(Sweep, PlotHasALinePerCombinationOfTheOtherParameters) {
  SweepSpec spec;
  spec.parameters = {{"a", {"1", "2"}}, {"b", {"x", "y"}}};
  spec.outputs = {"f"};
  const auto cases = sweep_cases(spec);
  std::vector<SweepCaseResult> results(4);
  for (int i = 0; i < 4; ++i) results[i].summary = {{"status", "ok"}, {"f", 10.0 * i}};
  results[3].summary["status"] = "diverged";
  const auto plot = sweep_plot_spec(spec, cases, results);
  ASSERT_TRUE(plot.has_value());
  EXPECT_EQ(plot->x_label, "a");
  ASSERT_EQ(plot->series.size(), 2u);
  EXPECT_EQ(plot->series[0].title, "b = x");
  EXPECT_EQ(plot->series[0].x, (std::vector<double>{1, 2}));
  EXPECT_EQ(plot->series[0].y, (std::vector<double>{0, 20}));
  EXPECT_EQ(plot->series[1].x, (std::vector<double>{1}));  // case 4 did not finish
  for (auto& r : results) r.summary["f"] = "text";
  EXPECT_FALSE(sweep_plot_spec(spec, cases, results).has_value());
}

}  // namespace sweep_test
}  // namespace finseg
