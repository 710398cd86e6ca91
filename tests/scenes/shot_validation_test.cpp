// Shot-file rules checked on small shots written by the tests: defaults, strictness (unknown
// keys, duplicates, versions), derived values (light power, transforms) and message details.
#include <gtest/gtest.h>

#include "shot_support.hpp"

namespace lacrima {
namespace shot_validation_test {

using test::shotErrorOf;
using test::writeShot;

// A valid shot on one line per section; `extra` is inserted as further top-level members.
std::string shotText(const std::string& extra = "",
                     const std::string& camera = R"({"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30})") {
  return "{\n"
         "  \"version\": 1,\n"
         "  \"frames\": {\"start\": 1, \"end\": 1},\n"
         "  \"output\": \"out.exr\",\n"
         "  \"render\": {\"width\": 16, \"height\": 8, \"spp\": 1},\n"
         "  \"camera\": " +
         camera + (extra.empty() ? "" : ",\n  " + extra) + "\n}\n";
}

std::string firstLine(const std::string& s) { return s.substr(0, s.find('\n')); }

// A committed file by its absolute path: shots written by the tests live under the build folder,
// which may be anywhere, so a path relative to them would not find the source tree.
std::string sourceFile(const std::string& relative) { return test::sourcePath(relative).string(); }

TEST(ShotValidation, MinimalShotGetsDocumentedDefaults) {
  const auto path = writeShot("minimal.json", "// comments are allowed\n" + shotText("/* here too */ \"shapes\": []"));
  const Shot shot = loadShot(path);
  EXPECT_EQ(shot.fps, 24.0);
  EXPECT_EQ(shot.render.maxDepth, 12);
  EXPECT_EQ(shot.render.seed, 0u);
  EXPECT_EQ(shot.render.threads, 0);
  EXPECT_FALSE(shot.render.floatOutput);
  EXPECT_TRUE((shot.background == Color(0, 0, 0)).all());
  EXPECT_EQ(shot.outputPattern, (path.parent_path() / "out.exr").string());  // one frame: no #### needed
  EXPECT_EQ(shot.camera.camera.focusDistance, 3.0f);
  EXPECT_TRUE(shot.materials.empty() && shot.lights.empty() && shot.assets.empty() && shot.shapes.empty());
}

TEST(ShotValidation, MissingShotFile) {
  const std::string f = (std::filesystem::path(LACRIMA_TEST_OUTPUT_DIR) / "no_such_shot.json").string();
  EXPECT_EQ(shotErrorOf(f), f + ": cannot read the shot file: No such file or directory");
}

TEST(ShotValidation, EmptyFileIsASyntaxErrorAtTheStart) {
  const auto f = writeShot("empty.json", "");
  EXPECT_EQ(firstLine(shotErrorOf(f)), f.string() +
                                           ":1:1: JSON syntax error: syntax error while parsing value - "
                                           "unexpected end of input; expected '[', '{', or a literal");
}

TEST(ShotValidation, MissingCommaPointsAtTheUnexpectedString) {
  const auto f = writeShot("missing_comma.json", "{\n  \"version\": 1\n  \"frames\": {}\n}\n");
  EXPECT_EQ(shotErrorOf(f), f.string() +
                                ":3:3: JSON syntax error: syntax error while parsing object - unexpected string "
                                "literal; expected '}'\n"
                                "      \"frames\": {}\n"
                                "      ^");
}

TEST(ShotValidation, TopLevelMustBeAnObject) {
  const auto f = writeShot("array.json", "[1, 2]\n");
  EXPECT_EQ(shotErrorOf(f), f.string() + ":1:1: expected an object, found an array of 2 elements\n    [1, 2]\n    ^");
}

TEST(ShotValidation, DuplicateKeysAreErrors) {
  const auto f = writeShot("duplicate.json", shotText("\"version\": 1"));
  EXPECT_EQ(firstLine(shotErrorOf(f)), f.string() +
                                           ":7:3: /version: duplicate key 'version' (first given at line 2, "
                                           "column 3)");
}

