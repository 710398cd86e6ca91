// `lacrima bench`'s per-frame cost report (tools/src/bench_frame_costs.*): its columns and rows on a
// tiny shot. Only the report's shape is checked: speed is measured by the bench, never by tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/test_directory.hpp"
#include "tools/lacrima_cli_support.hpp"

namespace lacrima::cli {
namespace bench_frame_costs_test {

namespace fs = std::filesystem;

// Three frames of a diffuse ellipsoid in front of a backdrop that slides up: the backdrop's mesh
// moves from frame to frame, so frames 2 and 3 refit the scene (and raw Embree refits it too).
fs::path writeSlidingBackdropShot(const fs::path& dir) {
  const fs::path path = dir / "sliding.json";
  std::ofstream(path) << R"({
  "version": 1,
  "frames": {"start": 1, "end": 3, "fps": 24},
  "output": "out/sliding.####.exr",
  "render": {"width": 16, "height": 9, "spp": 1, "maxDepth": 4, "seed": 1},
  "camera": {"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30},
  "background": [0.3, 0.35, 0.4],
  "materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
  "lights": [{"type": "sphere", "center": [1, 1.5, 2], "radius": 0.2, "power": 40}],
  "shapes": [
    {"type": "ellipsoid", "center": [0, 0, 0], "radii": [0.4, 0.3, 0.3], "material": "grey"},
    {"type": "rectangle", "center": {"keys": [[1, [0, 0, -1]], [3, [0, 0.2, -1]]]}, "size": [3, 2],
     "normal": [0, 0, 1], "material": "grey"}
  ]
})";
  return path;
}

std::vector<std::string> wordsOf(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// The report's lines from its header ("frame rig ...") on.
std::vector<std::string> reportLines(const std::string& output) {
  std::vector<std::string> lines;
  std::istringstream in(output);
  bool inReport = false;
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> words = wordsOf(line);
    if (!words.empty() && words[0] == "frame" && words.size() > 1 && words[1] == "rig") inReport = true;
    if (inReport && !words.empty()) lines.push_back(line);
  }
  return lines;
}

TEST(BenchFrameCosts, ReportsEveryStageForEveryFrameAndTheirMedians) {
  const fs::path dir = test::testDirectory("bench_frame_costs", /*fresh=*/true);
  const auto run = test::lacrima({"bench", writeSlidingBackdropShot(dir).string(), "--frame-costs-only", "--frames",
                                  "1-3", "--width", "16", "--height", "9", "--spp", "1", "--threads", "1"});
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  EXPECT_NE(run.output.find("shot load seconds"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("paths/s"), std::string::npos) << "--frame-costs-only skips the throughput\n" << run.output;

  const std::vector<std::string> lines = reportLines(run.output);
  ASSERT_EQ(lines.size(), 5u) << run.output;  // header, frames 1-3, median
  const std::vector<std::string> header = wordsOf(lines[0]);
  const std::vector<std::string> expected = {"frame",  "rig",      "flesh",  "details", "liquid-sim", "liquid",
                                             "eyes",   "other",    "geometry", "upload", "bvh",        "scene",
                                             "set-up", "total",    "raw-refit", "raw-1-step"};
  EXPECT_EQ(header, expected);
  // Frame 1 builds the scene ("1 B": no refit, no raw refit to compare); 2 and 3 refit it.
  const std::vector<std::string> first = wordsOf(lines[1]);
  ASSERT_EQ(first.size(), expected.size() + 1) << lines[1];
  EXPECT_EQ(first[0], "1");
  EXPECT_EQ(first[1], "B");
  EXPECT_EQ(first.back(), "-");
  for (size_t row = 2; row <= 4; ++row) {
    const std::vector<std::string> words = wordsOf(lines[row]);
    ASSERT_EQ(words.size(), expected.size()) << lines[row];
    EXPECT_EQ(words[0], row == 4 ? "median" : std::to_string(row)) << lines[row];
    for (size_t c = 1; c < words.size(); ++c) {
      if (expected[c] == "set-up") continue;  // a difference of two measurements: may be slightly negative
      EXPECT_GE(std::stod(words[c]), 0.0) << expected[c] << " in " << lines[row];
    }
  }
}

TEST(BenchFrameCosts, AFrameOutsideTheShotIsBadInput) {
  const fs::path dir = test::testDirectory("bench_frame_costs", /*fresh=*/true);
  const auto run = test::lacrima({"bench", writeSlidingBackdropShot(dir).string(), "--frame-costs-only", "--frames", "7"});
  EXPECT_EQ(run.exitStatus, 2) << run.output;
}

}  // namespace bench_frame_costs_test
}  // namespace lacrima::cli
