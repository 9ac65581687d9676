// HTML animation writer, checked without a browser: one self-contained file with the
// libraries inlined, and the embedded data reproduces the frames (positions in m, unit
// quaternions) within the stated rounding.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "writer_test_model.hpp"
#include "writers/html_animation.hpp"

namespace fs = std::filesystem;
using namespace finseg;

namespace writers_html_test {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

nlohmann::json embedded_data(const std::string& page) {
  const std::string open = "<script id=\"finseg-data\" type=\"application/json\">";
  const std::size_t a = page.find(open);
  EXPECT_NE(a, std::string::npos);
  const std::size_t b = page.find("</script>", a);
  return nlohmann::json::parse(page.substr(a + open.size(), b - a - open.size()));
}

TEST(HtmlAnimation, SelfContainedPageWithEmbeddedFrames) {
  auto s = writer_test::make_zigzag_scene(20);
  s.model.bodies[4].name = "</script><b>odd name";  // must not end the data element
  const writer_test::TempDir tmp("html_page");
  const fs::path path = tmp / "zigzag.html";
  write_html_animation(path.string(), "Zigzag <unfolding> & test", s.model, s.frames, s.curve);
  const std::string page = slurp(path);

  // Libraries are inlined, nothing is fetched: no src= or href= to anywhere.
  EXPECT_NE(page.find("REVISION=\"111\""), std::string::npos);
  EXPECT_NE(page.find("OrbitControls"), std::string::npos);
  EXPECT_NE(page.find("Chart.js v3"), std::string::npos);
  for (const std::string tag : {"<script", "<link", "<img", "<iframe"}) {
    for (std::size_t at = page.find(tag); at != std::string::npos; at = page.find(tag, at + 1)) {
      const std::string open = page.substr(at, page.find('>', at) - at);
      EXPECT_EQ(open.find("src="), std::string::npos) << open;
      EXPECT_EQ(open.find("href="), std::string::npos) << open;
    }
  }
  EXPECT_EQ(page.find("@@"), std::string::npos);
  EXPECT_NE(page.find("<title>Zigzag &lt;unfolding&gt; &amp; test</title>"), std::string::npos);
  EXPECT_FALSE(fs::exists(path.string() + ".partial"));

  const nlohmann::json d = embedded_data(page);
  EXPECT_EQ(d["title"], "Zigzag <unfolding> & test");
  EXPECT_EQ(d["bodies"]["name"][4], "</script><b>odd name");
  EXPECT_EQ(d["timeLabel"], "time [s]");
  ASSERT_EQ(d["frames"]["t"].size(), s.frames.size());
  ASSERT_EQ(d["bodies"]["panel"].size(), s.model.bodies.size());
  EXPECT_EQ(d["bodies"]["fixed"][0], 1);
  EXPECT_EQ(d["bodies"]["fixed"][5], 0);
  EXPECT_EQ(d["bodies"]["panel"][17], 5);
  EXPECT_NEAR(d["bodies"]["thickness"][0].get<double>(), 2e-4, 1e-12);
  // Outline of body 0 as x, y pairs (6 significant digits): its rectangle,
  // counter-clockwise from (-a/2, -b/2).
  const Outline& o = s.model.bodies[0].outline_B;
  ASSERT_EQ(d["bodies"]["outline"][0].size(), 2 * o.size());
  for (std::size_t k = 0; k < o.size(); ++k) {
    EXPECT_NEAR(d["bodies"]["outline"][0][2 * k].get<double>(), o[k].x(),
                5e-6 * std::abs(o[k].x()));
    EXPECT_NEAR(d["bodies"]["outline"][0][2 * k + 1].get<double>(), o[k].y(),
                5e-6 * std::abs(o[k].y()));
  }
  EXPECT_EQ(d["curve"]["xLabel"], "pull displacement [mm]");
  ASSERT_EQ(d["curve"]["y"].size(), s.frames.size());

  // The strip spans about 0.35 m: positions are kept to 1e-5 of that, quaternions to 1e-5.
  for (std::size_t f = 0; f < s.frames.size(); f += 7) {
    EXPECT_NEAR(d["frames"]["t"][f].get<double>(), s.frames[f].t, 1e-9);
    for (std::size_t b = 0; b < s.model.bodies.size(); ++b) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(d["frames"]["p"][f][3 * b + k].get<double>(), s.frames[f].p_W[b][k], 5e-6);
      }
      Eigen::Quaterniond q(d["frames"]["q"][f][4 * b + 3].get<double>(),
                           d["frames"]["q"][f][4 * b].get<double>(),
                           d["frames"]["q"][f][4 * b + 1].get<double>(),
                           d["frames"]["q"][f][4 * b + 2].get<double>());
      EXPECT_NEAR(q.norm(), 1.0, 2e-5);
      EXPECT_LT((q.normalized().toRotationMatrix() - s.frames[f].R_WB[b]).norm(), 1e-4);
    }
  }
  // Contact points appear in the second half of the frames only.
  EXPECT_EQ(d["frames"]["c"][0].size(), 0u);
  EXPECT_EQ(d["frames"]["c"][19].size(), 3u);
}

TEST(HtmlAnimation, RefusesACurveThatDoesNotMatchTheFrames) {
  auto s = writer_test::make_zigzag_scene(5);
  s.curve.x.pop_back();
  s.curve.y.pop_back();
  const writer_test::TempDir tmp("html_bad");
  const fs::path path = tmp / "bad.html";
  EXPECT_THROW(write_html_animation(path.string(), "bad", s.model, s.frames, s.curve), InputError);
  EXPECT_THROW(write_html_animation(path.string(), "bad", s.model, {}, Curve{}), InputError);
  EXPECT_FALSE(fs::exists(path));
  // An empty curve is allowed: the page then shows the 3-D view only.
  write_html_animation(path.string(), "no curve", s.model, s.frames, Curve{},
                       {"drive displacement [mm]", 1e3});
  EXPECT_TRUE(fs::exists(path));
}

TEST(HtmlAnimation, UnfinishedRunShowsABannerAndPeaksAreMarked) {
  // Former defect: the page of a diverged or interrupted run looked like a finished one.
  auto s = writer_test::make_zigzag_scene(6);
  const writer_test::TempDir tmp("html_banner");
  const fs::path path = tmp / "warned.html";
  HtmlAnnotations notes{
      "RUN DIVERGED - not finished: <step> & more", {{2.5, 0.1, "peak 0.1 N"}}, {}};
  write_html_animation(path.string(), "t", s.model, s.frames, s.curve, {}, notes);
  const std::string page = slurp(path);
  EXPECT_NE(page.find("<div id=\"runwarning\" role=\"alert\">RUN DIVERGED - not finished: "
                      "&lt;step&gt; &amp; more</div>"),
            std::string::npos);
  const nlohmann::json d = embedded_data(page);
  ASSERT_EQ(d["curve"]["marks"].size(), 1u);
  EXPECT_EQ(d["curve"]["marks"][0]["label"], "peak 0.1 N");
  EXPECT_NEAR(d["curve"]["marks"][0]["x"].get<double>(), 2.5, 0);
  // A finished run: the banner element is empty (hidden by CSS :empty).
  write_html_animation(path.string(), "t", s.model, s.frames, s.curve);
  EXPECT_NE(slurp(path).find("<div id=\"runwarning\" role=\"alert\"></div>"), std::string::npos);
  notes.marks[0].y = NAN;
  EXPECT_THROW(write_html_animation(path.string(), "t", s.model, s.frames, s.curve, {}, notes),
               InputError);
}

}  // namespace writers_html_test
