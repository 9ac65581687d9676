// A small hand-made model and motion for the writer tests: a strip folded in a zigzag of
// six panels (three segments each) that opens up over the frames. Lengths in m, time in s.
#pragma once

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Geometry>

#include "model/model.hpp"
#include "writers/frames.hpp"

namespace finseg::writer_test {

/// Value of the first attribute `name="..."` in `text` at or after `from` ("<missing>" if
/// none). Plain string search: std::regex trips GCC 12 warnings in the sanitizer build.
inline std::string xml_attr(const std::string& text, const std::string& name,
                            std::size_t from = 0) {
  const std::string key = " " + name + "=\"";
  const std::size_t a = text.find(key, from);
  if (a == std::string::npos) return "<missing>";
  const std::size_t b = text.find('"', a + key.size());
  return text.substr(a + key.size(), b - a - key.size());
}

/// The opening tag `<tag ...>` of the first element whose start contains `marker`.
inline std::string opening_tag(const std::string& text, const std::string& marker) {
  const std::size_t a = text.find(marker);
  if (a == std::string::npos) return "";
  const std::size_t start = text.rfind('<', a);
  return text.substr(start, text.find('>', a) - start + 1);
}

/// A fresh folder for one test's output, unique to this process (tests of several build
/// trees may run at once). Removed at the end unless FINSEG_KEEP_TEST_OUTPUT is set.
class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("finseg_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    if (!std::getenv("FINSEG_KEEP_TEST_OUTPUT")) {
      std::error_code ec;
      std::filesystem::remove_all(path_, ec);
    }
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

struct ZigzagScene {
  Model model;
  std::vector<Frame> frames;
  Curve curve;  ///< gauge force [N] against pull displacement [mm], one point per frame
};

/// Panel i rises (even i) or falls (odd i) at the fold angle a(t), which goes from 80 deg at
/// t = 0 to 20 deg at the last frame. Panels 0 and 5 are marked fixed.
inline ZigzagScene make_zigzag_scene(int num_frames = 40) {
  constexpr int kPanels = 6, kSegs = 3;
  constexpr double kPanelLength = 0.08, kWidth = 0.04, kThickness = 2e-4;  // m
  ZigzagScene s;
  s.model.source = "<writer test>";
  for (int p = 0; p < kPanels; ++p) {
    for (int k = 0; k < kSegs; ++k) {
      BodyDef b;
      b.name = fmt::format("p{}s{}", p, k);
      set_box(b, Vec3(kPanelLength / kSegs, kWidth, kThickness), 1e-3);
      b.panel = p;
      b.fixed = (p == 0 || p == kPanels - 1);
      s.model.bodies.push_back(b);
    }
  }
  s.curve.x_label = "pull displacement [mm]";
  s.curve.y_label = "gauge force [N]";
  for (int f = 0; f < num_frames; ++f) {
    const double u = num_frames > 1 ? double(f) / (num_frames - 1) : 0.0;
    const double a = (80.0 - 60.0 * u) * kDegToRad;
    Frame fr;
    fr.t = 0.05 * f;
    Vec3 start = Vec3::Zero();
    for (int p = 0; p < kPanels; ++p) {
      const double ang = (p % 2 == 0) ? -a : a;  // rotation about y: -a tilts +x upwards
      const Mat3 R = Eigen::AngleAxisd(ang, Vec3::UnitY()).toRotationMatrix();
      const Vec3 dir = R * Vec3::UnitX();
      for (int k = 0; k < kSegs; ++k) {
        fr.p_W.push_back(start + dir * (kPanelLength / kSegs) * (k + 0.5));
        fr.R_WB.push_back(R);
      }
      start += dir * kPanelLength;
    }
    if (u > 0.5) fr.contact_points_W.push_back(Vec3(0.1, 0.0, 0.01));
    s.frames.push_back(fr);
    const double d = 60.0 * u;  // mm
    s.curve.x.push_back(d);
    s.curve.y.push_back(0.8 * (1 - std::exp(-d / 15.0)) + 0.1 * std::sin(d / 6.0));
  }
  return s;
}

}  // namespace finseg::writer_test
