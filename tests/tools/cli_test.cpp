// Command-line tests: the real `lacrima` binary on bad shot files, bad options, good inputs and
// a tiny render, checking exit status, the exact messages and which files are (not) written.
// Renders are 32x18 or smaller at 1-2 spp, so every test takes well under a second or two.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "lacrima/renderer/cryptomatte.hpp"
#include "lacrima/renderer/camera.hpp"
#include "lacrima/scenes/shot.hpp"
#include "support/run_command.hpp"
#include "support/test_directory.hpp"
#include "tools/lacrima_cli_support.hpp"

namespace lacrima {
namespace cli_test {

namespace fs = std::filesystem;
using test::commandLine;
using test::lacrima;
using test::lacrimaStdout;
using test::lacrimaStderr;
using test::filesIn;

const std::string kHint = "Run with --help for more information.\n";

std::string sourcePath(const std::string& relative) { return (fs::path(LACRIMA_SOURCE_DIR) / relative).string(); }
std::string badShot(const std::string& name) { return sourcePath("tests/data/bad_shots/" + name); }

// An empty directory of its own for the running test, under LACRIMA_TEST_OUTPUT_DIR.
fs::path freshDir() { return test::testDirectory("cli", /*fresh=*/true); }

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The line `lacrima info` prints for an EXR attribute ("  name = value"), or "" when absent.
std::string attributeLine(const std::string& output, const std::string& name) {
  for (const std::string& line : splitLines(output))
    if (startsWith(line, "  " + name + " = ")) return line;
  return "";
}

// The warnings `lacrima check` / `render` print for a shot, one line each, as the library formats them.
std::string warningLines(const Shot& shot) {
  std::string out;
  for (const Diagnostic& d : shot.warnings) out += d.format() + "\n";
  return out;
}

// A small shot that loads with a warning: studio.exr has 3 negative texels, set to 0 on load
// (see LoadShot.DropsOnAPlane in tests/scenes). Three frames, output relative to the shot file.
fs::path writeWarningShot(const fs::path& dir) {
  const fs::path path = dir / "warn.json";
  std::ofstream(path) << "{\n"
                      << "  \"version\": 1,\n"
                      << "  \"frames\": {\"start\": 1, \"end\": 3, \"fps\": 24},\n"
                      << "  \"output\": \"out/warn.####.exr\",\n"
                      << "  \"render\": {\"width\": 8, \"height\": 8, \"spp\": 1, \"seed\": 3},\n"
                      << "  \"environment\": {\"file\": \"" << sourcePath("scenes/assets/hdri/studio.exr") << "\"},\n"
                      << "  \"camera\": {\"position\": [0, 0, 3], \"lookAt\": [0, 0, 0], \"fov\": 30},\n"
                      << "  \"materials\": {\"water\": {\"type\": \"water\", \"ior\": 1.337}},\n"
                      << "  \"shapes\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 0.5, "
                         "\"material\": \"water\"}]\n"
                      << "}\n";
  return path;
}

std::string warningShotWarning(const fs::path& shot) {
  return shot.string() + ":6:27: /environment/file: warning: " + sourcePath("scenes/assets/hdri/studio.exr") +
         ": 3 texels were NaN, infinite or negative, set to 0\n";
}

// ---- bad shot files --------------------------------------------------------------------------

struct BadShotCase {
  std::string file;
  std::vector<std::string> lines;  // the message, as tests/scenes/bad_shots_test.cpp expects it
};

std::ostream& operator<<(std::ostream& os, const BadShotCase& c) { return os << c.file; }

// The exact messages of tests/scenes/bad_shots_test.cpp: the tool prints loadShot's ShotError as it is.
std::vector<BadShotCase> badShotCases() {
  const auto f = [](const std::string& name) { return badShot(name); };
  return {
      {"syntax_error.json",
       {f("syntax_error.json") + ":5:50: JSON syntax error: syntax error while parsing object key - unexpected '}'; "
                                 "expected string literal",
        R"(      "render": {"width": 32, "height": 32, "spp": 4,},)",
        R"(                                                     ^)"}},
      {"unknown_key.json",
       {f("unknown_key.json") + ":7:3: /backgruond: unknown key 'backgruond'; did you mean 'background'?",
        R"(      "backgruond": [1, 1, 1])", R"(      ^)"}},
      {"unknown_blendshape.json",
       {f("unknown_blendshape.json") + ":11:23: /assets/0/blendshapes/browInnerUp_l: unknown blendshape "
                                       "'browInnerUp_l'; did you mean 'browInnerUp_L'?",
        R"(          "blendshapes": {"browInnerUp_l": 0.5, "jawOpen": 0.2})",
        R"(                          ^)"}},
      {"negative_spp.json",
       {f("negative_spp.json") + ":5:48: /render/spp: expected an integer >= 1, found -4",
        R"(      "render": {"width": 32, "height": 32, "spp": -4},)",
        R"(                                                   ^)"}},
      {"wrong_type.json",
       {f("wrong_type.json") + R"(:5:23: /render/width: expected an integer in [1, 16384], found "64")",
        R"(      "render": {"width": "64", "height": 32, "spp": 4},)",
        R"(                          ^)"}},
      {"missing_field.json",
       {f("missing_field.json") + ":5:3: /render: missing required key 'spp' (an integer >= 1)",
        R"(      "render": {"width": 32, "height": 32},)", R"(      ^)"}},
      {"undefined_material.json",
       {f("undefined_material.json") + ":11:72: /shapes/0/material: undefined material 'tears'; did you mean 'tear'?",
        R"(        {"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "tears"})",
        R"(                                                                           ^)"}},
      {"missing_asset.json",
       {f("missing_asset.json") + ":8:30: /assets/0/file: file not found: 'no_such_face.glb' (resolved to '" +
            f("no_such_face.glb") + "')",
        R"(        {"name": "face", "file": "no_such_face.glb"})",
        R"(                                 ^)"}},
      {"corrupt_asset.json",
       {f("corrupt_asset.json") + ":8:30: /assets/0/file: cannot load the glTF asset: " + f("corrupt.glb") +
            R"(: not a glTF file: neither a GLB binary (magic "glTF") nor JSON)",
        R"(        {"name": "face", "file": "corrupt.glb"})", R"(                                 ^)"}},
      {"several_errors.json",
       {
           f("several_errors.json") + ":3:37: /frames/fsp: unknown key 'fsp'; did you mean 'fps'?",
           R"(      "frames": {"start": 1, "end": 48, "fsp": 24},)",
           R"(                                        ^)",
           f("several_errors.json") + ":4:13: /output: 'renders/still.exr' has no frame number field ('####' or "
                                      "'%04d') but the shot has frames 1-48: every frame would overwrite the last",
           R"(      "output": "renders/still.exr",)",
           R"(                ^)",
           f("several_errors.json") + ":5:23: /render/width: expected an integer in [1, 16384], found 0",
           R"(      "render": {"width": 0, "height": 32, "spp": 4.5, "floatOutput": "yes"},)",
           R"(                          ^)",
           f("several_errors.json") + ":5:47: /render/spp: expected an integer >= 1, found 4.5",
           R"(      "render": {"width": 0, "height": 32, "spp": 4.5, "floatOutput": "yes"},)",
           R"(                                                  ^)",
           f("several_errors.json") + R"(:5:67: /render/floatOutput: expected true or false, found "yes")",
           R"(      "render": {"width": 0, "height": 32, "spp": 4.5, "floatOutput": "yes"},)",
           R"(                                                                      ^)",
           f("several_errors.json") +
               ":6:47: /camera/lookAt: expected [x, y, z] (an array of 3 numbers), found an array of 2 elements",
           R"(      "camera": {"position": [0, 0, 3], "lookAt": [0, 0], "fov": 200, "fStop": -2},)",
           R"(                                                  ^)",
           f("several_errors.json") + ":6:62: /camera/fov: expected a number in (0, 180), found 200",
           R"(      "camera": {"position": [0, 0, 3], "lookAt": [0, 0], "fov": 200, "fStop": -2},)",
           R"(                                                                 ^)",
           f("several_errors.json") + ":6:76: /camera/fStop: expected a number > 0, found -2",
           R"(      "camera": {"position": [0, 0, 3], "lookAt": [0, 0], "fov": 200, "fStop": -2},)",
           R"(                                                                               ^)",
           f("several_errors.json") + ":8:38: /materials/tear/ior: expected a number in (1, 3], found 0.9",
           R"(        "tear": {"type": "water", "ior": 0.9},)",
           R"(                                         ^)",
           f("several_errors.json") +
               ":9:22: /materials/skin/type: unknown material type 'skinn'; did you mean 'skin'?",
           R"(        "skin": {"type": "skinn"},)",
           R"(                         ^)",
           f("several_errors.json") + ":10:50: /materials/plane/albedo/1: expected a number in [0, 1], found 1.5",
           R"(        "plane": {"type": "diffuse", "albedo": [0.5, 1.5, 0.5]})",
           R"(                                                     ^)",
           f("several_errors.json") + ":13:5: /lights/0: missing required key 'radiance' ([r, g, b] in W/(m^2 sr); "
                                      "or 'power' in watts)",
           R"(        {"type": "rectangle", "center": [0, 1, 0], "size": [0.2, 0.2], "normal": [0, -1, 0]},)",
           R"(        ^)",
           f("several_errors.json") + ":14:83: /lights/1/power: give either 'radiance' or 'power', not both",
           R"(        {"type": "sphere", "center": [0, 1, 0], "radius": 0.1, "radiance": [1, 1, 1], "power": 5})",
           R"(                                                                                      ^)",
           f("several_errors.json") + ":17:55: /shapes/0/radius: expected a number > 0, found -1",
           R"(        {"type": "sphere", "center": [0, 0, 0], "radius": -1, "material": "water"})",
           R"(                                                          ^)",
           f("several_errors.json") +
               ":17:71: /shapes/0/material: undefined material 'water' (defined materials: 'tear', 'skin', 'plane')",
           R"(        {"type": "sphere", "center": [0, 0, 0], "radius": -1, "material": "water"})",
           R"(                                                                          ^)",
       }},
  };
}