TEST(ShotValidation, UnsupportedVersionStopsTheSectionChecks) {
  std::string text = shotText("\"nonsense\": 1");
  text.replace(text.find("\"version\": 1"), 12, "\"version\": 2");
  const auto f = writeShot("version2.json", text);
  EXPECT_EQ(firstLine(shotErrorOf(f)),
            f.string() + ":2:14: /version: unsupported version 2: this lacrima reads shot files of version 1");
  std::vector<Diagnostic> diagnostics;
  shotErrorOf(f, &diagnostics);
  EXPECT_EQ(diagnostics.size(), 2u);  // the unknown key is still reported (keys are checked first)
}

TEST(ShotValidation, MisspelledRequiredKeyIsReportedOnceAsATypo) {
  std::string text = shotText();
  text.replace(text.find("\"camera\""), 8, "\"camrea\"");
  const auto f = writeShot("camrea.json", text);
  std::vector<Diagnostic> diagnostics;
  EXPECT_EQ(firstLine(shotErrorOf(f, &diagnostics)),
            f.string() + ":6:3: /camrea: unknown key 'camrea'; did you mean 'camera'?");
  EXPECT_EQ(diagnostics.size(), 1u);  // no "missing required key 'camera'" on top
}

TEST(ShotValidation, UnknownKeyWithoutCloseMatchListsAllowedKeys) {
  const auto f = writeShot("unrelated_key.json", shotText("\"environment\": {\"file\": \"x.exr\", \"zzz\": 1}"));
  std::vector<Diagnostic> diagnostics;
  shotErrorOf(f, &diagnostics);
  ASSERT_EQ(diagnostics.size(), 2u);
  EXPECT_EQ(diagnostics[0].jsonPath, "/environment/file");
  EXPECT_EQ(firstLine(diagnostics[0].message),
            "file not found: 'x.exr' (resolved to '" + (f.parent_path() / "x.exr").string() + "')");
  EXPECT_EQ(diagnostics[1].jsonPath, "/environment/zzz");
  EXPECT_EQ(firstLine(diagnostics[1].message), "unknown key 'zzz' (allowed here: file, intensity, rotation)");
}

TEST(ShotValidation, OutputNeedsAFrameFieldOnlyForSeveralFrames) {
  std::string text = shotText();
  text.replace(text.find("\"end\": 1"), 8, "\"end\": 3");
  const auto f = writeShot("no_frame_field.json", text);
  EXPECT_EQ(firstLine(shotErrorOf(f)), f.string() +
                                           ":4:13: /output: 'out.exr' has no frame number field ('####' or '%04d') but "
                                           "the shot has frames 1-3: every frame would overwrite the last");
  text.replace(text.find("out.exr"), 7, "out.%04d.exr");
  EXPECT_NO_THROW(loadShot(writeShot("printf_frame_field.json", text)));
}

TEST(ShotValidation, EndFrameBeforeStart) {
  std::string text = shotText();
  text.replace(text.find("\"start\": 1"), 10, "\"start\": 5");
  const auto f = writeShot("end_before_start.json", text);
  EXPECT_EQ(firstLine(shotErrorOf(f)), f.string() + ":3:33: /frames/end: expected an integer >= 5, found 1");
}

TEST(ShotValidation, BackgroundAndEnvironmentAreExclusive) {
  const auto f = writeShot("both_backgrounds.json",
                           shotText("\"environment\": {\"file\": \"" + sourceFile("scenes/assets/hdri/studio.exr") + "\"}, "
                                    "\"background\": [1, 1, 1]"));
  std::vector<Diagnostic> diagnostics;
  shotErrorOf(f, &diagnostics);
  ASSERT_GE(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics.back().jsonPath, "/background");
  EXPECT_EQ(firstLine(diagnostics.back().message),
            "'background' and 'environment' cannot both be given: the uniform background is used only without an "
            "environment map");
}

