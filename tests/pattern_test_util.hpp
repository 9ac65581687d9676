// Small crease patterns written by hand for the FOLD tests, and a check that a FOLD text is
// refused with the expected file, field and reason.
#pragma once

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli_test_util.hpp"
#include "core/error.hpp"
#include "patterns/fold_format.hpp"

namespace finseg::test {

/// Two unit squares side by side (mm), a valley crease at 90 degrees between them:
///   5 --- 4 --- 3
///   |  0  |  1  |
///   0 --- 1 --- 2
inline nlohmann::json two_squares() {
  return nlohmann::json::parse(R"({
    "file_spec": 1.1, "file_creator": "hand", "frame_unit": "mm",
    "vertices_coords": [[0,0], [1,0], [2,0], [2,1], [1,1], [0,1]],
    "faces_vertices": [[0,1,4,5], [1,2,3,4]],
    "edges_vertices": [[0,1], [1,2], [2,3], [3,4], [4,5], [5,0], [1,4]],
    "edges_assignment": ["B", "B", "B", "B", "B", "B", "V"],
    "edges_foldAngle": [0, 0, 0, 0, 0, 0, 90]})");
}

/// Writes `fold` to bad.fold in `dir`, reads it and expects InputError naming that file,
/// exactly `field`, and a message containing `why`.
inline void expect_refused(const TempDir& dir, const nlohmann::json& fold, const std::string& field,
                           const std::string& why, std::optional<double> unit = {}) {
  const std::string path = dir / "bad.fold";
  spit(path, fold.dump(1));
  try {
    read_fold(path, unit);
    ADD_FAILURE() << "accepted; expected " << field << ": " << why;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
  }
}

}  // namespace finseg::test
