// The landmark files `lacrima track` reads (tools/src/landmark_io.hpp): lacrima's CSV, OpenFace's
// CSV and JSON give the same points; missing ones are NaN; malformed files name the file and the
// line or JSON pointer.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "lacrima/base/error.hpp"
#include "landmark_io.hpp"
#include "support/test_directory.hpp"

namespace lacrima::cli {
namespace landmark_io_test {

namespace fs = std::filesystem;

// Landmark l of frame f at (10 f + l, 100 + l); landmark 5 of frame 2 missing.
Eigen::Vector2d expectedPoint(int frame, size_t l) { return Eigen::Vector2d(10.0 * frame + double(l), 100.0 + double(l)); }

void expectTheTwoFrames(const LandmarkTrack& track) {
  ASSERT_EQ(track.size(), 2u);
  for (int frame : {1, 2}) {
    ASSERT_EQ(track.at(frame).size(), 68u);
    for (size_t l = 0; l < 68; ++l) {
      if (frame == 2 && l == 5) {
        EXPECT_FALSE(track.at(frame)[l].allFinite()) << "missing";
        continue;
      }
      EXPECT_TRUE(track.at(frame)[l].isApprox(expectedPoint(frame, l))) << "frame " << frame << " landmark " << l;
    }
  }
}

fs::path write(const std::string& name, const std::string& text) {
  const fs::path file = test::testDirectory("landmark_io") / name;
  std::ofstream(file) << text;
  return file;
}

std::string inputErrorOf(const fs::path& file) {
  try {
    readLandmarks(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(LandmarkFiles, LacrimasCsvOpenFacesCsvAndJsonGiveTheSamePoints) {
  LandmarkTrack track;
  for (int frame : {1, 2}) {
    track[frame].resize(68);
    for (size_t l = 0; l < 68; ++l) track[frame][l] = expectedPoint(frame, l);
  }
  track[2][5] = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  const fs::path ours = test::testDirectory("landmark_io") / "landmarks.csv";
  writeLandmarksCsv(ours, track);
  expectTheTwoFrames(readLandmarks(ours));

  // OpenFace writes every landmark of a frame it tracked; frame 2 it lost (success 0) but a third
  // frame carries frame 2's points for a second face, which is not read.
  std::string openFace = "frame, face_id, timestamp, confidence, success";
  for (size_t l = 0; l < 68; ++l) openFace += fmt::format(", x_{}", l);
  for (size_t l = 0; l < 68; ++l) openFace += fmt::format(", y_{}", l);
  openFace += "\n";
  const auto row = [&](int frame, int face, int success) {
    std::string line = fmt::format("{}, {}, 0.0, 0.98, {}", frame, face, success);
    for (size_t l = 0; l < 68; ++l) line += fmt::format(", {}", expectedPoint(frame, l).x());
    for (size_t l = 0; l < 68; ++l) line += fmt::format(", {}", expectedPoint(frame, l).y());
    return line + "\n";
  };
  const LandmarkTrack fromOpenFace = readLandmarks(write("openface.csv", openFace + row(1, 0, 1) + row(2, 0, 0) + row(2, 1, 1)));
  ASSERT_EQ(fromOpenFace.size(), 2u);
  EXPECT_TRUE(fromOpenFace.at(1)[67].isApprox(expectedPoint(1, 67)));
  for (const Eigen::Vector2d& p : fromOpenFace.at(2)) EXPECT_FALSE(p.allFinite()) << "a lost frame has no landmarks";

  std::string json = R"({"frames": [)";
  for (int frame : {1, 2}) {
    json += fmt::format(R"({}{{"frame": {}, "points": [)", frame == 1 ? "" : ", ", frame);
    for (size_t l = 0; l < 68; ++l)
      json += (l ? ", " : "") + (frame == 2 && l == 5 ? std::string("null")
                                                       : fmt::format("[{}, {}]", expectedPoint(frame, l).x(),
                                                                     expectedPoint(frame, l).y()));
    json += "]}";
  }
  expectTheTwoFrames(readLandmarks(write("landmarks.json", json + "]}")));
}

TEST(LandmarkFiles, MalformedFilesNameTheFileAndWhere) {
  EXPECT_NE(inputErrorOf(write("header.csv", "f,l,x,y\n")).find("header.csv:1: expected the header 'frame,landmark,u,v'"),
            std::string::npos);
  EXPECT_NE(inputErrorOf(write("row.csv", "frame,landmark,u,v\n1,70,3,4\n")).find("row.csv:2: expected 'frame,landmark,u,v' "
                                                                               "with a landmark in 0-67"),
            std::string::npos);
  EXPECT_NE(inputErrorOf(write("openface_short.csv", "frame, x_0, y_0\n1, 2, 3\n")).find("needs the column 'x_1'"),
            std::string::npos);
  EXPECT_NE(inputErrorOf(write("points.json", R"({"frames": [{"frame": 1, "points": [[1, 2]]}]})"))
                .find("points.json: /frames/0/points: expected 68 points"),
            std::string::npos);
  EXPECT_NE(inputErrorOf(write("broken.json", R"({"frames": )")).find("broken.json: not JSON"), std::string::npos);
  EXPECT_NE(inputErrorOf(test::testDirectory("landmark_io") / "absent.csv").find("cannot open the landmarks"),
            std::string::npos);
}

}  // namespace landmark_io_test
}  // namespace lacrima::cli
