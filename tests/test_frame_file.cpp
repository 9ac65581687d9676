// The checkpoint's frame file (src/writers/frame_file.*): frames come back to the bit, a
// checkpoint appends only the frames recorded since the last one, a file of another run or
// with other times is not trusted, and a file shorter than its checkpoint says is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "writers/frame_file.hpp"

namespace finseg {
namespace frame_file_test {

namespace fs = std::filesystem;
using test::slurp;
using test::TempDir;

// A frame of `n` bodies with every field filled (NaN where a segment borders no crease).
Frame frame(double t, int n) {
  Frame f;
  f.t = t;
  for (int i = 0; i < n; ++i) {
    const double a = t + 0.1 * i;
    f.p_W.push_back({a, -a, 2 * a});
    f.R_WB.push_back(Eigen::AngleAxisd(a, Vec3(1, 2, 3).normalized()).toRotationMatrix());
    f.v_W.push_back({1, a, 0});
    f.w_W.push_back({0, 0, a});
    f.segments.force_W.push_back({a, 1, 1});
    f.segments.moment_W.push_back({1, a, 1});
    f.segments.element_force.push_back(a);
    f.segments.element_moment.push_back(2 * a);
    f.segments.crease_opening.push_back(i % 2 == 0 ? NAN : a);
    f.segments.crease_moment.push_back(i % 2 == 0 ? NAN : -a);
    f.segments.contact_normal.push_back(3 * a);
    f.segments.contact_friction.push_back(4 * a);
  }
  f.contact_points_W = {{t, 0, 0}};
  f.contact_normal = {0.5};
  f.contact_penetration = {1e-6};
  f.contact_friction = {0.1};
  return f;
}

// Bitwise equality of two arrays of doubles (NaN included).
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expect_same(const Frame& a, const Frame& b) {
  EXPECT_EQ(std::memcmp(&a.t, &b.t, sizeof(double)), 0);
  ASSERT_EQ(a.R_WB.size(), b.R_WB.size());
  for (std::size_t i = 0; i < a.R_WB.size(); ++i) EXPECT_EQ(a.R_WB[i], b.R_WB[i]);
  visit_frame_vectors(a, [&](const char* key, const std::vector<Vec3>& v) {
    visit_frame_vectors(b, [&](const char* k2, const std::vector<Vec3>& w) {
      if (std::strcmp(key, k2) == 0) {
        EXPECT_TRUE(same_bits(v, w)) << key;
      }
    });
  });
  visit_frame_arrays(a, [&](const char* key, const std::vector<double>& v) {
    visit_frame_arrays(b, [&](const char* k2, const std::vector<double>& w) {
      if (std::strcmp(key, k2) == 0) {
        EXPECT_TRUE(same_bits(v, w)) << key;
      }
    });
  });
}

TEST(FrameFile, FramesComeBackToTheBit) {
  TempDir dir;
  const std::string path = dir / "f";
  const std::vector<Frame> frames{frame(0, 5), frame(0.01, 5), frame(0.02, 5)};
  const auto bytes = sync_frame_file(path, "0123456789abcdef", frames);
  EXPECT_EQ(bytes, fs::file_size(path));
  const std::vector<Frame> back = read_frame_file(path, "0123456789abcdef", 3, bytes);
  ASSERT_EQ(back.size(), 3u);
  for (int k = 0; k < 3; ++k) expect_same(frames[k], back[k]);
}

// Each checkpoint adds the new frames after the bytes already there, which stay as written.
TEST(FrameFile, ACheckpointAppendsOnlyTheNewFrames) {
  TempDir dir;
  const std::string path = dir / "f";
  std::vector<Frame> frames{frame(0, 4), frame(0.01, 4)};
  const auto two = sync_frame_file(path, "h", frames);
  const std::string before = slurp(path);
  frames.push_back(frame(0.02, 4));
  const auto three = sync_frame_file(path, "h", frames);
  const std::string after = slurp(path);
  EXPECT_EQ(after.substr(0, two), before);
  // The third frame's record alone: a file of it alone, less its header (24 bytes).
  const auto one = sync_frame_file(dir / "g", "h", {frame(0.02, 4)});
  EXPECT_EQ(three - two, one - 24);
  EXPECT_EQ(sync_frame_file(path, "h", frames), three);  // nothing new: unchanged
  EXPECT_EQ(slurp(path), after);
}

// A file left by another run (another scene hash) is rewritten; one whose frames part from
// the run's at some time keeps the frames before and gets the run's from there.
TEST(FrameFile, AFileOfAnotherRunOrOtherTimesIsNotTrusted) {
  TempDir dir;
  const std::string path = dir / "f";
  sync_frame_file(path, "other", {frame(0, 3), frame(0.01, 3), frame(0.02, 3)});
  const std::vector<Frame> mine{frame(0, 3), frame(0.01, 3)};
  auto bytes = sync_frame_file(path, "mine", mine);
  auto back = read_frame_file(path, "mine", 2, bytes);
  EXPECT_EQ(bytes, fs::file_size(path));
  for (int k = 0; k < 2; ++k) expect_same(mine[k], back[k]);
  const std::vector<Frame> other_times{frame(0, 3), frame(0.015, 3), frame(0.03, 3)};
  bytes = sync_frame_file(path, "mine", other_times);
  back = read_frame_file(path, "mine", 3, bytes);
  for (int k = 0; k < 3; ++k) expect_same(other_times[k], back[k]);
}

// Reading cuts frames written after the checkpoint; a short file, another run's header or a
// count that does not fill the bytes are refused with the file named.
TEST(FrameFile, ReadingCutsLaterFramesAndRefusesWhatDoesNotMatch) {
  TempDir dir;
  const std::string path = dir / "f";
  const auto one = sync_frame_file(path, "h", {frame(0, 2)});
  const auto two = sync_frame_file(path, "h", {frame(0, 2), frame(0.5, 2)});
  EXPECT_EQ(read_frame_file(path, "h", 1, one).size(), 1u);
  EXPECT_EQ(fs::file_size(path), one);
  const auto message = [&](auto&& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message([&] { read_frame_file(path, "h", 2, two); }).find("holds"), std::string::npos);
  EXPECT_NE(message([&] { read_frame_file(path, "x", 1, one); }).find("(header)"),
            std::string::npos);
  EXPECT_NE(message([&] { read_frame_file(path, "h", 2, one); }).find("frame 1"),
            std::string::npos);
  EXPECT_NE(message([&] { read_frame_file(path, "h", 0, one); }).find("end at byte"),
            std::string::npos);
  EXPECT_NE(message([&] { read_frame_file(dir / "none", "h", 0, 24); }).find(dir / "none"),
            std::string::npos);
}

}  // namespace frame_file_test
}  // namespace finseg