std::string joinedMessage(const BadShotCase& c) {
  std::string out;
  for (const std::string& line : c.lines) out += line + "\n";
  return out;
}

TEST(CliBadShots, EveryBadShotFileHasACase) {
  std::set<std::string> onDisk, covered;
  for (const auto& entry : fs::directory_iterator(sourcePath("tests/data/bad_shots")))
    if (entry.path().extension() == ".json") onDisk.insert(entry.path().filename().string());
  for (const BadShotCase& c : badShotCases()) covered.insert(c.file);
  EXPECT_EQ(onDisk, covered) << "add the new bad shot's message to badShotCases()";
}

class CliBadShot : public ::testing::TestWithParam<BadShotCase> {};

TEST_P(CliBadShot, CheckExitsTwoWithTheShotErrors) {
  const BadShotCase& c = GetParam();
  const auto run = lacrima({"check", badShot(c.file)});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, joinedMessage(c));
}

TEST_P(CliBadShot, RenderExitsTwoWithTheShotErrorsAndWritesNothing) {
  const BadShotCase& c = GetParam();
  const fs::path dir = freshDir();
  const auto run =
      lacrima({"render", badShot(c.file), "--out", (dir / "out" / "bad.####.exr").string(), "--preview", "--quiet"});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, joinedMessage(c));
  EXPECT_TRUE(filesIn(dir).empty());
  EXPECT_FALSE(fs::exists(dir / "out"));
}

