// The skin material's keys in a shot file: the dual specular lobe and the pores (docs/shot-format.md).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "shot_support.hpp"

namespace lacrima {
namespace skin_material_shot_test {

std::string shotWithMaterials(const std::string& materials) {
  return "{\n  \"version\": 1,\n  \"frames\": {\"start\": 1, \"end\": 1},\n  \"output\": \"out.exr\",\n"
         "  \"render\": {\"width\": 16, \"height\": 8, \"spp\": 1},\n"
         "  \"camera\": {\"position\": [0, 0, 3], \"lookAt\": [0, 0, 0], \"fov\": 30},\n"
         "  \"materials\": {" + materials + "}\n}\n";
}

std::string shotWithSkin(const std::string& skinMembers) {
  return shotWithMaterials("\"skin\": {\"type\": \"skin\"" + skinMembers + "}");
}

const SkinParams& skinOf(const Shot& shot) { return std::get<SkinParams>(shot.materials.at(0).params); }

TEST(SkinMaterialShot, DefaultsAreTheSingleLobeSkinWithoutPores) {
  const Shot shot = loadShot(test::writeShot("skin_defaults.json", shotWithSkin(R"(, "roughness": 0.3)")));
  const SkinParams& p = skinOf(shot);
  EXPECT_EQ(p.roughness, 0.3f);
  EXPECT_EQ(p.lobeMix, 0.0f);
  EXPECT_EQ(p.poreDepth, 0.0f);
}

TEST(SkinMaterialShot, ReadsTheSecondLobeAndThePores) {
  const Shot shot = loadShot(test::writeShot(
      "skin_dual.json",
      shotWithSkin(R"(, "roughness": 0.3, "roughness2": 0.65, "lobeMix": 0.2, "poreScale": 0.0004, "poreDepth": 0.00003)")));
  const SkinParams& p = skinOf(shot);
  EXPECT_EQ(p.roughness, 0.3f);
  EXPECT_EQ(p.roughness2, 0.65f);
  EXPECT_EQ(p.lobeMix, 0.2f);
  EXPECT_EQ(p.poreScale, 0.0004f);
  EXPECT_EQ(p.poreDepth, 0.00003f);
}

TEST(SkinMaterialShot, ReadsTheFurrowsAndTheCavity) {
  const Shot shot = loadShot(test::writeShot(
      "skin_relief.json", shotWithSkin(R"(, "furrowScale": 0.0005, "furrowDepth": 0.000012, "cavity": 0.5)")));
  const SkinParams& p = skinOf(shot);
  EXPECT_EQ(p.furrowScale, 0.0005f);
  EXPECT_EQ(p.furrowDepth, 0.000012f);
  EXPECT_EQ(p.cavity, 0.5f);
  const Shot plain = loadShot(test::writeShot("skin_relief_defaults.json", shotWithSkin("")));
  const SkinParams& defaults = skinOf(plain);
  EXPECT_EQ(defaults.furrowDepth, 0.0f);
  EXPECT_EQ(defaults.cavity, 0.0f);
}

TEST(SkinMaterialShot, SecondRoughnessWithoutMixIsAnError) {
  test::expectSingleError("skin_no_mix.json", shotWithSkin(R"(, "roughness2": 0.6)"),
                          "/materials/skin/roughness2: 'roughness2' needs 'lobeMix' (the weight of the second "
                          "lobe, in [0, 1])");
}

TEST(SkinMaterialShot, OutOfRangeValuesNameTheirKey) {
  test::expectSingleError("skin_bad_mix.json", shotWithSkin(R"(, "roughness2": 0.6, "lobeMix": 1.5)"),
                          "/materials/skin/lobeMix: expected a number in [0, 1], found 1.5");
  test::expectSingleError("skin_bad_scale.json", shotWithSkin(R"(, "poreScale": 0)"),
                          "/materials/skin/poreScale: expected a number > 0, found 0");
  test::expectSingleError("skin_bad_depth.json", shotWithSkin(R"(, "poreDepth": -0.001)"),
                          "/materials/skin/poreDepth: expected a number >= 0, found -0.001");
  test::expectSingleError("skin_bad_furrow_scale.json", shotWithSkin(R"(, "furrowScale": -1)"),
                          "/materials/skin/furrowScale: expected a number > 0, found -1");
  test::expectSingleError("skin_bad_cavity.json", shotWithSkin(R"(, "cavity": 2)"),
                          "/materials/skin/cavity: expected a number in [0, 1], found 2");
}

TEST(SkinMaterialShot, SubsurfaceIsOffByDefaultAndReadsItsMeanFreePath) {
  EXPECT_FALSE(skinOf(loadShot(test::writeShot("skin_no_sss.json", shotWithSkin("")))).subsurface);
  const Shot defaults = loadShot(test::writeShot("skin_sss_defaults.json", shotWithSkin(R"(, "subsurface": {})")));
  ASSERT_TRUE(skinOf(defaults).subsurface);
  EXPECT_TRUE((skinOf(defaults).subsurface->meanFreePath == SubsurfaceParams{}.meanFreePath).all());
  const Shot given = loadShot(
      test::writeShot("skin_sss.json", shotWithSkin(R"(, "subsurface": {"meanFreePath": [0.002, 0.001, 0.0005]})")));
  ASSERT_TRUE(skinOf(given).subsurface);
  EXPECT_TRUE((skinOf(given).subsurface->meanFreePath == Color(0.002f, 0.001f, 0.0005f)).all());
  EXPECT_EQ(skinOf(given).subsurface->method, SubsurfaceMethod::RandomWalk);
  const Shot diffusion =
      loadShot(test::writeShot("skin_sss_diffusion.json", shotWithSkin(R"(, "subsurface": {"method": "diffusion"})")));
  EXPECT_EQ(skinOf(diffusion).subsurface->method, SubsurfaceMethod::Diffusion);
}

TEST(SkinMaterialShot, BadSubsurfaceNamesItsKey) {
  test::expectSingleError("skin_sss_zero.json", shotWithSkin(R"(, "subsurface": {"meanFreePath": [0.002, 0, 0.001]})"),
                          "/materials/skin/subsurface/meanFreePath/1: expected a number > 0, found 0");
  test::expectSingleError("skin_sss_not_object.json", shotWithSkin(R"(, "subsurface": true)"),
                          "/materials/skin/subsurface: expected an object, found true");
  test::expectSingleError("skin_sss_method.json", shotWithSkin(R"(, "subsurface": {"method": "difusion"})"),
                          "/materials/skin/subsurface/method: unknown subsurface method 'difusion'; did you mean 'diffusion'?");
  test::expectSingleError("skin_sss_method_unknown.json", shotWithSkin(R"(, "subsurface": {"method": "dipole"})"),
                          "/materials/skin/subsurface/method: unknown subsurface method 'dipole' (expected one of "
                          "'randomWalk', 'diffusion')");
}

// The example of the "skin" section of docs/shot-format.md must stay a valid material.
TEST(SkinMaterialShot, DocExampleLoads) {
  std::ifstream in(test::sourcePath("docs/shot-format.md"));
  ASSERT_TRUE(in) << "docs/shot-format.md not found";
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t section = doc.find("### skin");
  ASSERT_NE(section, std::string::npos);
  const size_t begin = doc.find("```json\n", section);
  ASSERT_NE(begin, std::string::npos);
  const size_t end = doc.find("\n```", begin + 8);
  const Shot shot = loadShot(test::writeShot("skin_doc.json", shotWithMaterials(doc.substr(begin + 8, end - begin - 8))));
  const SkinParams& p = skinOf(shot);
  EXPECT_GT(p.lobeMix, 0.0f);
  EXPECT_GT(p.poreDepth, 0.0f);
  EXPECT_GT(p.furrowDepth, 0.0f);
  EXPECT_GT(p.cavity, 0.0f);
  ASSERT_TRUE(p.subsurface);
  EXPECT_EQ(p.subsurface->method, SubsurfaceMethod::Diffusion);
}

}  // namespace skin_material_shot_test
}  // namespace lacrima
