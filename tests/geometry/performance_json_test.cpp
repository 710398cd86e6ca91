// Performance-capture weight tracks in JSON: the same data as the CSV form, errors located by
// JSON pointer.
#include <gtest/gtest.h>

#include <fstream>

#include "geometry/glb_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/io/performance_track.hpp"

namespace lacrima {
namespace performance_json_test {

const std::vector<std::string> kNames = {"jawOpen", "eyeBlink_L", "eyeBlink_R"};

std::filesystem::path writeJson(const std::string& text) {
  const std::filesystem::path path = test::testOutputDir() / "track.json";
  std::ofstream(path) << text;
  return path;
}

std::string errorOf(const std::string& json) {
  const std::filesystem::path path = writeJson(json);
  try {
    readPerformanceTrack(path, kNames);
  } catch (const InputError& e) {
    return std::string(e.what()).substr(path.string().size());
  }
  return "no error";
}

TEST(PerformanceJson, ReadsFpsOrTimesAndMapsNames) {
  PerformanceCsvOptions options;
  options.nameMap = {{"JawOpen", "jawOpen"}};
  const PerformanceTrack byFps = readPerformanceTrack(
      writeJson(R"({"fps": 50, "weights": {"JawOpen": [0, 0.5, 1], "eyeBlink_R": [1, 0, 0]}})"), kNames, options);
  EXPECT_EQ(byFps.names, (std::vector<std::string>{"jawOpen", "eyeBlink_R"}));
  EXPECT_EQ(byFps.times, (std::vector<float>{0.0f, 0.02f, 0.04f}));
  EXPECT_EQ(byFps.frames[1], (std::vector<float>{0.5f, 0.0f}));
  const PerformanceTrack byTime =
      readPerformanceTrack(writeJson(R"({"time": [0.5, 0.75], "weights": {"eyeBlink_L": [0.25, 1]}})"), kNames);
  EXPECT_EQ(byTime.times, (std::vector<float>{0.5f, 0.75f}));
  EXPECT_EQ(byTime.frames[1], std::vector<float>{1.0f});
}

TEST(PerformanceJson, ErrorsNameTheFileAndJsonPointer) {
  EXPECT_EQ(errorOf(R"({"fps": 30, "weights": {"jawOpn": [0]}})"),
            ": /weights/jawOpn: unknown blendshape 'jawOpn' (did you mean 'jawOpen'?)");
  EXPECT_EQ(errorOf(R"({"fps": 30, "weights": {"jawOpen": [0, "x"]}})"),
            ": /weights/jawOpen/1: expected a finite number, found \"x\"");
  EXPECT_EQ(errorOf(R"({"time": [0, 0], "weights": {"jawOpen": [0, 1]}})"),
            ": /time/1: time 0 s is not after the previous 0 s");
  EXPECT_EQ(errorOf(R"({"fps": 30, "weights": {"jawOpen": [0, 1], "eyeBlink_L": [0]}})"),
            ": /weights/jawOpen: 2 samples, but 'eyeBlink_L' has 1");  // channels in name order
  EXPECT_EQ(errorOf(R"({"fps": 30, "weights": {}})"),
            ": /weights: expected an object mapping blendshape names to arrays of weights");
  EXPECT_EQ(errorOf(R"({"fsp": 30, "weights": {"jawOpen": [0]}})"), ": /fsp: unknown key 'fsp' (did you mean 'fps'?)");
  EXPECT_EQ(errorOf(R"({"fps": -2, "weights": {"jawOpen": [0]}})"), ": /fps: expected a number > 0, found -2");
  EXPECT_EQ(errorOf(R"({"time": [0], "weights": {"jawOpen": [0, 1]}})"), ": /time: 1 times for 2 samples per blendshape");
  EXPECT_NE(errorOf(R"({"fps": 30, "weights": )").find(": JSON syntax error at byte"), std::string::npos);
}

}  // namespace performance_json_test
}  // namespace lacrima