TEST(ShotValidation, CameraUpParallelToTheViewDirection) {
  const auto f =
      writeShot("up_parallel.json", shotText("", R"({"position": [0, 3, 0], "lookAt": [0, 0, 0], "fov": 30})"));
  EXPECT_EQ(
      firstLine(shotErrorOf(f)),
      f.string() + ":6:47: /camera/lookAt: the view direction is parallel to the default 'up' [0, 1, 0]; give 'up'");
  const auto g = writeShot(
      "up_given.json", shotText("", R"({"position": [0, 3, 0], "lookAt": [0, 0, 0], "up": [0, 0, -1], "fov": 30})"));
  const Shot shot = loadShot(g);
  const Vec3 down = shot.camera.camera.cameraToWorld.linear() * Vec3(0, 0, -1);
  EXPECT_NEAR(down.y(), -1.0f, 1e-6f);
}

TEST(ShotValidation, FovAndFocalLengthAreAlternatives) {
  const auto f =
      writeShot("fov_and_focal.json",
                shotText("", R"({"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30, "focalLength": 50})"));
  EXPECT_EQ(firstLine(shotErrorOf(f)),
            f.string() + ":6:69: /camera/focalLength: give either 'fov' or 'focalLength', not both");
  const auto g = writeShot("no_fov.json", shotText("", R"({"position": [0, 0, 3], "lookAt": [0, 0, 0]})"));
  EXPECT_EQ(firstLine(shotErrorOf(g)), g.string() +
                                           ":6:3: /camera: missing required key 'fov' (vertical field of view "
                                           "in degrees; or 'focalLength' in mm)");
}

TEST(ShotValidation, ThinLensFromFovAndFocusDistance) {
  const auto f = writeShot(
      "thin_lens.json",
      shotText("", R"({"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30, "fStop": 2, "focusDistance": 2.5})"));
  const Shot shot = loadShot(f);
  const float focalMm = 24.0f / (2.0f * std::tan(degreesToRadians(15.0f)));
  EXPECT_NEAR(shot.camera.camera.lensRadius, focalMm * 1e-3f / 4.0f, 1e-7f);
  EXPECT_FLOAT_EQ(shot.camera.camera.focusDistance, 2.5f);
}

// "focus": "surface" hands the renderer a camera that focuses on the first surface on its view axis
// (the look-at distance stays as the fallback); a misspelt mode and a second way of focusing are
// errors naming the key.
TEST(ShotValidation, FocusOnTheSurfaceOrAtTheLookAtPoint) {
  const auto f = writeShot(
      "focus_surface.json",
      shotText("", R"({"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30, "fStop": 2, "focus": "surface"})"));
  const Shot shot = loadShot(f);
  EXPECT_TRUE(shot.camera.camera.focusOnSurface);
  EXPECT_FLOAT_EQ(shot.camera.camera.focusDistance, 3.0f);
  const auto g = writeShot(
      "focus_look_at.json",
      shotText("", R"({"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30, "fStop": 2, "focus": "lookAt"})"));
  EXPECT_FALSE(loadShot(g).camera.camera.focusOnSurface);
  const auto pinhole =
      writeShot("focus_pinhole.json", shotText("", R"({"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30, "focus": "surface"})"));
  const Shot pinholeShot = loadShot(pinhole);
  ASSERT_EQ(pinholeShot.warnings.size(), 1u);
  EXPECT_NE(pinholeShot.warnings[0].message.find("'focus' has no effect without 'fStop'"), std::string::npos)
      << pinholeShot.warnings[0].message;
  const auto typo = writeShot(
      "focus_typo.json",
      shotText("", R"({"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30, "fStop": 2, "focus": "surfce"})"));
  EXPECT_EQ(firstLine(shotErrorOf(typo)),
            typo.string() + ":6:90: /camera/focus: unknown focus 'surfce'; did you mean 'surface'?");
  const auto both = writeShot("focus_both.json", shotText("", R"({"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30,
     "fStop": 2, "focus": "surface", "focusDistance": 2})"));
  EXPECT_NE(firstLine(shotErrorOf(both)).find("/camera/focus: give either 'focusDistance' or 'focus', not both"),
            std::string::npos)
      << shotErrorOf(both);
}

