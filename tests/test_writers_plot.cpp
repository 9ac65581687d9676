// gnuplot writer: real PNG and SVG files with the data and script beside them; gnuplot's
// own complaint comes back in the exception.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "writer_test_model.hpp"
#include "writers/plot.hpp"

namespace fs = std::filesystem;
using namespace finseg;

namespace writers_plot_test {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

PlotSpec sample_spec() {
  PlotSpec spec;
  spec.title = "Pull force, condition 1 (80 deg, low stiffness)";
  spec.x_label = "pull displacement [mm]";
  spec.y_label = "gauge force [N]";
  PlotSeries sim{"simulation", {}, {}, "lines"}, exp{"experiment mean", {}, {}, "points"};
  for (int i = 0; i <= 60; ++i) {
    const double d = i;
    sim.x.push_back(d);
    sim.y.push_back(0.8 * (1 - std::exp(-d / 15.0)) + 0.1 * std::sin(d / 6.0));
    if (i % 4 == 0) {
      exp.x.push_back(d);
      exp.y.push_back(sim.y.back() * 1.04 + 0.01);
    }
  }
  spec.series = {sim, exp};
  spec.markers = {{12.0, "contact begins"}, {38.0, "panels 2 and 5 bend"}};
  return spec;
}

TEST(PlotWriter, WritesAPngWithDataAndScriptBeside) {
  const writer_test::TempDir tmp("plot_png");
  const fs::path png = tmp / "force.png";
  write_plot(png.string(), sample_spec());
  const std::string bytes = slurp(png);
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  // IHDR width and height, big-endian: the terminal size 1200 x 750.
  auto be32 = [&](std::size_t at) {
    return (unsigned(static_cast<unsigned char>(bytes[at])) << 24) |
           (unsigned(static_cast<unsigned char>(bytes[at + 1])) << 16) |
           (unsigned(static_cast<unsigned char>(bytes[at + 2])) << 8) |
           unsigned(static_cast<unsigned char>(bytes[at + 3]));
  };
  EXPECT_EQ(bytes.substr(12, 4), "IHDR");
  EXPECT_EQ(be32(16), 1200u);
  EXPECT_EQ(be32(20), 750u);
  const std::string dat = slurp(png.string() + ".dat");
  EXPECT_NE(dat.find("pull displacement [mm]"), std::string::npos);
  EXPECT_NE(dat.find("38 "), std::string::npos);
  const std::string gp = slurp(png.string() + ".gp");
  EXPECT_NE(gp.find("pngcairo"), std::string::npos);
  EXPECT_NE(gp.find("'contact begins'"), std::string::npos);
  EXPECT_FALSE(fs::exists(png.string() + ".partial"));
}

TEST(PlotWriter, WritesAnSvgWithTitleAndLabels) {
  const writer_test::TempDir tmp("plot_svg");
  const fs::path svg = tmp / "force.svg";
  PlotSpec spec = sample_spec();
  spec.title = "Tom's force <test> & more";  // quote and XML characters survive
  write_plot(svg.string(), spec);
  const std::string text = slurp(svg);
  EXPECT_NE(text.find("<svg"), std::string::npos);
  // gnuplot escapes < and & (a bare > is valid XML text).
  EXPECT_TRUE(text.find("Tom's force &lt;test&gt; &amp; more") != std::string::npos ||
              text.find("Tom's force &lt;test> &amp; more") != std::string::npos);
  EXPECT_NE(text.find("gauge force [N]"), std::string::npos);
  EXPECT_NE(text.find("panels 2 and 5 bend"), std::string::npos);
}

TEST(PlotWriter, ReportsGnuplotErrorsAndBadInput) {
  const writer_test::TempDir tmp("plot_bad");
  const fs::path png = tmp / "broken.png";
  PlotSpec spec = sample_spec();
  for (auto& s : spec.series) {
    s.x.clear();
    s.y.clear();
  }
  try {
    write_plot(png.string(), spec);
    FAIL() << "gnuplot accepted a plot without any data";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("gnuplot failed"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(png));
  EXPECT_FALSE(fs::exists(png.string() + ".partial"));

  EXPECT_THROW(write_plot((tmp / "x.pdf").string(), sample_spec()), std::invalid_argument);
  spec = sample_spec();
  spec.series[0].y.pop_back();
  EXPECT_THROW(write_plot(png.string(), spec), std::invalid_argument);
  spec = sample_spec();
  spec.series[0].style = "lines; system 'touch /tmp/x'";
  EXPECT_THROW(write_plot(png.string(), spec), std::invalid_argument);
}

TEST(PlotWriter, UnfinishedRunBannerBandAndPeakPoints) {
  // Former defect: the plot of a diverged or interrupted run looked like a finished one.
  const writer_test::TempDir tmp("plot_warning");
  PlotSpec spec = sample_spec();
  spec.warning = "RUN INTERRUPTED - not finished, results end early";
  spec.points = {{20.0, 0.7, "deployment peak 0.7 N"}, {58.0, 0.8, "largest force 0.8 N", false}};
  PlotBand band{"measured spread", {}, {}, {}};
  for (double x : spec.series[0].x) {
    band.x.push_back(x);
    band.lower.push_back(0.1);
    band.upper.push_back(0.2);
  }
  spec.bands = {band};
  const fs::path svg = tmp / "warned.svg";
  write_plot(svg.string(), spec);
  const std::string text = slurp(svg);
  EXPECT_NE(text.find("RUN INTERRUPTED"), std::string::npos);
  EXPECT_NE(text.find("deployment peak 0.7 N"), std::string::npos);
  EXPECT_NE(text.find("largest force 0.8 N"), std::string::npos);
  const std::string gp = slurp(svg.string() + ".gp");
  EXPECT_NE(gp.find("filledcurves"), std::string::npos);
  // The band is block 0, the series follow it.
  EXPECT_NE(gp.find("index 0 using 1:2:3"), std::string::npos);
  EXPECT_NE(gp.find("index 1 using 1:2 with lines"), std::string::npos);
  // Point labels face the middle: the right-hand one is right-aligned, the other left.
  EXPECT_NE(gp.find("'largest force 0.8 N' at 58, 0.8 right"), std::string::npos) << gp;
  EXPECT_NE(gp.find("'deployment peak 0.7 N' at 20, 0.7 left"), std::string::npos) << gp;
  // Legend outside the data area.
  EXPECT_NE(gp.find("set key outside"), std::string::npos);
  spec.bands[0].upper.pop_back();
  EXPECT_THROW(write_plot(svg.string(), spec), std::invalid_argument);
}

}  // namespace writers_plot_test
