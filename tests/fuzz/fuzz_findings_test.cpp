// The fuzzer findings that were bugs in lacrima, each checked for its exact outcome (the replay
// in corpus_replay_test.cpp only checks that no crash or foreign exception remains).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "fuzz_support.hpp"
#include "lacrima/io/performance_track.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima::fuzz {
namespace fuzz_findings_test {

// A misspelt "fov" (the only field of view of a look-at camera) is reported as an unknown key with
// the suggestion, and the shot does not load. It used to crash: the missing 'fov' was not
// reported again, so the camera was derived from a null glTF camera (shot_reader_camera.cpp readCamera).
TEST(FuzzFindings, MisspeltFovIsAnErrorNotACrash) {
  const std::filesystem::path path = workDirectory() / "misspelt_fov.json";
  std::ofstream(path) << R"({"version": 1, "frames": {"start": 1, "end": 1}, "output": "out.exr",
 "render": {"width": 32, "height": 32, "spp": 1},
 "camera": {"position": [0, 0, 3], "lookAt": [0, 0, 0], "FOV": 30}})";
  try {
    loadShot(path);
    FAIL() << "expected a ShotError";
  } catch (const ShotError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u) << e.what();
    EXPECT_EQ(e.diagnostics()[0].jsonPath, "/camera/FOV");
    const std::string& message = e.diagnostics()[0].message;  // then the line, with a caret under the key
    EXPECT_EQ(message.substr(0, message.find('\n')), "unknown key 'FOV'; did you mean 'fov'?");
  }
}

// A number too large for a double used to escape both JSON readers as nlohmann's out_of_range
// ("lacrima: internal error"); it is now bad input with the file, and for a shot the position.
TEST(FuzzFindings, NumberTooLargeForADoubleIsBadInput) {
  const std::filesystem::path shotPath = workDirectory() / "huge_number.json";
  std::ofstream(shotPath) << R"({"version": 1, "frames": {"start": 1, "end": 1}, "output": "out.exr",
 "render": {"width": 32, "height": 32, "spp": 1e999},
 "camera": {"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30}})";
  try {
    loadShot(shotPath);
    FAIL() << "expected a ShotError";
  } catch (const ShotError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u) << e.what();
    EXPECT_EQ(e.diagnostics()[0].line, 2);
    EXPECT_EQ(e.diagnostics()[0].column, 47);  // the "1" of 1e999
    const std::string& message = e.diagnostics()[0].message;
    EXPECT_NE(message.find("number overflow parsing '1e999'"), std::string::npos) << message;
  }
  const std::filesystem::path trackPath = workDirectory() / "huge_fps.json";
  std::ofstream(trackPath) << R"({"fps": 1e999, "weights": {"jawOpen": [0, 1]}})";
  try {
    readPerformanceJson(trackPath, {"jawOpen"});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), trackPath.string() + ": JSON number out of range: [json.exception.out_of_range.406] "
                                                           "number overflow parsing '1e999'");
  }
}

}  // namespace fuzz_findings_test
}  // namespace lacrima::fuzz