TEST(ShotValidation, LightPowerBecomesRadiance) {
  const auto f = writeShot("light_power.json", shotText(R"("lights": [
    {"type": "rectangle", "center": [0, 1, 0], "u": [0.5, 0, 0], "v": [0, 0, -0.2], "power": [2, 4, 6], "twoSided": true},
    {"type": "rectangle", "center": [0, 1, 0], "u": [0.5, 0, 0], "v": [0, 0, -0.2], "radiance": [1, 2, 3]}
  ])"));
  const Shot shot = loadShot(f);
  ASSERT_EQ(shot.lights.size(), 2u);
  const float area = 0.1f;
  // Two-sided: the power leaves through both sides, L = P / (2 pi A).
  EXPECT_NEAR(shot.lights[0].light.radiance.x(), 2.0f / (2.0f * kPi * area), 1e-4f);
  EXPECT_NEAR(shot.lights[0].light.radiance.z(), 6.0f / (2.0f * kPi * area), 1e-4f);
  EXPECT_TRUE(shot.lights[0].light.twoSided);
  EXPECT_TRUE(shot.lights[0].light.edgeU == Vec3(0.5f, 0, 0));
  EXPECT_NEAR(shot.lights[0].light.edgeU.cross(shot.lights[0].light.edgeV).normalized().y(), 1.0f, 1e-6f);
  EXPECT_TRUE((shot.lights[1].light.radiance == Color(1, 2, 3)).all());
}

TEST(ShotValidation, ALightNamesItsLightGroup) {
  const auto f = writeShot("light_group.json", shotText(R"("lights": [
    {"type": "rectangle", "center": [0, 1, 0], "u": [0.5, 0, 0], "v": [0, 0, -0.2], "power": 2, "lightGroup": "key"},
    {"type": "sphere", "center": [0, 1, 0], "radius": 0.1, "power": 1, "lightGroup": "key"},
    {"type": "sphere", "center": [1, 1, 0], "radius": 0.1, "power": 1}
  ])"));
  const Shot shot = loadShot(f);
  ASSERT_EQ(shot.lights.size(), 3u);
  EXPECT_EQ(shot.lights[0].light.group, "key");
  EXPECT_EQ(shot.lights[1].light.group, "key");
  EXPECT_EQ(shot.lights[2].light.group, "");
  const auto empty = writeShot("light_group_empty.json", shotText(R"("lights": [
    {"type": "sphere", "center": [0, 1, 0], "radius": 0.1, "power": 1, "lightGroup": ""}])"));
  std::vector<Diagnostic> diagnostics;
  test::shotErrorOf(empty, &diagnostics);
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].jsonPath, "/lights/0/lightGroup");
}

TEST(ShotValidation, RectangleEdgesAndSizeCannotBeMixed) {
  const auto f = writeShot("rectangle_mixed.json", shotText(R"("materials": {"grey": {"type": "diffuse"}},
  "shapes": [{"type": "rectangle", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, 0, -1], "size": [1, 1], "material": "grey"}])"));
  EXPECT_EQ(firstLine(shotErrorOf(f)),
            f.string() + ":8:90: /shapes/0/size: 'size' cannot be combined with the edges 'u' and 'v'");
}

TEST(ShotValidation, TransformScalesRotatesThenTranslates) {
  ShotTransform t;
  t.translate = Vec3(1, 2, 3);
  t.scale = Vec3(2, 2, 2);
  t.rotation = Eigen::AngleAxisf(kPi / 2, Vec3::UnitY()).toRotationMatrix();
  const Vec3 x = t.matrix() * Vec3(1, 0, 0);
  EXPECT_NEAR((x - Vec3(1, 2, 1)).norm(), 0.0f, 1e-6f);  // X -> -Z, doubled, moved
}

