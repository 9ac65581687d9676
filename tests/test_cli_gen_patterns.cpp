// finseg gen miura / gen cone through the command line: the FOLD file and scene they write
// read back; "fold once, deploy many times": a Miura sheet folded from flat by
// `run --fold` (face 1 clamped flat) reaches the pattern's own folded form (which gen miura
// places with face 1 where it lies flat), and a run started from that state file pulls it
// open along the same force curve as a run from the pattern's folded form.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_test_util.hpp"
#include "core/types.hpp"

namespace finseg {
namespace cli_gen_patterns_test {

using test::run_finseg;
using test::TempDir;

std::vector<Vec3> centroids(const TempDir& dir, const std::string& state_file) {
  return test::state_centres(dir / state_file);
}

TEST(CliGenPatterns, MiuraFoldedFromFlatReachesItsFoldedFormAndDeploysFromTheStateFile) {
  TempDir dir;
  auto r = run_finseg(dir, "gen miura --rows 2 --columns 4 --fold-angle 60 --out m.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  // The pattern's folded form at rest (no pull): the reference.
  r = run_finseg(dir, "run m.yaml --quiet --set drives.0.travel=0 --out ref");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "run m.yaml --quiet --fold --set pattern.start=flat --out folded");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<Vec3> a = centroids(dir, "ref/checkpoint.json");
  const std::vector<Vec3> b = centroids(dir, "folded/checkpoint.json");
  ASSERT_EQ(a.size(), b.size());
  double worst = 0, extent = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    extent = std::max(extent, (a[i] - a[0]).norm());
    worst = std::max(worst, (a[i] - b[i]).norm());
  }
  EXPECT_GT(extent, 0.02);
  EXPECT_LT(worst, 1e-9 * extent);
  // Deploy from the folded state: the drive starts where its point is, so the gauge starts
  // slack and pulls while the creases resist.
  r = run_finseg(dir, "run m.yaml --quiet --state folded/checkpoint.json --out deploy");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "run m.yaml --quiet --out direct");
  ASSERT_EQ(r.code, 0) << r.err;
  std::string header;
  const auto rows = test::csv_rows(test::slurp(dir / "deploy/pull.csv"), &header);
  const auto direct = test::csv_rows(test::slurp(dir / "direct/pull.csv"), &header);
  ASSERT_GT(rows.size(), 10u);
  ASSERT_EQ(rows.size(), direct.size());
  EXPECT_NEAR(rows.front()[1], 0.0, 1e-9);
  EXPECT_GT(rows.back()[1], 0.0);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_NEAR(rows[k][1], direct[k][1], 1e-6 * std::abs(direct.back()[1])) << "row " << k;
  }
}