INSTANTIATE_TEST_SUITE_P(BadShotFiles, CliBadShot, ::testing::ValuesIn(badShotCases()),
                         [](const ::testing::TestParamInfo<BadShotCase>& info) {
                           return fs::path(info.param.file).stem().string();
                         });

// ---- option errors ---------------------------------------------------------------------------

class CliOptions : public ::testing::Test {
 protected:
  // Renders test_drops.json with the given extra options into a fresh directory, which must stay
  // empty; returns the output.
  std::string renderFails(const std::vector<std::string>& options) {
    const fs::path dir = freshDir();
    std::vector<std::string> args = {"render", drops_, "--out", (dir / "t.####.exr").string(), "--quiet"};
    args.insert(args.end(), options.begin(), options.end());
    const auto run = lacrima(args);
    EXPECT_EQ(run.exitStatus, 2) << run.output;
    EXPECT_TRUE(filesIn(dir).empty());
    return run.output;
  }

  const std::string drops_ = sourcePath("scenes/shots/test_drops.json");
};

TEST_F(CliOptions, WidthWithoutHeight) {
  EXPECT_EQ(renderFails({"--width", "32"}), "--width requires --height\n" + kHint);
  EXPECT_EQ(renderFails({"--height", "18"}), "--height requires --width\n" + kHint);
}

TEST_F(CliOptions, SamplesPerPixelMustBePositive) {
  EXPECT_EQ(renderFails({"--spp", "0"}), "--spp: expected an integer >= 1, found 0\n" + kHint);
  EXPECT_EQ(renderFails({"--spp", "-3"}), "--spp: expected an integer >= 1, found -3\n" + kHint);
  EXPECT_EQ(renderFails({"--spp", "2.5"}), "--spp: expected an integer >= 1, found 2.5\n" + kHint);
  EXPECT_EQ(renderFails({"--spp", "many"}), "--spp: expected an integer >= 1, found 'many'\n" + kHint);
  EXPECT_EQ(renderFails({"--spp", "99999999999"}),
            "--spp: expected an integer >= 1, found 99999999999 (too large)\n" + kHint);
}

TEST_F(CliOptions, OtherNumericRanges) {
  EXPECT_EQ(renderFails({"--width", "0", "--height", "18"}),
            "--width: expected an integer in [1, 16384], found 0\n" + kHint);
  EXPECT_EQ(renderFails({"--threads", "-1"}), "--threads: expected an integer >= 0, found -1\n" + kHint);
  EXPECT_EQ(renderFails({"--seed", "-1"}), "--seed: expected an integer >= 0, found -1\n" + kHint);
  EXPECT_EQ(renderFails({"--max-depth", "1001"}),
            "--max-depth: expected an integer in [0, 1000], found 1001\n" + kHint);
}