TEST(ShotValidation, EulerAndAxisAngleRotations) {
  const auto f = writeShot("rotations.json", shotText(R"("materials": {"grey": {"type": "diffuse"}},
  "shapes": [
    {"type": "ellipsoid", "center": [0, 0, 0], "radii": [1, 2, 3], "rotate": [90, 0, 90], "material": "grey"},
    {"type": "ellipsoid", "center": [0, 0, 0], "radii": [1, 2, 3], "rotate": {"axis": [0, 0, 2], "angle": 90}, "material": "grey"}
  ])"));
  const Shot shot = loadShot(f);
  ASSERT_EQ(shot.shapes.size(), 2u);
  // XYZ order: X first (Y -> Z), then Z (X -> Y): R * Y = Z, R * X = Y.
  EXPECT_NEAR((shot.shapes[0].rotation * Vec3(0, 1, 0) - Vec3(0, 0, 1)).norm(), 0.0f, 1e-6f);
  EXPECT_NEAR((shot.shapes[0].rotation * Vec3(1, 0, 0) - Vec3(0, 1, 0)).norm(), 0.0f, 1e-6f);
  EXPECT_NEAR((shot.shapes[1].rotation * Vec3(1, 0, 0) - Vec3(0, 1, 0)).norm(), 0.0f, 1e-6f);
}

TEST(ShotValidation, AssetNamesPartsWeightsAndCamerasAreChecked) {
  const auto f = writeShot("face_problems.json",
                           shotText(R"("materials": {"skin": {"type": "skin"}},
  "assets": [{"name": "face", "file": ")" + sourceFile("scenes/assets/ict-face/ict_face.glb") + R"(",
    "materials": {"M_Fcae": "skin"}, "blendshapes": {"jawOpen": 1.5}, "hide": ["M_Teth"]}])",
                                    R"({"gltf": {"asset": "face", "camera": "closeup"}})"));
  std::vector<Diagnostic> diagnostics;
  shotErrorOf(f, &diagnostics);
  std::vector<std::string> lines;
  for (const Diagnostic& d : diagnostics) lines.push_back(d.jsonPath + ": " + firstLine(d.message));
  EXPECT_EQ(lines, (std::vector<std::string>{
                       "/camera/gltf/camera: asset 'face' has no camera 'closeup' (it has no cameras)",
                       "/assets/0/materials/M_Fcae: asset 'face' has no part or material named 'M_Fcae'; did you "
                       "mean 'M_Face'?",
                       "/assets/0/blendshapes/jawOpen: expected a number in [0, 1], found 1.5",
                       "/assets/0/hide/0: asset 'face' has no part or material named 'M_Teth'; did you mean 'M_Teeth'?",
                   }));
}

// A glTF camera in an asset that fails to load: the asset's error, and no crash.
TEST(ShotValidation, GltfCameraOfAMissingAssetReportsTheAssetOnly) {
  const auto f = writeShot("camera_of_missing_asset.json",
                           shotText(R"("assets": [{"name": "face", "file": "nope.glb"}])",
                                    R"({"gltf": {"asset": "face", "camera": "closeup"}})"));
  std::vector<Diagnostic> diagnostics;
  shotErrorOf(f, &diagnostics);
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].jsonPath, "/assets/0/file");
  EXPECT_EQ(firstLine(diagnostics[0].message),
            "file not found: 'nope.glb' (resolved to '" + (f.parent_path() / "nope.glb").string() + "')");
}

TEST(ShotValidation, ColorConfigIsResolvedAndMustExist) {
  const auto f = writeShot("color_config.json", shotText(R"("colorConfig": "missing.ocio")"));
  EXPECT_EQ(firstLine(shotErrorOf(f)), f.string() +
                                           ":7:18: /colorConfig: file not found: 'missing.ocio' (resolved to '" +
                                           (f.parent_path() / "missing.ocio").string() + "')");
}

TEST(ShotValidation, LongLinesAreCutAroundTheColumnInExcerpts) {
  std::string text = shotText();
  text.replace(text.find("\"spp\": 1"), 8, "\"spp\": 0" + std::string(200, ' '));
  text.replace(text.find("\"output\""), 8, std::string(150, ' ') + "\"output\"");
  const auto f = writeShot("long_line.json", text);
  const std::string message = shotErrorOf(f);
  const std::string excerpt = message.substr(message.find('\n') + 1);
  const std::string sourceLine = excerpt.substr(0, excerpt.find('\n'));
  EXPECT_LE(sourceLine.size(), 4u + 3u + 100u + 3u);
  // The caret sits under the offending value.
  const std::string caretLine = excerpt.substr(excerpt.find('\n') + 1);
  EXPECT_EQ(sourceLine.substr(caretLine.size() - 1, 1), "0");
}

}  // namespace shot_validation_test
}  // namespace lacrima
