// The HTML animation in a real browser: Debian's chromium, headless, with the software
// WebGL renderer (SwiftShader), no network. The page must load without an error, draw the
// boxes with WebGL and play frames. If chromium is missing the test fails: scripts/setup.sh
// installs it.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "writer_test_model.hpp"
#include "writers/html_animation.hpp"

namespace fs = std::filesystem;
using namespace finseg;

namespace html_browser_test {

std::string find_chromium() {
  for (const char* name : {"chromium", "chromium-browser"}) {
    const std::string cmd = std::string("command -v ") + name + " 2>/dev/null";
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) continue;
    char buf[512] = {0};
    const bool got = std::fgets(buf, sizeof buf, p) != nullptr;
    pclose(p);
    if (got) {
      std::string path(buf);
      while (!path.empty() && (path.back() == '\n' || path.back() == '\r')) path.pop_back();
      return path;
    }
  }
  return "";
}

/// Runs chromium headless on `url` and returns what it printed on stdout.
std::string run_chromium(const std::string& chromium, const fs::path& profile,
                         const std::string& extra_args, const std::string& url, int& status) {
  const std::string cmd =
      "timeout 60 '" + chromium + "' --headless --no-sandbox --disable-gpu " +
      "--use-gl=angle --use-angle=swiftshader --enable-unsafe-swiftshader " +
      "--disable-background-networking --disable-component-update --disable-sync " +
      "--disable-default-apps --no-first-run --no-default-browser-check " +
      "--disable-extensions --mute-audio --window-size=1280,800 --user-data-dir='" +
      profile.string() + "' " + extra_args + " '" + url + "' 2>/dev/null";
  std::string out;
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) {
    status = -1;
    return out;
  }
  char buf[8192];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  const int rc = pclose(p);
  status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  return out;
}

std::string attr_of_status(const std::string& dom, const std::string& name) {
  const std::string tag = writer_test::opening_tag(dom, "id=\"status\"");
  return tag.empty() ? "<no status>" : writer_test::xml_attr(tag, name);
}

TEST(HtmlAnimationInBrowser, RendersAndPlaysInHeadlessChromium) {
  const std::string chromium = find_chromium();
  ASSERT_FALSE(chromium.empty())
      << "chromium is not installed; run scripts/setup.sh (Debian package 'chromium')";

  const writer_test::TempDir tmp("html_browser");
  const fs::path dir = tmp.path();
  const auto s = writer_test::make_zigzag_scene(40);
  const fs::path page = dir / "zigzag.html";
  // With a run-status banner and a chart mark, so that their code runs in the browser too.
  const HtmlAnnotations notes{
      "RUN INTERRUPTED - not finished", {{s.curve.x[10], s.curve.y[10], "deployment peak"}}, {}};
  write_html_animation(page.string(), "Zigzag strip (browser test)", s.model, s.frames, s.curve,
                       FrameAxis{}, notes);

  int status = 0;
  const std::string dom =
      run_chromium(chromium, dir / "profile", "--virtual-time-budget=3000 --dump-dom",
                   "file://" + page.string() + "?selftest=1", status);
  ASSERT_EQ(status, 0) << "chromium failed";
  ASSERT_NE(dom.find("id=\"status\""), std::string::npos) << dom.substr(0, 2000);

  EXPECT_EQ(attr_of_status(dom, "data-error"), "");
  EXPECT_EQ(attr_of_status(dom, "data-frames"), "40");
  EXPECT_NE(dom.find("role=\"alert\">RUN INTERRUPTED - not finished</div>"), std::string::npos);
  // Playing: the clock advanced frames (30 frames/s for about 3 s of virtual time).
  EXPECT_GT(std::stoi(attr_of_status(dom, "data-advanced")), 10);
  EXPECT_EQ(attr_of_status(dom, "data-playing"), "1");
  EXPECT_GT(std::stoi(attr_of_status(dom, "data-rendered")), 10);
  // WebGL drew the boxes: many pixels differ from the background.
  EXPECT_GT(std::stoi(attr_of_status(dom, "data-drawn")), 2000);
  // The chart is there and the readout names units.
  EXPECT_NE(dom.find("gauge force against pull displacement"), std::string::npos);
  const std::string clock_open = "<div class=\"overlay\" id=\"clock\">time ";
  const std::size_t clock = dom.find(clock_open);
  ASSERT_NE(clock, std::string::npos);
  const std::string reading = dom.substr(clock + clock_open.size(), 12);
  EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(reading[0]))) << reading;
  EXPECT_NE(reading.find(" s<"), std::string::npos) << reading;
}

}  // namespace html_browser_test