TEST_F(CliOptions, RegionMustBeFourNumbersWithinTheFrame) {
  const std::vector<std::string> frame = {"--width", "16", "--height", "12", "--region"};
  const auto fails = [&](const std::string& region) {
    std::vector<std::string> options = frame;
    options.push_back(region);
    const std::string output = renderFails(options);
    return output.substr(output.find("--region"));  // after the shot's own warnings, if any
  };
  EXPECT_EQ(fails("10,2,8,5"), "--region 10,2,8,5: the region does not lie within the 16x12 frame (it ends at pixel "
                               "(17, 6))\n");
  EXPECT_EQ(fails("0,0,0,4"), "--region 0,0,0,4: the region's width and height must be at least 1\n");
  EXPECT_EQ(fails("-1,0,2,2"), "--region: expected an integer in [0, 16384], found -1\n" + kHint);
  EXPECT_EQ(fails("1,2,3"), "--region: At least 4 required but received 3\n" + kHint);
}

TEST_F(CliOptions, MalformedFrames) {
  EXPECT_EQ(renderFails({"--frames", "3-1"}), "--frames 3-1: range '3-1' ends before it starts\n");
  EXPECT_EQ(renderFails({"--frames", "abc"}),
            "--frames abc: 'abc' is not a frame number or a range like 1-48 or 1-48x2\n");
  EXPECT_EQ(renderFails({"--frames", "1-48x0"}),
            "--frames 1-48x0: step after 'x' in '1-48x0' must be a whole number >= 1\n");
  EXPECT_EQ(renderFails({"--frames", ""}), "--frames '': no frames given\n");
  EXPECT_EQ(renderFails({"--frames", "1,"}),
            "--frames 1,: empty item in the list (a comma at the start or end, or two in a row)\n");
}

TEST_F(CliOptions, FramesOutsideTheShotsRange) {
  // test_drops.json has the single frame 1 (read from the file, which may change).
  const Shot shot = loadShot(drops_);
  const std::string range = std::to_string(shot.frameStart) + "-" + std::to_string(shot.frameEnd);
  const std::string after = std::to_string(shot.frameEnd + 1), before = std::to_string(shot.frameStart - 1);
  EXPECT_EQ(renderFails({"--frames", after}),
            "--frames " + after + ": frame " + after + " is outside the frame range " + range + " of " + drops_ + "\n");
  EXPECT_EQ(renderFails({"--frames", before}),
            "--frames " + before + ": frame " + before + " is outside the frame range " + range + " of " + drops_ +
                "\n");
}

TEST_F(CliOptions, OutOfRangeFrameIsFoundBeforeAnyFrameIsRendered) {
  const fs::path dir = freshDir();
  const fs::path shot = writeWarningShot(dir);  // frames 1-3, output out/warn.####.exr
  const auto run = lacrima({"render", shot.string(), "--frames", "1,5", "--quiet"});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, "--frames 1,5: frame 5 is outside the frame range 1-3 of " + shot.string() + "\n");
  EXPECT_EQ(filesIn(dir), std::set<std::string>{"warn.json"});
}

TEST_F(CliOptions, OutputPatternErrors) {
  const fs::path dir = freshDir();
  const fs::path shot = writeWarningShot(dir);  // frames 1-3
  const std::string still = (dir / "still.exr").string();
  auto run = lacrima({"render", shot.string(), "--out", still, "--quiet"});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, "output '" + still +
                            "' has no #### frame field but 3 frames are to be rendered: every frame would "
                            "overwrite the last\n");
  // A .png "EXR" would be overwritten by its own --preview.
  const std::string png = (dir / "t.####.png").string();
  run = lacrima({"render", shot.string(), "--out", png, "--preview", "--quiet"});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, "output '" + png + "': frames are OpenEXR files, the name must end in .exr\n");
  EXPECT_EQ(filesIn(dir), std::set<std::string>{"warn.json"});
}

TEST_F(CliOptions, MissingPreviewConfigIsFoundBeforeRendering) {
  const fs::path dir = freshDir();
  const fs::path shot = writeWarningShot(dir);  // no colorConfig: the tool's default, from the environment
  const std::string config = (dir / "missing.ocio").string();
  const auto run = test::runCommand("LACRIMA_OCIO_CONFIG=" + test::shellQuote(config) + " " +
                                    commandLine({"render", shot.string(), "--frames", "1", "--preview", "--quiet"}));
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, "OCIO config '" + config + "' for --preview: file not found (or not a regular file)\n");
  EXPECT_EQ(filesIn(dir), std::set<std::string>{"warn.json"});
}

TEST_F(CliOptions, MissingShotFile) {
  const fs::path dir = freshDir();
  const std::string missing = (dir / "no_such_shot.json").string();
  const std::string expected = missing + ": cannot read the shot file: No such file or directory\n";
  auto run = lacrima({"check", missing});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, expected);
  run = lacrima({"render", missing, "--out", (dir / "t.####.exr").string(), "--quiet"});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, expected);
  EXPECT_TRUE(filesIn(dir).empty());
}

