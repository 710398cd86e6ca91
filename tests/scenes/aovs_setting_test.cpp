// The `render.aovs` key (docs/shot-format.md, "AOVs"; docs/compositing.md).
#include <gtest/gtest.h>

#include "lacrima/scenes/shot.hpp"
#include "scenes/shot_support.hpp"

namespace lacrima {
namespace aovs_setting_test {

using test::expectSingleError;
using test::shotWithRender;
using test::writeShot;

CryptomatteSettings cryptomatteOf(const std::string& name, const std::string& renderExtra) {
  return loadShot(writeShot(name, shotWithRender(renderExtra))).render.cryptomatte;
}

TEST(AovsSetting, NoneByDefaultEachCryptomatteByItsLayerName) {
  EXPECT_EQ(cryptomatteOf("aovs_default.json", ""), CryptomatteSettings{});
  EXPECT_EQ(cryptomatteOf("aovs_empty.json", R"(, "aovs": [])"), CryptomatteSettings{});
  EXPECT_EQ(cryptomatteOf("aovs_object.json", R"(, "aovs": ["CryptoObject"])"), (CryptomatteSettings{true, false, 6}));
  EXPECT_EQ(cryptomatteOf("aovs_both.json", R"(, "aovs": ["CryptoMaterial", "CryptoObject"])"),
            (CryptomatteSettings{true, true, 6}));
}

TEST(AovsSetting, LightGroupsByTheirLayerNameAndLightsByTheirGroup) {
  EXPECT_FALSE(loadShot(writeShot("aovs_no_groups.json", shotWithRender(""))).render.lightGroups);
  const Shot shot = loadShot(writeShot("aovs_groups.json", shotWithRender(R"(, "aovs": ["lightGroups"])")));
  EXPECT_TRUE(shot.render.lightGroups);
  EXPECT_EQ(shot.render.cryptomatte, CryptomatteSettings{});
}

TEST(AovsSetting, LightPathsAllTogetherOrEachByItsLayerName) {
  EXPECT_FALSE(loadShot(writeShot("aovs_no_paths.json", shotWithRender(""))).render.lightPaths.any());
  const LightPathSet all = loadShot(writeShot("aovs_paths.json", shotWithRender(R"(, "aovs": ["lightPaths"])"))).render.lightPaths;
  for (const LightPath pass : allLightPaths()) EXPECT_TRUE(all.has(pass)) << lightPathName(pass);
  const LightPathSet two =
      loadShot(writeShot("aovs_two_paths.json", shotWithRender(R"(, "aovs": ["specular_direct", "subsurface"])")))
          .render.lightPaths;
  for (const LightPath pass : allLightPaths())
    EXPECT_EQ(two.has(pass), pass == LightPath::SpecularDirect || pass == LightPath::Subsurface) << lightPathName(pass);
}

TEST(AovsSetting, BadValuesAreReportedAtTheirPath) {
  expectSingleError("aovs_typo.json", shotWithRender(R"(, "aovs": ["CryptoObjects"])"),
                    "/render/aovs/0: unknown AOV 'CryptoObjects'; did you mean 'CryptoObject'?");
  expectSingleError("aovs_unknown.json", shotWithRender(R"(, "aovs": ["CryptoObject", "glitter"])"),
                    "/render/aovs/1: unknown AOV 'glitter' (expected one of 'CryptoObject', 'CryptoMaterial', "
                    "'lightGroups', 'lightPaths', 'diffuse_direct', 'diffuse_indirect', 'specular_direct', "
                    "'specular_indirect', 'transmission_direct', 'transmission_indirect', 'subsurface', 'emission', "
                    "'environment')");
  expectSingleError("aovs_path_typo.json", shotWithRender(R"(, "aovs": ["diffuse_indrect"])"),
                    "/render/aovs/0: unknown AOV 'diffuse_indrect'; did you mean 'diffuse_indirect'?");
  expectSingleError("aovs_type.json", shotWithRender(R"(, "aovs": "CryptoObject")"),
                    "/render/aovs: expected a list of layer names such as [\"CryptoObject\", \"CryptoMaterial\"], "
                    "found \"CryptoObject\"");
}

}  // namespace aovs_setting_test
}  // namespace lacrima