TEST(CliGenPatterns, ConeSceneReadsBackAndBadOptionsAreRefused) {
  TempDir dir;
  auto r = run_finseg(dir,
                      "gen cone --fan-fold --top disc --base disc --pleats 6 --axial-folds 2 "
                      "--subdivisions 1 --out c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  // The pattern reads back (faces planar when folded, seams meeting in 3-D): 2 x 6 + 1
  // wedges (two half facets at the seam) in 3 bands, and two end discs of a 13-sided hub (a
  // fan of 13 triangles) and 13 trapezoids; the base hub clamped.
  r = run_finseg(dir, "inspect c.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("bodies 91 (13 fixed)"), std::string::npos) << r.out;
  // Both ends open: the wall alone, one face of the base band clamped.
  r = run_finseg(dir,
                 "gen cone --fan-fold --pleats 6 --axial-folds 2 --subdivisions 1 --top open "
                 "--base open --fold-steps 10 --out o.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "inspect o.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("bodies 39 (1 fixed)"), std::string::npos) << r.out;
  // The force check at its start: the force Jacobian agrees with central differences of the
  // forces everywhere (solvers/force_check.hpp).
  r = run_finseg(dir, "inspect o.yaml --check-forces");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("every entry agrees"), std::string::npos) << r.out;
  // From the fan stack (open ends only): the pattern's folded form reads back (planar faces,
  // the seam closed).
  r = run_finseg(dir,
                 "gen cone --pleats 6 --axial-folds 2 --subdivisions 1 --top open "
                 "--base open --stowed 150 --out st.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "inspect st.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("bodies 39 (1 fixed)"), std::string::npos) << r.out;
  // Gathered (open ends only), pulled or inflated: the scenes read back (the chamber closes,
  // by fixed end plates or by caps).
  for (const char* extra : {"", " --inflate", " --inflate --caps"}) {
    r = run_finseg(dir,
                   std::string("gen cone --pleats 6 --axial-folds 2 --subdivisions 1 --top open "
                               "--base open --gathered 0.8 --out ga.yaml") +
                       extra);
    ASSERT_EQ(r.code, 0) << r.err;
    r = run_finseg(dir, "inspect ga.yaml");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("bodies 39 (1 fixed)"), std::string::npos) << r.out;
  }
  // With caps the chamber is the gathered wall closed at its own end rings: no plates, and
  // less air in it than in the deployed frustum (the generated inflator's volume).
  const std::string capped = test::slurp(dir / "ga.yaml");
  EXPECT_NE(capped.find("cap_open_ends: true"), std::string::npos) << capped;
  EXPECT_EQ(capped.find("end_plates"), std::string::npos) << capped;
  r = run_finseg(dir,
                 "run ga.yaml --out gc --set solver.t_end=0.001 --set outputs.vtk=false "
                 "--set outputs.html=false --set outputs.plot=false");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string gas = test::slurp(dir / "gc/chamber_cone.csv");
  const auto first = gas.find('\n') + 1;  // t = 0: t, pressure, volume, ...
  const double volume = std::stod(gas.substr(gas.find(',', gas.find(',', first) + 1) + 1));
  const auto frustum = capped.find("kg: the deployed volume, ");
  ASSERT_NE(frustum, std::string::npos) << capped;
  EXPECT_GT(volume, 0);
  EXPECT_LT(volume, std::stod(capped.substr(frustum + 25)));
  expect_refused(dir, "gen cone --top open --base open --gathered 0.5 --caps --out l.yaml",
                 "--caps");
  for (const char* bad : {"--top disc --gathered 0.5", "--top open --base open --gathered 1",
                          "--top open --base open "
                          "--gathered -0.1",
                          "--top open --base open --gathered 0.5 --stowed 150"}) {
    expect_refused(dir, std::string("gen cone ") + bad + " --out l.yaml", "--gathered");
  }
  // Cut to a target segment size graded towards the folds: the scene says so and reads back
  // with more segments than one per face.
  r = run_finseg(dir,
                 "gen cone --pleats 6 --axial-folds 2 --top open --base open "
                 "--segment-size 0.03 --crease-refinement 2 --out sz.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(test::slurp(dir / "sz.yaml").find("segment_size: 0.03"), std::string::npos);
  EXPECT_NE(test::slurp(dir / "sz.yaml").find("crease_refinement: 2"), std::string::npos);
  r = run_finseg(dir, "inspect sz.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto at = r.out.find("bodies ");
  ASSERT_NE(at, std::string::npos) << r.out;
  EXPECT_GT(std::stoi(r.out.substr(at + 7)), 39) << r.out;
  for (const auto& [bad, field] : {std::pair{"--segment-size -0.01", "--segment-size"},
                                   {"--subdivisions 2 --segment-size 0.01", "--segment-size"},
                                   {"--crease-refinement 0.5", "--crease-refinement"}}) {
    expect_refused(dir, std::string("gen cone --top open --base open ") + bad + " --out l.yaml",
                   field);
  }
  expect_refused(dir, "gen cone --top open --base open --inflate --out l.yaml", "--inflate");
  for (const char* bad : {"--stowed 150", "--gathered 0.5", "--fold-to-gathered 0.5"}) {
    expect_refused(dir,
                   std::string("gen cone --top open --base open --wrap ") + bad + " --out l.yaml",
                   "--wrap");
  }
  // The wrap assignment's scene says so in its header, and its pattern reads back.
  ASSERT_EQ(run_finseg(dir,
                       "gen cone --fan-fold --wrap --pleats 3 --axial-folds 1 "
                       "--subdivisions 1 --out w.yaml")
                .code,
            0);
  EXPECT_NE(test::slurp(dir / "w.yaml").find("--wrap: pleats + 1 mountains"), std::string::npos);
  EXPECT_EQ(run_finseg(dir, "inspect w.yaml").code, 0);
  for (const char* bad : {"--base disc --stowed 150", "--top open --base open --stowed 181"}) {
    expect_refused(dir, std::string("gen cone ") + bad + " --out l.yaml", "--stowed");
  }
  expect_refused(dir, "gen cone --top lid --out l.yaml", "--top");
  // With no start chosen the wall is gathered by folding; the end discs, the wrap and the
  // fold fraction belong to the fan fold alone, which takes no other start.
  ASSERT_EQ(
      run_finseg(dir, "gen cone --pleats 3 --axial-folds 1 --subdivisions 1 --out d.yaml").code, 0);
  EXPECT_NE(test::slurp(dir / "d.yaml").find("title: cone gathered by folding"), std::string::npos);
  for (const auto& [bad, field] : {std::pair{"--top disc", "--top"},
                                   {"--base disc", "--base"},
                                   {"--wrap", "--wrap"},
                                   {"--fold-fraction 0.5", "--fold-fraction"},
                                   {"--fan-fold --gathered 0.5", "--fan-fold"},
                                   {"--fan-fold --fold-to-gathered 0.5", "--fan-fold"}}) {
    expect_refused(dir, std::string("gen cone ") + bad + " --out l.yaml", field);
  }
  expect_refused(dir, "gen cone --fold-steps -1 --out l.yaml", "--fold-steps");
  expect_refused(dir, "gen cone --top-radius 0.2 --base-radius 0.1 --out d.yaml", "--top-radius");
  expect_refused(dir, "gen miura --sector-angle 95 --out e.yaml", "--sector-angle");
  expect_refused(dir, "gen miura --fold-angle 0 --out e.yaml", "--fold-angle");  // nothing to fold
  // A sheet folded less than the 15 degrees the pull opens it to is opened to half its fold
  // angle (the scene's travel was negative, refused by the reader).
  r = run_finseg(dir, "gen miura --fold-angle 1 --out m1.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  r = run_finseg(dir, "inspect m1.yaml");
  EXPECT_EQ(r.code, 0) << r.err;
}

// Stowed by reflection (`--reflected F`, docs/folding.md): the pattern's folded form is the
// stowed wall and reads back (planar faces, the seam closed); the run starts with contact on
// and no point touching, its apex pulled along the axis (every whole facet of the top band
// drawn up, every whole facet of the base band pinned by a gauge that does not travel, nothing
// clamped, one probe for the top); inflated, by strings drawing both ends apart while gas
// fills it, with triangle cells too; bad combinations are refused.
TEST(CliGenPatterns, ConeStowedByReflectionReadsBackStartsApartAndBadOptionsAreRefused) {
  TempDir dir;
  auto r = run_finseg(dir,
                      "gen cone --pleats 6 --axial-folds 2 --subdivisions 1 --top open "
                      "--base open --reflected 0.5 --out re.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string pulled = test::slurp(dir / "re.yaml");
  EXPECT_NE(pulled.find("{name: top11, at:"), std::string::npos) << pulled;  // 2 x 6 - 1 facets
  EXPECT_EQ(pulled.find("{name: top12, at:"), std::string::npos) << pulled;
  EXPECT_NE(pulled.find("{name: base11, at:"), std::string::npos) << pulled;
  EXPECT_NE(pulled.find("travel: 0, step: 0, speed: 0}"), std::string::npos) << pulled;
  EXPECT_NE(pulled.find("{name: top, type: drive, drives: [top1, top2,"), std::string::npos);
  EXPECT_EQ(pulled.find("{name: base, type: drive"), std::string::npos) << pulled;
  EXPECT_EQ(pulled.find("fixtures"), std::string::npos) << pulled;
  r = run_finseg(dir, "inspect re.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("bodies 39 (0 fixed)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("drives 22, probes 5"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  shape deployed ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("probe shape (distance from shape deployed)"), std::string::npos) << r.out;
  r = run_finseg(dir,
                 "run re.yaml --out d --set solver.t_end=0.02 --set outputs.vtk=false "
                 "--set outputs.html=false --set outputs.plot=false");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string contact = test::slurp(dir / "d/contact.csv");
  const auto row = contact.find('\n') + 1;  // t = 0: no active point
  EXPECT_EQ(contact.substr(row, contact.find('\n', row) - row).substr(0, 4), "0,0,") << contact;
  // The apex resists being drawn up (pull_displacement_m, force_N, .., force_z_N, ..): the pins
  // hold the base, the top's gauges pull along +z.
  {
    std::string header;
    const auto rows = test::csv_rows(test::slurp(dir / "d/top.csv"), &header);
    ASSERT_FALSE(rows.empty());
    const double travel = std::stod(pulled.substr(pulled.find("travel: ") + 8));
    EXPECT_NEAR(rows.back()[0], 0.02 * travel, 1e-9);  // at t = 0.02 s of 1 s
    EXPECT_GT(rows.back()[1], 0);
    EXPECT_GT(rows.back()[4], 0);
  }
  {
    // The shape probe on the pattern's "deployed" frame: the pull brings the wall nearer.
    std::string header;
    const auto rows = test::csv_rows(test::slurp(dir / "d/shape.csv"), &header);
    ASSERT_EQ(header, "t_s,rms_distance_m,largest_distance_m");
    ASSERT_GE(rows.size(), 2u);
    EXPECT_LT(rows.back()[1], rows.front()[1]);
  }
  {
    // The unfolding probe towards the same frame: one column per crease line (FOLD edge), and
    // the pull has begun to open them (none half way in 20 ms).
    std::string header;
    const auto rows = test::csv_rows(test::slurp(dir / "d/unfolding.csv"), &header);
    ASSERT_EQ(header.substr(0, 40), "t_s,lines_half_open,mean_opening,edge1_d");
    ASSERT_GE(rows.size(), 2u);
    EXPECT_EQ(rows.front()[2], 0);
    EXPECT_GT(rows.back()[2], 0);
    const std::string order = test::slurp(dir / "d/unfolding_order.csv");
    EXPECT_EQ(order.substr(0, order.find('\n')),
              "rank,line,start_deg,target_deg,final_deg,final_opening,half_open_t_s,open_90_t_s,"
              "flat_x_m,flat_y_m");
  }
  // Inflated (--inflate): the wall closed by caps is filled while strings (free across the
  // axis) draw its ends apart, nothing clamped; in its first 20 ms the gas enters and the wall
  // grows.
  r = run_finseg(dir,
                 "gen cone --pleats 6 --axial-folds 2 --subdivisions 1 --top open "
                 "--base open --reflected 0.5 --inflate --out ri.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string inflated = test::slurp(dir / "ri.yaml");
  EXPECT_NE(inflated.find("chambers:"), std::string::npos);
  EXPECT_NE(inflated.find("cap_open_ends: true"), std::string::npos) << inflated;
  EXPECT_EQ(inflated.find("fixtures"), std::string::npos) << inflated;
  EXPECT_NE(inflated.find("t_end: 1.3"), std::string::npos) << inflated;
  std::size_t strings = 0;
  for (auto at = inflated.find("lateral_stiffness: 0,"); at != std::string::npos;
       at = inflated.find("lateral_stiffness: 0,", at + 1)) {
    ++strings;
  }
  EXPECT_EQ(strings, 22u);
  r = run_finseg(dir, "inspect ri.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("bodies 39 (0 fixed)"), std::string::npos) << r.out;
  r = run_finseg(dir,
                 "run ri.yaml --out i --set solver.t_end=0.02 --set outputs.vtk=false "
                 "--set outputs.html=false --set outputs.plot=false");
  ASSERT_EQ(r.code, 0) << r.err;
  {
    std::string header;
    const auto rows = test::csv_rows(test::slurp(dir / "i/chamber_cone.csv"), &header);
    ASSERT_GE(rows.size(), 2u);  // t_s, pressure_Pa, volume_m3, mass_kg, ...
    EXPECT_GT(rows.back()[3], 0);
    EXPECT_GT(rows.back()[2], rows.front()[2]);
  }
  // Triangle cells (--cells triangles): four a face, seams and chamber as before.
  r = run_finseg(dir,
                 "gen cone --pleats 6 --axial-folds 2 --subdivisions 1 --top open "
                 "--base open --reflected 0.5 --inflate --cells triangles --out rt.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(test::slurp(dir / "rt.yaml").find("cells: triangles"), std::string::npos);
  r = run_finseg(dir, "inspect rt.yaml");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("bodies 156 (0 fixed)"), std::string::npos) << r.out;
  expect_refused(dir, "gen cone --cells hexagons --out l.yaml", "--cells");
  for (const char* bad : {"--top disc --reflected 0.5", "--top open --base open --reflected 1",
                          "--top open --base open --reflected -0.2",
                          "--top open --base open --reflected 0.5 --gathered 0.5"}) {
    expect_refused(dir, std::string("gen cone ") + bad + " --out l.yaml", "--reflected");
  }
  expect_refused(dir, "gen cone --top open --base open --reflected 0.5 --wrap --out l.yaml",
                 "--wrap");
}

}  // namespace cli_gen_patterns_test
}  // namespace finseg