TEST_F(CliOptions, UnknownSubcommandOrOption) {
  auto run = lacrima({"frobnicate", drops_});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output,
            "lacrima: unknown subcommand 'frobnicate' (expected a subcommand: render, check, info, bench, export, diff, test-suite, farm, flood, track)\n" + kHint);
  run = lacrima({"--bogus"});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output,
            "lacrima: unknown option '--bogus' (expected a subcommand: render, check, info, bench, export, diff, test-suite, farm, flood, track)\n" + kHint);
  run = lacrima({});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, "A subcommand is required\n" + kHint);
  EXPECT_EQ(renderFails({"--bogus"}), "The following argument was not expected: --bogus\n" + kHint);
}

TEST(CliHelp, MainAndRenderHelpHaveExamples) {
  const std::vector<std::vector<std::string>> helps = {{"--help"}, {"render", "--help"}};
  for (const std::vector<std::string>& args : helps) {
    const auto run = lacrima(args);
    EXPECT_EQ(run.exitStatus, 0) << args.front();
    EXPECT_NE(run.output.find("\nExamples:\n  lacrima render "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("Exit status: 0 success, 1 render failure"), std::string::npos) << run.output;
  }
  const auto version = lacrima({"--version"});
  EXPECT_EQ(version.exitStatus, 0);
  EXPECT_EQ(version.output, std::string("lacrima ") + LACRIMA_VERSION + "\n");
}

// ---- check and info on good and corrupt inputs -----------------------------------------------

TEST(CliCheck, GoodShotIsOkAndItsWarningsGoToStderr) {
  const std::string drops = sourcePath("scenes/shots/test_drops.json");
  const Shot shot = loadShot(drops);
  char fps[32];
  std::snprintf(fps, sizeof fps, "%g", shot.fps);
  const auto out = lacrimaStdout({"check", drops});
  EXPECT_EQ(out.exitStatus, 0);
  EXPECT_EQ(out.output, drops + ": OK (frames " + std::to_string(shot.frameStart) + "-" +
                            std::to_string(shot.frameEnd) + " at " + fps + " fps, " +
                            std::to_string(shot.render.width) + "x" + std::to_string(shot.render.height) + ", " +
                            std::to_string(shot.render.samplesPerPixel) + " spp)\n");
  const auto err = lacrimaStderr({"check", drops});
  EXPECT_EQ(err.exitStatus, 0);
  EXPECT_EQ(err.output, warningLines(shot));
}

TEST(CliCheck, ThreadsCapTheWorkNotTheVerdict) {
  const std::string drops = sourcePath("scenes/shots/test_drops.json");
  const auto all = lacrimaStdout({"check", drops});
  const auto one = lacrimaStdout({"check", drops, "--threads", "1"});
  EXPECT_EQ(one.exitStatus, 0);
  EXPECT_EQ(one.output, all.output);
  const auto bad = lacrima({"check", drops, "--threads", "-2"});
  EXPECT_EQ(bad.exitStatus, 2);
  EXPECT_EQ(bad.output, "--threads: expected an integer >= 0, found -2\n" + kHint);
}

TEST(CliCheck, WarningsArePrintedWithTheirLocation) {
  const fs::path dir = freshDir();
  const fs::path shot = writeWarningShot(dir);
  const auto err = lacrimaStderr({"check", shot.string()});
  EXPECT_EQ(err.exitStatus, 0);
  EXPECT_EQ(err.output, warningShotWarning(shot));
  const auto out = lacrimaStdout({"check", shot.string()});
  EXPECT_EQ(out.exitStatus, 0);
  EXPECT_EQ(out.output, shot.string() + ": OK (frames 1-3 at 24 fps, 8x8, 1 spp)\n");
}

TEST(CliInfo, FaceAssetHas57MorphTargets) {
  const std::string face = sourcePath("scenes/assets/ict-face/ict_face.glb");
  const auto run = lacrima({"info", face});
  EXPECT_EQ(run.exitStatus, 0);
  EXPECT_TRUE(startsWith(run.output, "file: " + face + "\n")) << run.output;
  EXPECT_NE(run.output.find("\nprimitives: 12\n"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("\nmorph targets: 57\n  browDown_L, browDown_R, "), std::string::npos) << run.output;
  // Which primitives are open: the tear line is (a thin sheet when given water), the eyeballs are not.
  EXPECT_NE(run.output.find("open surfaces: 7 of 12"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("#8 M_LacrimalFluid (164)"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("M_ScleraRight ("), std::string::npos) << run.output;
}

TEST(CliInfo, CorruptAssetIsBadInputNamingTheFile) {
  const std::string corrupt = badShot("corrupt.glb");
  const auto run = lacrima({"info", corrupt});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, corrupt + R"(: not a glTF file: neither a GLB binary (magic "glTF") nor JSON)" + "\n");
}

TEST(CliInfo, MissingOrUnknownFile) {
  const std::string missing = sourcePath("scenes/assets/no_such.glb");
  auto run = lacrima({"info", missing});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, missing + ": no such file\n");
  const std::string json = sourcePath("tests/data/bad_shots/unknown_key.json");
  run = lacrima({"info", json});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_EQ(run.output, json + ": unknown file type '.json' (expected .glb, .gltf, .exr, .hdr or .png)\n");
}

// ---- real renders ----------------------------------------------------------------------------

TEST(CliRender, TinyRenderWritesEachFrameAndItsPreviewWithMetadata) {
  const fs::path dir = freshDir();
  const std::string drops = sourcePath("scenes/shots/test_drops.json");
  const Shot shot = loadShot(drops);
  const auto run = lacrima({"render", drops, "--width", "32", "--height", "18", "--spp", "2", "--out",
                            (dir / "t.####.exr").string(), "--preview", "--quiet"});
  ASSERT_EQ(run.exitStatus, 0) << run.output;

  std::set<std::string> expectedFiles;
  std::vector<std::string> exrs;
  for (int f = shot.frameStart; f <= shot.frameEnd; ++f) {
    const std::string exr = expandFramePattern("t.####.exr", f), png = expandFramePattern("t.####.png", f);
    expectedFiles.insert(exr);
    expectedFiles.insert(png);
    exrs.push_back(exr);
  }
  EXPECT_EQ(filesIn(dir), expectedFiles);

  // stderr: the shot's warnings first, then one summary line per frame (--quiet: no progress),
  // then the sequence's.
  const std::vector<std::string> lines = splitLines(run.output);
  const std::vector<std::string> warnings = splitLines(warningLines(shot));
  ASSERT_EQ(lines.size(), warnings.size() + exrs.size() + 1) << run.output;
  EXPECT_TRUE(startsWith(lines.back(), "lacrima: " + std::to_string(exrs.size()) + " frames: " +
                                           std::to_string(exrs.size()) + " rendered, 0 skipped, 0 failed in "))
      << lines.back();
  for (size_t i = 0; i < warnings.size(); ++i) EXPECT_EQ(lines[i], warnings[i]);
  for (size_t i = 0; i < exrs.size(); ++i) {
    const std::string& line = lines[warnings.size() + i];
    EXPECT_TRUE(startsWith(line, "frame " + std::to_string(shot.frameStart + int(i)) + ": 32x18, 2 spp, ")) << line;
    EXPECT_TRUE(endsWith(line, " 0 NaN/Inf samples discarded -> " + (dir / exrs[i]).string() + " + " +
                                   expandFramePattern("t.####.png", shot.frameStart + int(i))))
        << line;
  }

  const fs::path exr = dir / exrs.front();
  const auto input = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(input) << OIIO::geterror();
  EXPECT_EQ(input->spec().width, 32);
  EXPECT_EQ(input->spec().height, 18);
  input->close();

  const auto info = lacrima({"info", exr.string()});
  EXPECT_EQ(info.exitStatus, 0);
  EXPECT_TRUE(startsWith(info.output, exr.string() + "\n  32 x 18, 11 channels in 4 layers:\n    (beauty)             R G B A (half)"))
      << info.output;
  EXPECT_EQ(attributeLine(info.output, "lacrima:version"), std::string("  lacrima:version = ") + LACRIMA_VERSION);
  EXPECT_EQ(attributeLine(info.output, "lacrima:seed"), "  lacrima:seed = " + std::to_string(shot.render.seed));
  EXPECT_EQ(attributeLine(info.output, "lacrima:spp"), "  lacrima:spp = 2");
  EXPECT_EQ(attributeLine(info.output, "lacrima:frame"), "  lacrima:frame = " + std::to_string(shot.frameStart));
  EXPECT_EQ(attributeLine(info.output, "lacrima:shot"), "  lacrima:shot = " + drops);
  EXPECT_EQ(attributeLine(info.output, "compression"), "  compression = zip");
  // worldToCamera: the 16 numbers of the shot camera's matrix, in the order writeExr stores them.
  const std::string w2c = attributeLine(info.output, "worldToCamera");
  ASSERT_FALSE(w2c.empty()) << info.output;
  std::istringstream numbers(w2c.substr(std::string("  worldToCamera = ").size()));
  std::vector<float> values;
  for (std::string item; std::getline(numbers, item, ',');) values.push_back(std::stof(item));
  const Mat4 expected = worldToCameraMatrix(buildFrame(shot, shot.frameStart).camera);
  ASSERT_EQ(values.size(), 16u) << w2c;
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(values[i], expected.data()[i], 1e-5f) << "element " << i << " of " << w2c;
  EXPECT_FALSE(attributeLine(info.output, "worldToNDC").empty()) << info.output;
}

TEST(CliRender, OverridesReachTheExr) {
  const fs::path dir = freshDir();
  const std::string drops = sourcePath("scenes/shots/test_drops.json");
  const Shot shot = loadShot(drops);
  const std::string frame = std::to_string(shot.frameStart);
  const auto run = lacrima({"render", drops, "--frames", frame, "--width", "8", "--height", "8", "--spp", "1", "--seed",
                            "18446744073709551615", "--max-depth", "3", "--threads", "1", "--float", "--out",
                            (dir / "o.%04d.exr").string(), "--quiet"});
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  const std::string exr = expandFramePattern("o.####.exr", shot.frameStart);
  EXPECT_EQ(filesIn(dir), std::set<std::string>{exr});
  const auto info = lacrima({"info", (dir / exr).string()});
  EXPECT_EQ(info.exitStatus, 0);
  EXPECT_NE(info.output.find("  8 x 8, 11 channels in 4 layers:\n    (beauty)             R G B A (float)"), std::string::npos)
      << info.output;
  EXPECT_EQ(attributeLine(info.output, "lacrima:seed"), "  lacrima:seed = 18446744073709551615");
  EXPECT_EQ(attributeLine(info.output, "lacrima:spp"), "  lacrima:spp = 1");
  EXPECT_EQ(attributeLine(info.output, "lacrima:maxDepth"), "  lacrima:maxDepth = 3");
  // The defaults of what the shot leaves out: how its samples were drawn and filtered.
  EXPECT_EQ(attributeLine(info.output, "lacrima:sampler"), "  lacrima:sampler = sobol");
  EXPECT_EQ(attributeLine(info.output, "lacrima:filter"), "  lacrima:filter = blackman-harris 1.5 px");
}

// --region renders part of the frame into an EXR whose data window it is; info says so, the
// summary line names it, and --resume renders a frame again for another region.
TEST(CliRender, ARegionIsTheExrsDataWindowAndResumeKnowsIt) {
  const fs::path dir = freshDir();
  const std::string out = (dir / "r.####.exr").string();
  const fs::path shot = test::writeSphereShot(dir, 1, "");
  const auto render = [&](const std::string& region, bool resume) {
    std::vector<std::string> args = {"render", shot.string(), "--spp", "2", "--out", out, "--region", region};
    if (resume) args.push_back("--resume");
    return lacrima(args);
  };
  const auto first = render("4,3,10,6", false);
  ASSERT_EQ(first.exitStatus, 0) << first.output;
  EXPECT_NE(first.output.find("frame 1: 10x6 at (4, 3) of 32x18, 2 spp, "), std::string::npos) << first.output;
  const auto info = lacrima({"info", (dir / "r.0001.exr").string()});
  EXPECT_NE(info.output.find("  10 x 6, 11 channels in 4 layers:\n  a region of the 32 x 18 frame: its pixels from "
                             "(4, 3)\n"),
            std::string::npos)
      << info.output;
  const auto same = render("4,3,10,6", true);
  EXPECT_NE(same.output.find("1 skipped"), std::string::npos) << same.output;
  const auto moved = render("5,3,10,6", true);
  EXPECT_NE(moved.output.find("it holds the region 10x6 at (4, 3), this run renders 10x6 at (5, 3)"),
            std::string::npos)
      << moved.output;
  EXPECT_NE(moved.output.find("1 rendered, 0 skipped"), std::string::npos) << moved.output;
}

// --denoise adds the denoised layer (and says how long it took); --no-denoise overrides a shot
// that asks for it; the shot's adaptive sampling adds the samples channel and the mean spp.
TEST(CliRender, DenoiseAndAdaptiveSamplingReachTheExr) {
  const fs::path dir = freshDir();
  const std::string out = (dir / "s.####.exr").string();
  const fs::path shot = test::writeSphereShot(dir, 1, R"(, "adaptive": {"threshold": 0.05, "minSpp": 2}, "denoise": true)");
  const auto on = lacrima({"render", shot.string(), "--spp", "4", "--out", out});
  ASSERT_EQ(on.exitStatus, 0) << on.output;
  EXPECT_NE(on.output.find("frame 1: 32x18, 4 spp max, "), std::string::npos) << on.output;
  EXPECT_NE(on.output.find(", denoised in "), std::string::npos) << on.output;
  const std::string exr = (dir / "s.0001.exr").string();
  auto info = lacrima({"info", exr});
  EXPECT_NE(info.output.find("15 channels"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("    samples              (float)"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("    denoised             R G B (half)"), std::string::npos) << info.output;
  EXPECT_EQ(attributeLine(info.output, "lacrima:denoise"), "  lacrima:denoise = on");
  EXPECT_EQ(attributeLine(info.output, "lacrima:adaptive"), "  lacrima:adaptive = threshold 0.05 min 2 spp");

  const auto off = lacrima({"render", shot.string(), "--spp", "4", "--out", out, "--no-denoise", "--quiet"});
  ASSERT_EQ(off.exitStatus, 0) << off.output;
  info = lacrima({"info", exr});
  EXPECT_NE(info.output.find("12 channels"), std::string::npos) << info.output;
  EXPECT_EQ(attributeLine(info.output, "lacrima:denoise"), "  lacrima:denoise = off");
  const auto both = lacrima({"render", shot.string(), "--denoise", "--no-denoise", "--out", out});
  EXPECT_EQ(both.exitStatus, 2) << both.output;
}

// The shot's Cryptomattes reach the EXR, and lacrima info lists their layers and manifests.
TEST(CliRender, CryptomattesReachTheExrAndInfoListsThem) {
  const fs::path dir = freshDir();
  const fs::path shot = test::writeSphereShot(dir, 1, R"(, "aovs": ["CryptoObject", "CryptoMaterial"])");
  const std::string exr = (dir / "c.0001.exr").string();
  const auto rendered = lacrima({"render", shot.string(), "--out", (dir / "c.####.exr").string(), "--quiet"});
  ASSERT_EQ(rendered.exitStatus, 0) << rendered.output;
  const auto info = lacrima({"info", exr});
  EXPECT_NE(info.output.find("35 channels in 10 layers"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("    CryptoObject02       R G B A (float)"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("  Cryptomatte CryptoObject (key " + cryptomatteKey("CryptoObject") +
                             ", MurmurHash3_32, uint32_to_float32): "),
            std::string::npos)
      << info.output;
  EXPECT_NE(info.output.find("  Cryptomatte CryptoMaterial (key "), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("    sphere 0                                 " + cryptomatteHex(cryptomatteIdOf("sphere 0"))),
            std::string::npos)
      << info.output;

  // --aov adds a layer to the shot's; an unknown one is refused with the names it takes.
  const auto groups = lacrima({"render", shot.string(), "--out", (dir / "g.####.exr").string(), "--aov", "lightGroups", "--quiet"});
  ASSERT_EQ(groups.exitStatus, 0) << groups.output;
  const auto groupInfo = lacrima({"info", (dir / "g.0001.exr").string()});
  EXPECT_NE(groupInfo.output.find("    lightgroup_environment R G B (float)"), std::string::npos) << groupInfo.output;
  EXPECT_NE(groupInfo.output.find("    CryptoObject00"), std::string::npos) << "the shot's stay" << groupInfo.output;
  const auto paths = lacrima({"render", shot.string(), "--out", (dir / "p.####.exr").string(), "--aov", "lightPaths", "--quiet"});
  ASSERT_EQ(paths.exitStatus, 0) << paths.output;
  const auto pathInfo = lacrima({"info", (dir / "p.0001.exr").string()});
  // The names are padded to the longest (transmission_indirect) so the channels line up.
  for (const char* pass : {"    diffuse_direct        R G B (float)", "    transmission_indirect R G B (float)"})
    EXPECT_NE(pathInfo.output.find(pass), std::string::npos) << pass << pathInfo.output;
  const auto unknown = lacrima({"render", shot.string(), "--out", (dir / "u.####.exr").string(), "--aov", "glitter"});
  EXPECT_EQ(unknown.exitStatus, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("CryptoObject"), std::string::npos) << unknown.output;
  EXPECT_FALSE(fs::exists(dir / "u.0001.exr"));
}

TEST(CliRender, WarningsComeBeforeRenderingAndFrameStepsAreHonoured) {
  const fs::path dir = freshDir();
  const fs::path shot = writeWarningShot(dir);  // frames 1-3, output out/warn.####.exr next to it
  const auto run = lacrima({"render", shot.string(), "--frames", "1-3x2", "--quiet"});
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  EXPECT_TRUE(startsWith(run.output, warningShotWarning(shot) + "frame 1: 8x8, 1 spp, ")) << run.output;
  EXPECT_EQ(splitLines(run.output).size(), 4u) << run.output;  // the warning, frames 1 and 3, the summary
  EXPECT_EQ(filesIn(dir), (std::set<std::string>{"warn.json", "out/warn.0001.exr", "out/warn.0003.exr"}));
}

TEST(CliBench, SphReportsParticleUpdatesPerSecondAndRejectsBadCounts) {
  auto run = lacrima({"bench", "--sph", "--particles", "2000", "--steps", "2", "--threads", "1"});
  EXPECT_EQ(run.exitStatus, 0) << run.output;
  EXPECT_NE(run.output.find("dam break, 2048 particles"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("particle updates/s"), std::string::npos) << run.output;
  run = lacrima({"bench", "--sph", "--particles", "-5"});
  EXPECT_EQ(run.exitStatus, 2) << run.output;
  EXPECT_NE(run.output.find("--particles"), std::string::npos) << run.output;
}

}  // namespace cli_test
}  // namespace lacrima
