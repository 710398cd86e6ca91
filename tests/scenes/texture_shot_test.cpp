// Texture maps of diffuse and skin materials in a shot file ("textures", docs/shot-format.md):
// paths relative to the shot, the albedo factor defaulting to 1 with a map, the colour space
// override, exact messages for missing and unreadable files and misplaced maps, the warning for
// meshes without uvs, and the ICT face's uvs reaching the frame.
#include <gtest/gtest.h>

#include <fstream>

#include "shot_support.hpp"

namespace lacrima {
namespace texture_shot_test {

std::string shotWithMaterials(const std::string& materials, const std::string& extra = "") {
  return "{\n  \"version\": 1,\n  \"frames\": {\"start\": 1, \"end\": 1},\n  \"output\": \"out.exr\",\n"
         "  \"render\": {\"width\": 16, \"height\": 8, \"spp\": 1},\n"
         "  \"camera\": {\"position\": [0, 0, 3], \"lookAt\": [0, 0, 0], \"fov\": 30},\n"
         "  \"materials\": {" + materials + "}" + (extra.empty() ? "" : ",\n  " + extra) + "\n}\n";
}

// A 2 x 2 binary PPM next to the shot files (OIIO reads PNM), named `name`.
std::filesystem::path writeImage(const std::string& name) {
  const std::filesystem::path path = test::testDirectory("shots") / name;
  std::ofstream out(path, std::ios::binary);
  out << "P6\n2 2\n255\n";
  for (int i = 0; i < 4; ++i) out << char(200) << char(150) << char(120);
  return path;
}

std::string skinWithTextures(const std::string& textures, const std::string& members = "") {
  return R"("skin": {"type": "skin")" + members + R"(, "textures": )" + textures + "}";
}

TEST(TextureShot, ReadsMapsRelativeToTheShotFile) {
  const auto dir = writeImage("albedo.ppm").parent_path();
  writeImage("roughness.ppm");
  writeImage("normal.ppm");
  writeImage("mfp.ppm");
  const Shot shot = loadShot(test::writeShot(
      "textured_skin.json",
      shotWithMaterials(skinWithTextures(R"({"albedo": {"file": "albedo.ppm", "colorSpace": "linear"},
          "roughness": "roughness.ppm", "normal": {"file": "normal.ppm"}, "meanFreePath": "mfp.ppm"})",
                                         R"(, "subsurface": {})"))));
  const MaterialTextures& t = shot.materials.at(0).textures;
  ASSERT_TRUE(t.albedo && t.roughness && t.normal && t.meanFreePath);
  EXPECT_EQ(t.albedo->file, dir / "albedo.ppm");
  EXPECT_EQ(t.albedo->encoding, TextureEncoding::Linear);
  EXPECT_EQ(t.roughness->file, dir / "roughness.ppm");
  EXPECT_EQ(t.roughness->encoding, TextureEncoding::Auto);
  EXPECT_EQ(t.meanFreePath->file, dir / "mfp.ppm");
  // With an albedo map the albedo constant is a factor, 1 unless given.
  EXPECT_TRUE((std::get<SkinParams>(shot.materials[0].params).albedo == Color::Ones()).all());
}

TEST(TextureShot, AnAlbedoGivenWithAMapIsKeptAsItsFactor) {
  writeImage("albedo.ppm");
  const Shot shot = loadShot(test::writeShot(
      "textured_diffuse.json",
      shotWithMaterials(R"("paint": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5], "textures": {"albedo": "albedo.ppm"}})")));
  EXPECT_TRUE((std::get<DiffuseParams>(shot.materials[0].params).albedo == Color::Constant(0.5f)).all());
  EXPECT_TRUE(shot.materials[0].textures.albedo.has_value());
  EXPECT_FALSE(shot.materials[0].textures.roughness.has_value());
}

TEST(TextureShot, MissingFileIsAnExactError) {
  const auto resolved = (test::testDirectory("shots") / "no_such_albedo.png").string();
  test::expectSingleError("texture_missing.json", shotWithMaterials(skinWithTextures(R"({"albedo": "no_such_albedo.png"})")),
                          "/materials/skin/textures/albedo: file not found: 'no_such_albedo.png' (resolved to '" +
                              resolved + "')");
}

TEST(TextureShot, MissingFileInsideAnObjectNamesItsFileKey) {
  const auto resolved = (test::testDirectory("shots") / "gone.exr").string();
  test::expectSingleError("texture_missing_object.json",
                          shotWithMaterials(skinWithTextures(R"({"normal": {"file": "gone.exr"}})")),
                          "/materials/skin/textures/normal/file: file not found: 'gone.exr' (resolved to '" + resolved +
                              "')");
}

TEST(TextureShot, FileThatIsNoImageIsAnError) {
  const auto path = test::testDirectory("shots") / "not_an_image.png";
  std::ofstream(path) << "this is text, not a PNG\n";
  const auto shotPath = test::writeShot("texture_not_image.json",
                                        shotWithMaterials(skinWithTextures(R"({"albedo": "not_an_image.png"})")));
  std::vector<Diagnostic> diagnostics;
  test::shotErrorOf(shotPath, &diagnostics);
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].jsonPath, "/materials/skin/textures/albedo");
  const std::string expectedStart = "not a readable image: 'not_an_image.png' (resolved to '" + path.string() + "'): ";
  EXPECT_EQ(diagnostics[0].message.substr(0, expectedStart.size()), expectedStart) << diagnostics[0].message;
}

