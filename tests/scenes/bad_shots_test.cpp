// Every bad shot file in tests/data/bad_shots gives a ShotError with exactly these messages:
// file:line:column, JSON pointer, what was expected and found, the source line and a caret.
#include <gtest/gtest.h>

#include "shot_support.hpp"

namespace lacrima {
namespace bad_shots_test {

using test::joinLines;
using test::shotErrorOf;

std::string badShot(const std::string& name) { return test::sourcePath("tests/data/bad_shots/" + name).string(); }

TEST(BadShots, SyntaxErrorGivesLineColumnAndCaret) {
  const std::string f = badShot("syntax_error.json");
  std::vector<Diagnostic> diagnostics;
  EXPECT_EQ(shotErrorOf(f, &diagnostics),
            joinLines({f + ":5:50: JSON syntax error: syntax error while parsing object key - unexpected '}'; "
                           "expected string literal",
                       R"(      "render": {"width": 32, "height": 32, "spp": 4,},)",
                       R"(                                                     ^)"}));
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].line, 5);
  EXPECT_EQ(diagnostics[0].column, 50);
  EXPECT_EQ(diagnostics[0].jsonPath, "");
}

TEST(BadShots, UnknownTopLevelKeySuggestsClosest) {
  const std::string f = badShot("unknown_key.json");
  EXPECT_EQ(shotErrorOf(f), joinLines({f + ":7:3: /backgruond: unknown key 'backgruond'; did you mean 'background'?",
                                       R"(      "backgruond": [1, 1, 1])", R"(      ^)"}));
}

TEST(BadShots, UnknownBlendshapeSuggestsClosestTargetOfTheFace) {
  const std::string f = badShot("unknown_blendshape.json");
  EXPECT_EQ(shotErrorOf(f),
            joinLines({f + ":11:23: /assets/0/blendshapes/browInnerUp_l: unknown blendshape 'browInnerUp_l'; did you "
                           "mean 'browInnerUp_L'?",
                       R"(          "blendshapes": {"browInnerUp_l": 0.5, "jawOpen": 0.2})",
                       R"(                          ^)"}));
}

TEST(BadShots, NegativeSamplesPerPixel) {
  const std::string f = badShot("negative_spp.json");
  EXPECT_EQ(shotErrorOf(f), joinLines({f + ":5:48: /render/spp: expected an integer >= 1, found -4",
                                       R"(      "render": {"width": 32, "height": 32, "spp": -4},)",
                                       R"(                                                   ^)"}));
}

TEST(BadShots, StringWhereANumberIsExpected) {
  const std::string f = badShot("wrong_type.json");
  EXPECT_EQ(shotErrorOf(f), joinLines({f + R"(:5:23: /render/width: expected an integer in [1, 16384], found "64")",
                                       R"(      "render": {"width": "64", "height": 32, "spp": 4},)",
                                       R"(                          ^)"}));
}

TEST(BadShots, MissingRequiredField) {
  const std::string f = badShot("missing_field.json");
  EXPECT_EQ(shotErrorOf(f), joinLines({f + ":5:3: /render: missing required key 'spp' (an integer >= 1)",
                                       R"(      "render": {"width": 32, "height": 32},)", R"(      ^)"}));
}

TEST(BadShots, UndefinedMaterialSuggestsClosest) {
  const std::string f = badShot("undefined_material.json");
  EXPECT_EQ(shotErrorOf(f),
            joinLines({f + ":11:72: /shapes/0/material: undefined material 'tears'; did you mean 'tear'?",
                       R"(        {"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "tears"})",
                       R"(                                                                           ^)"}));
}

TEST(BadShots, MissingAssetFile) {
  const std::string f = badShot("missing_asset.json");
  EXPECT_EQ(shotErrorOf(f), joinLines({f + ":8:30: /assets/0/file: file not found: 'no_such_face.glb' (resolved to '" +
                                           badShot("no_such_face.glb") + "')",
                                       R"(        {"name": "face", "file": "no_such_face.glb"})",
                                       R"(                                 ^)"}));
}

TEST(BadShots, CorruptAssetFile) {
  const std::string f = badShot("corrupt_asset.json");
  EXPECT_EQ(shotErrorOf(f),
            joinLines({f + ":8:30: /assets/0/file: cannot load the glTF asset: " + badShot("corrupt.glb") +
                           R"(: not a glTF file: neither a GLB binary (magic "glTF") nor JSON)",
                       R"(        {"name": "face", "file": "corrupt.glb"})", R"(                                 ^)"}));
}

