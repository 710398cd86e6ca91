// `lacrima track`: the real binary writes a synthetic performance of the ICT face, tracks it back
// within stated errors, and the weight track it writes plays in a shot; bad performances and
// options are reported and write nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>

#include "support/run_command.hpp"
#include "support/test_directory.hpp"

namespace lacrima {
namespace track_cli_test {

namespace fs = std::filesystem;

test::CommandResult lacrima(const std::string& arguments) {
  return test::runCommand(test::shellQuote(LACRIMA_BINARY) + " " + arguments);
}

std::string firstLine(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

// Tracks dir/perf into dir/track and expects the printed errors against the truth below the bounds.
void expectTrackedWithin(const fs::path& dir, double weightRmse, double vertexMm) {
  const auto tracked = lacrima("track " + test::shellQuote((dir / "perf" / "performance.json").string()) + " --out " +
                               test::shellQuote((dir / "track").string()));
  ASSERT_EQ(tracked.exitStatus, 0) << tracked.output;
  std::smatch match;
  ASSERT_TRUE(std::regex_search(tracked.output, match, std::regex("weight RMSE ([0-9.]+), mean vertex error ([0-9.]+) mm")))
      << tracked.output;
  EXPECT_LT(std::stod(match[1]), weightRmse);
  EXPECT_LT(std::stod(match[2]), vertexMm);
}

// A small shot of the ICT face (frames 1 to lastFrame at fps, rendered at 32 x 32, 1 spp);
// `assetMembers` follow the asset's file and materials.
std::string faceShot(int lastFrame, int fps, const std::string& assetMembers) {
  return R"({
  "version": 1,
  "frames": {"start": 1, "end": )" + std::to_string(lastFrame) + R"(, "fps": )" + std::to_string(fps) + R"(},
  "output": "shot.####.exr",
  "render": {"width": 32, "height": 32, "spp": 1},
  "camera": {"position": [0, 0, 0.6], "lookAt": [0, 0, 0], "fov": 30},
  "materials": {"skin": {"type": "skin", "albedo": [0.62, 0.43, 0.35]}},
  "lights": [{"type": "sphere", "center": [0.4, 0.5, 0.6], "radius": 0.05, "power": 40}],
  "assets": [{"file": ")" + std::string(LACRIMA_SOURCE_DIR) + R"(/scenes/assets/ict-face/ict_face.glb",
              "materials": {"M_Face": "skin"}, )" + assetMembers + R"(}]
})";
}

TEST(TrackCli, ASyntheticPerformanceIsTrackedBackAndItsTrackPlaysInAShot) {
  const fs::path dir = test::testDirectory("track_cli", /*fresh=*/true);
  const auto made = lacrima("track --synthesize " + test::shellQuote((dir / "perf").string()) + " --frames 12 --seed 3");
  ASSERT_EQ(made.exitStatus, 0) << made.output;
  for (const char* file : {"performance.json", "depth.0001.exr", "depth.0012.exr", "landmarks.csv", "truth_weights.csv",
                           "truth_performance.csv"})
    EXPECT_TRUE(fs::exists(dir / "perf" / file)) << file;
  // Measured: weight RMSE 0.02-0.03, vertex error 0.3-0.5 mm (60 frames: 0.023, 0.29 mm).
  expectTrackedWithin(dir, 0.06, 1.0);
  EXPECT_EQ(firstLine(dir / "track" / "weights.csv").rfind("frame,browDown_L,browDown_R,", 0), 0u);
  const std::string performanceHeader = firstLine(dir / "track" / "performance.csv");
  EXPECT_EQ(performanceHeader.rfind("frame,browDown_L,", 0), 0u);
  EXPECT_TRUE(performanceHeader.ends_with(",head.rx,head.ry,head.rz,head.tx,head.ty,head.tz")) << performanceHeader;

  // The tracks as a shot's performance: the weights on any asset, the weights and head channels on
  // one with a rig; the shots load and check.
  std::ofstream(dir / "tracked.json") << faceShot(12, 30, R"("performance": {"file": ")" +
                                                           (dir / "track" / "weights.csv").string() + R"(", "fps": 30})");

  const auto checked = lacrima("check " + test::shellQuote((dir / "tracked.json").string()));
  EXPECT_EQ(checked.exitStatus, 0) << checked.output;
  std::ifstream in(dir / "tracked.json");
  std::string shot((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  shot.replace(shot.find("weights.csv"), 11, "performance.csv");
  shot.replace(shot.find("\"performance\""), 13, "\"rig\": {\"preset\": \"ict\"}, \"performance\"");
  std::ofstream(dir / "tracked_head.json") << shot;
  const auto withHead = lacrima("check " + test::shellQuote((dir / "tracked_head.json").string()));
  EXPECT_EQ(withHead.exitStatus, 0) << withHead.output;
}

TEST(TrackCli, APerformanceRenderedByLacrimaItselfIsTrackedBack) {
  const fs::path dir = test::testDirectory("track_cli_render", /*fresh=*/true);
  const auto made = lacrima("track --synthesize " + test::shellQuote((dir / "perf").string()) + " --render --frames 4");
  ASSERT_EQ(made.exitStatus, 0) << made.output;
  EXPECT_TRUE(fs::exists(dir / "perf" / "capture.json"));
  EXPECT_TRUE(fs::exists(dir / "perf" / "render.0004.exr")) << "the path tracer's frames, their Z AOV the depth";
  EXPECT_TRUE(fs::exists(dir / "perf" / "depth.0004.exr"));
  expectTrackedWithin(dir, 0.06, 1.0);  // measured on 30 frames: weight RMSE 0.033, 0.37 mm
}

// The value of `column` in the CSV's row `row` (0: the first after the header).
double csvValue(const fs::path& file, const std::string& column, int row) {
  std::ifstream in(file);
  std::string line, cell;
  std::getline(in, line);
  std::stringstream header(line);
  int index = 0;
  while (std::getline(header, cell, ',') && cell != column) ++index;
  for (int r = 0; r <= row; ++r) std::getline(in, line);
  std::stringstream values(line);
  for (int c = 0; c <= index; ++c) std::getline(values, cell, ',');
  return std::stod(cell);
}

TEST(TrackCli, AShotsOwnPerformanceIsCapturedTrackedAndPlayedBackByTheShot) {
  const fs::path dir = test::testDirectory("track_cli_shot", /*fresh=*/true);
  // A bowed, tilted head (the staging) that sobs once while the brows rise and the jaw drops.
  std::ofstream(dir / "cry.json") << faceShot(8, 24, R"("name": "face", "rig": {"preset": "ict"},
      "blendshapes": {"browInnerUp_L": {"keys": [[1, 0.2], [8, 0.8]]}, "browInnerUp_R": {"keys": [[1, 0.2], [8, 0.8]]},
                      "jawOpen": {"keys": [[1, 0], [5, 0.4], [8, 0.1]]}},
      "joints": {"head.rx": {"keys": [[1, 5], [4, 7], [8, 5.5]]}, "head.rz": 10})");

  const auto made = lacrima("track --synthesize " + test::shellQuote((dir / "perf").string()) + " --from-shot " +
                            test::shellQuote((dir / "cry.json").string()));
  ASSERT_EQ(made.exitStatus, 0) << made.output;
  EXPECT_TRUE(fs::exists(dir / "perf" / "depth.0008.exr")) << "the shot's frames 1-8";
  EXPECT_FALSE(fs::exists(dir / "perf" / "depth.0009.exr"));
  EXPECT_NEAR(csvValue(dir / "perf" / "truth_performance.csv", "head.rx", 3), 7.0, 1e-4) << "the shot's head at frame 4";
  EXPECT_NEAR(csvValue(dir / "perf" / "truth_performance.csv", "jawOpen", 4), 0.4, 1e-4);

  const auto tracked = lacrima("track " + test::shellQuote((dir / "perf" / "performance.json").string()) + " --out " +
                               test::shellQuote((dir / "track").string()) + " --head-start 5,0,10 --no-filter");
  ASSERT_EQ(tracked.exitStatus, 0) << tracked.output;
  EXPECT_NE(tracked.output.find("against truth_weights.csv"), std::string::npos) << tracked.output;
  // The head's channels are the staging followed by the tracked motion.
  for (int row : {0, 3, 7})
    for (const char* channel : {"head.rx", "head.ry", "head.rz"})
      EXPECT_NEAR(csvValue(dir / "track" / "performance.csv", channel, row),
                  csvValue(dir / "perf" / "truth_performance.csv", channel, row), 0.3)
          << channel << " at frame " << row + 1;

  const auto played = lacrima("render " + test::shellQuote((dir / "cry.json").string()) + " --performance face=" +
                              test::shellQuote((dir / "track" / "performance.csv").string()) + " --frames 4 --out " +
                              test::shellQuote((dir / "played.####.exr").string()) + " -q");
  EXPECT_EQ(played.exitStatus, 0) << played.output;
  EXPECT_TRUE(fs::exists(dir / "played.0004.exr"));
  const auto noEquals = lacrima("render " + test::shellQuote((dir / "cry.json").string()) + " --performance face --out " +
                                test::shellQuote((dir / "bad.####.exr").string()));
  EXPECT_EQ(noEquals.exitStatus, 2);
  EXPECT_NE(noEquals.output.find("--performance face: expected ASSET=FILE"), std::string::npos) << noEquals.output;
  const auto noAsset = lacrima("render " + test::shellQuote((dir / "cry.json").string()) + " --performance nose=" +
                               test::shellQuote((dir / "track" / "performance.csv").string()) + " --out " +
                               test::shellQuote((dir / "bad.####.exr").string()));
  EXPECT_EQ(noAsset.exitStatus, 2);
  EXPECT_NE(noAsset.output.find("no asset named 'nose'"), std::string::npos) << noAsset.output;
  EXPECT_FALSE(fs::exists(dir / "bad.0001.exr"));
  const auto twoValues = lacrima("track " + test::shellQuote((dir / "perf" / "performance.json").string()) +
                                 " --head-start 5,0 --out " + test::shellQuote((dir / "bad_track").string()));
  EXPECT_NE(twoValues.exitStatus, 0);
  EXPECT_FALSE(fs::exists(dir / "bad_track"));
}

TEST(TrackCli, BadPerformancesAndOptionsAreReportedAndWriteNothing) {
  const fs::path dir = test::testDirectory("track_cli_bad", /*fresh=*/true);
  std::ofstream(dir / "performance.json") << R"({"version": 1, "frames": {"start": 1, "end": 2}, "depth": "d.####.exr"})";
  const auto noCamera = lacrima("track " + test::shellQuote((dir / "performance.json").string()) + " --out " +
                                test::shellQuote((dir / "out").string()));
  EXPECT_EQ(noCamera.exitStatus, 2);
  EXPECT_NE(noCamera.output.find("performance.json: 'camera' must give width, height, fx, fy, cx and cy"), std::string::npos)
      << noCamera.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  const auto neither = lacrima("track");
  EXPECT_EQ(neither.exitStatus, 2);
  EXPECT_NE(neither.output.find("give a performance.json to track, or --synthesize FOLDER"), std::string::npos) << neither.output;
  std::ofstream(dir / "camera_only.json")
      << R"({"frames": {"start": 1, "end": 1}, "camera": {"width": 64, "height": 48, "fx": 50, "fy": 50, "cx": 32, "cy": 24},
            "depth": "missing.####.exr"})";
  const auto missing = lacrima("track " + test::shellQuote((dir / "camera_only.json").string()) + " --out " +
                               test::shellQuote((dir / "out").string()));
  EXPECT_EQ(missing.exitStatus, 2);
  EXPECT_NE(missing.output.find("cannot read the depth map"), std::string::npos) << missing.output;
  EXPECT_NE(missing.output.find("missing.0001.exr"), std::string::npos) << missing.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace track_cli_test
}  // namespace lacrima
