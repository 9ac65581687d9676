// Provenance: `finseg --version`, SHA-256 against the FIPS 180-2 test vectors, and a run's
// summary.json recording version, revision, date, the hashes of the scene and of its crease
// CSV, every warning, and the new crease/pose probes' files.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_test_util.hpp"
#include "core/blas_kernels.hpp"
#include "core/version.hpp"
#include "test_paths.hpp"
#include "writers/provenance.hpp"

namespace finseg {
namespace provenance_test {

using test::run_finseg;
using test::slurp;
using test::spit;
using test::TempDir;

// `pattern` with '9' standing for any digit and 'f' for any lowercase hex digit.
bool matches(const std::string& s, const std::string& pattern) {
  if (s.size() != pattern.size()) return false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const bool digit = c >= '0' && c <= '9';
    if (pattern[i] == '9'   ? !digit
        : pattern[i] == 'f' ? !(digit || (c >= 'a' && c <= 'f'))
                            : c != pattern[i]) {
      return false;
    }
  }
  return true;
}

TEST(Provenance, Sha256MatchesTheStandardTestVectors) {
  const TempDir dir;
  spit(dir / "abc", "abc");
  EXPECT_EQ(sha256_file(dir / "abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  spit(dir / "empty", "");
  EXPECT_EQ(sha256_file(dir / "empty"),
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_THROW(sha256_file(dir / "missing"), std::runtime_error);
}

TEST(Provenance, VersionFlagPrintsVersionAndRevision) {
  const TempDir dir;
  const auto r = run_finseg(dir, "--version");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "finseg " + version() + " (git " + git_revision() + ")\n");
  EXPECT_TRUE(git_revision() == "unknown" || matches(git_revision(), std::string(40, 'f')));
  EXPECT_FALSE(version().empty());
}

// The revision is the checkout's HEAD when the program was built (stamped at every build, so a
// build tree rebuilt after new commits does not report the commit it was configured at).
TEST(Provenance, RevisionIsTheBuiltCheckoutsHead) {
  const TempDir dir;
  const std::string head = dir / "head";
  const std::string cmd = "git -C \"" + std::string(FINSEG_SOURCE_DIR) + "\" rev-parse HEAD > \"" +
                          head + "\" 2>/dev/null";
  std::string expected = "unknown";  // not a checkout (a source archive)
  if (std::system(cmd.c_str()) == 0) {
    expected = slurp(head);
    while (!expected.empty() && expected.back() == '\n') expected.pop_back();
  }
  EXPECT_EQ(git_revision(), expected);
}

// A two-panel sheet folded 170 deg with the example crease table (copied into `dir`); its
// opening angle 10 deg is below the data's 30 deg, so the law warns.
std::string folded_sheet_scene(const TempDir& dir, const std::string& solver) {
  std::filesystem::copy_file(std::string(FINSEG_SOURCE_DIR) + "/examples/creases/creases.csv",
                             dir / "creases.csv");
  return R"(material: {youngs_modulus: 3e9, density: 800}
sheet:
  length: 0.1
  width: 0.02
  thickness: 1e-4
  folds: [{s: 0.05, angle_deg: 170, law: {type: measured, file: creases.csv, pressing_time: 300}}]
discretisation: {segments: 2}
fixtures: {panels: [1]}
probes:
  - {name: fold, type: crease, crease: 1}
  - {name: tip, type: pose, body: seg_r0_s3}
solver: )" +
         solver + "\n";
}

TEST(Provenance, SummaryRecordsHashesDateWarningsAndNewProbes) {
  const TempDir dir;
  spit(dir / "s.yaml", folded_sheet_scene(dir, "{type: static}"));
  const auto r = run_finseg(dir, "run s.yaml --out out --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(dir / "out/summary.json"));
  const auto& p = j.at("provenance");
  EXPECT_EQ(p.at("finseg_version"), version());
  EXPECT_EQ(p.at("git_revision"), git_revision());
  // The kernels the run's BLAS ran: the CPU's own where OpenBLAS fell back to Prescott's
  // (core/blas_kernels.hpp), as in this process once it has factored.
  use_cpu_blas_kernels();
  EXPECT_EQ(p.at("blas_kernels"), blas_kernels());
  EXPECT_TRUE(matches(p.at("date_utc").get<std::string>(), "9999-99-99T99:99:99Z"))
      << p.at("date_utc");
  EXPECT_EQ(p.at("scene").at("file"), "s.yaml");
  EXPECT_EQ(p.at("scene").at("sha256"), sha256_file(dir / "s.yaml"));
  ASSERT_EQ(p.at("data_files").size(), 1u);
  EXPECT_EQ(p.at("data_files")[0].at("sha256"), sha256_file(dir / "creases.csv"));
  bool warned = false;
  for (const auto& w : j.at("warnings")) {
    warned = warned || w.get<std::string>().find("outside the measured") != std::string::npos;
  }
  EXPECT_TRUE(warned) << j.at("warnings").dump();
  EXPECT_NE(r.err.find("finseg: warning: crease law"), std::string::npos);
  EXPECT_EQ(j.at("probes").at("fold").at("type"), "crease");
  EXPECT_EQ(j.at("probes").at("tip").at("type"), "pose");
  const std::string csv = slurp(dir / "out/fold.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "load_scale,fold_angle_deg,opening_angle_deg,moment_Nm");
}

// The checkpoint's scene hash covers the crease table: editing the table refuses --resume.
TEST(Provenance, ResumeRefusesACheckpointWhoseCreaseTableChanged) {
  const TempDir dir;
  // The automatic step (6.9e-6 s): a fixed 1e-5 s is past the explicit limit of this sheet.
  spit(dir / "s.yaml", folded_sheet_scene(dir, "{type: explicit, t_end: 2e-3}"));
  ASSERT_EQ(run_finseg(dir, "run s.yaml --out out --quiet").code, 0);
  EXPECT_EQ(run_finseg(dir, "run s.yaml --out out --quiet --resume").code, 0);
  spit(dir / "creases.csv", slurp(dir / "creases.csv") + "\n");
  const auto r = run_finseg(dir, "run s.yaml --out out --quiet --resume");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("crease data changed"), std::string::npos) << r.err;
}

}  // namespace provenance_test
}  // namespace finseg