TEST(BadShots, SeveralErrorsAreAllReportedInFileOrder) {
  const std::string f = badShot("several_errors.json");
  std::vector<Diagnostic> diagnostics;
  const std::string message = shotErrorOf(f, &diagnostics);
  const std::vector<std::string> expected = {
      f + ":3:37: /frames/fsp: unknown key 'fsp'; did you mean 'fps'?",
      R"(      "frames": {"start": 1, "end": 48, "fsp": 24},)",
      R"(                                        ^)",
      f + ":4:13: /output: 'renders/still.exr' has no frame number field ('####' or '%04d') but the shot has frames "
          "1-48: every frame would overwrite the last",
      R"(      "output": "renders/still.exr",)",
      R"(                ^)",
      f + ":5:23: /render/width: expected an integer in [1, 16384], found 0",
      R"(      "render": {"width": 0, "height": 32, "spp": 4.5, "floatOutput": "yes"},)",
      R"(                          ^)",
      f + ":5:47: /render/spp: expected an integer >= 1, found 4.5",
      R"(      "render": {"width": 0, "height": 32, "spp": 4.5, "floatOutput": "yes"},)",
      R"(                                                  ^)",
      f + R"(:5:67: /render/floatOutput: expected true or false, found "yes")",
      R"(      "render": {"width": 0, "height": 32, "spp": 4.5, "floatOutput": "yes"},)",
      R"(                                                                      ^)",
      f + ":6:47: /camera/lookAt: expected [x, y, z] (an array of 3 numbers), found an array of 2 elements",
      R"(      "camera": {"position": [0, 0, 3], "lookAt": [0, 0], "fov": 200, "fStop": -2},)",
      R"(                                                  ^)",
      f + ":6:62: /camera/fov: expected a number in (0, 180), found 200",
      R"(      "camera": {"position": [0, 0, 3], "lookAt": [0, 0], "fov": 200, "fStop": -2},)",
      R"(                                                                 ^)",
      f + ":6:76: /camera/fStop: expected a number > 0, found -2",
      R"(      "camera": {"position": [0, 0, 3], "lookAt": [0, 0], "fov": 200, "fStop": -2},)",
      R"(                                                                               ^)",
      f + ":8:38: /materials/tear/ior: expected a number in (1, 3], found 0.9",
      R"(        "tear": {"type": "water", "ior": 0.9},)",
      R"(                                         ^)",
      f + ":9:22: /materials/skin/type: unknown material type 'skinn'; did you mean 'skin'?",
      R"(        "skin": {"type": "skinn"},)",
      R"(                         ^)",
      f + ":10:50: /materials/plane/albedo/1: expected a number in [0, 1], found 1.5",
      R"(        "plane": {"type": "diffuse", "albedo": [0.5, 1.5, 0.5]})",
      R"(                                                     ^)",
      f + ":13:5: /lights/0: missing required key 'radiance' ([r, g, b] in W/(m^2 sr); or 'power' in watts)",
      R"(        {"type": "rectangle", "center": [0, 1, 0], "size": [0.2, 0.2], "normal": [0, -1, 0]},)",
      R"(        ^)",
      f + ":14:83: /lights/1/power: give either 'radiance' or 'power', not both",
      R"(        {"type": "sphere", "center": [0, 1, 0], "radius": 0.1, "radiance": [1, 1, 1], "power": 5})",
      R"(                                                                                      ^)",
      f + ":17:55: /shapes/0/radius: expected a number > 0, found -1",
      R"(        {"type": "sphere", "center": [0, 0, 0], "radius": -1, "material": "water"})",
      R"(                                                          ^)",
      f + ":17:71: /shapes/0/material: undefined material 'water' (defined materials: 'tear', 'skin', 'plane')",
      R"(        {"type": "sphere", "center": [0, 0, 0], "radius": -1, "material": "water"})",
      R"(                                                                          ^)",
  };
  EXPECT_EQ(message, joinLines(expected));
  EXPECT_EQ(diagnostics.size(), expected.size() / 3);
}

}  // namespace bad_shots_test
}  // namespace lacrima