TEST(TextureShot, MisplacedMapsAndBadColourSpacesAreExactErrors) {
  writeImage("albedo.ppm");
  test::expectSingleError("texture_bad_space.json",
                          shotWithMaterials(skinWithTextures(R"({"albedo": {"file": "albedo.ppm", "colorSpace": "rec709"}})")),
                          "/materials/skin/textures/albedo/colorSpace: unknown colour space 'rec709' (expected one of "
                          "'auto', 'srgb', 'linear')");
  test::expectSingleError("texture_mfp_no_sss.json",
                          shotWithMaterials(skinWithTextures(R"({"meanFreePath": "albedo.ppm"})")),
                          "/materials/skin/textures: a 'meanFreePath' texture needs 'subsurface' (it scales the "
                          "subsurface mean free path)");
  test::expectSingleError("texture_bad_value.json", shotWithMaterials(skinWithTextures(R"({"albedo": 3})")),
                          "/materials/skin/textures/albedo: expected an image file path or {\"file\": path, "
                          "\"colorSpace\": ...}, found 3");
  test::expectSingleError("texture_diffuse_roughness.json",
                          shotWithMaterials(R"("paint": {"type": "diffuse", "textures": {"roughness": "albedo.ppm"}})"),
                          "/materials/paint/textures/roughness: unknown key 'roughness' (allowed here: albedo, normal)");
}

// The procedural iris in place of an albedo map (iris_pattern.hpp): the albedo stays the iris's
// mean colour (not a factor of 1), no file is read, and its keys are checked.
TEST(TextureShot, AnIrisPatternInPlaceOfAnAlbedoMap) {
  const Shot shot = loadShot(test::writeShot(
      "iris_pattern.json", shotWithMaterials(R"("iris": {"type": "diffuse", "albedo": [0.2, 0.11, 0.055],
          "textures": {"albedo": {"pattern": "iris", "seed": 5}}}, "plain": {"type": "diffuse",
          "textures": {"albedo": {"pattern": "iris"}}})")));
  const MaterialTextures& t = shot.materials.at(0).textures;
  ASSERT_TRUE(t.irisPattern.has_value());
  EXPECT_EQ(t.irisPattern->seed, 5u);
  EXPECT_FALSE(t.albedo.has_value());
  EXPECT_TRUE(t.any());
  EXPECT_FALSE(t.anyFile());
  EXPECT_TRUE((std::get<DiffuseParams>(shot.materials[0].params).albedo == Color(0.2f, 0.11f, 0.055f)).all());
  EXPECT_EQ(shot.materials.at(1).textures.irisPattern->seed, 1u);
  EXPECT_TRUE((std::get<DiffuseParams>(shot.materials[1].params).albedo == DiffuseParams{}.albedo).all());

  test::expectSingleError(
      "iris_pattern_typo.json",
      shotWithMaterials(R"("iris": {"type": "diffuse", "textures": {"albedo": {"pattern": "irsi"}}})"),
      "/materials/iris/textures/albedo/pattern: unknown albedo pattern 'irsi'; did you mean 'iris'?");
  test::expectSingleError(
      "iris_pattern_with_file.json",
      shotWithMaterials(R"("iris": {"type": "diffuse", "textures": {"albedo": {"pattern": "iris", "file": "a.png"}}})"),
      "/materials/iris/textures/albedo/file: unknown key 'file' (allowed here: pattern, seed)");
  test::expectSingleError(
      "iris_pattern_negative_seed.json",
      shotWithMaterials(R"("iris": {"type": "diffuse", "textures": {"albedo": {"pattern": "iris", "seed": -1}}})"),
      "/materials/iris/textures/albedo/seed: expected an integer >= 0, found -1");
}

TEST(TextureShot, TexturedMaterialOnAShapeWithoutUvsWarns) {
  writeImage("albedo.ppm");
  const Shot shot = loadShot(test::writeShot(
      "texture_ellipsoid.json",
      shotWithMaterials(R"("paint": {"type": "diffuse", "textures": {"albedo": "albedo.ppm"}})",
                        R"("shapes": [{"type": "ellipsoid", "center": [0, 0, 0], "radii": [1, 1, 1], "material": "paint"},
                                      {"type": "rectangle", "center": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0], "material": "paint"}])")));
  ASSERT_EQ(shot.warnings.size(), 1u);
  EXPECT_EQ(shot.warnings[0].jsonPath, "/shapes/0/material");
  EXPECT_NE(shot.warnings[0].message.find("this ellipsoid has no uvs: the textures of material 'paint' are skipped there"),
            std::string::npos)
      << shot.warnings[0].message;
}

TEST(TextureShot, IctFaceUvsReachTheFrameForATexturedSkin) {
  writeImage("albedo.ppm");
  const std::string text = test::replaced(test::ictFaceShot("", "", "", 1), R"("skin": {"type": "skin"})",
                                          R"("skin": {"type": "skin", "textures": {"albedo": ")" +
                                              (test::testDirectory("shots") / "albedo.ppm").string() + R"("}})");
  const Shot shot = loadShot(test::writeShot("texture_ict_face.json", text));
  EXPECT_TRUE(shot.warnings.empty()) << shot.warnings[0].message;
  const Frame frame = buildFrame(shot, 1);
  const uint32_t skin = uint32_t(shot.findMaterial("skin"));
  size_t skinMeshes = 0;
  for (const MeshInstance& m : frame.meshes) {
    if (m.materialId != skin) continue;
    ++skinMeshes;
    EXPECT_EQ(m.mesh.uvs.size(), m.mesh.vertexCount()) << m.mesh.name;
  }
  EXPECT_GE(skinMeshes, 1u);
}

}  // namespace texture_shot_test
}  // namespace lacrima
