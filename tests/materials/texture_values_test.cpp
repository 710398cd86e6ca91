// What texture maps do to a material (materials/texture_values.hpp): each map multiplies its
// constant, the tangent-space normal map follows the uv tangents with green up the image
// (OpenGL convention), and the sRGB curve decodes as IEC 61966-2-1 says.
#include <gtest/gtest.h>

#include "lacrima/materials/texture_values.hpp"

namespace lacrima {
namespace texture_values_test {

TEST(TextureValues, MapsMultiplyTheirConstants) {
  SkinParams skin;
  skin.subsurface = SubsurfaceParams{};
  TextureValues values;
  values.albedo = Color(0.5f, 1.0f, 0.25f);
  values.roughness = 0.5f;
  values.meanFreePath = Color(2.0f, 1.0f, 0.5f);
  const auto textured = std::get<SkinParams>(applyTextureValues(skin, values));
  EXPECT_TRUE(textured.albedo.isApprox(skin.albedo * Color(0.5f, 1.0f, 0.25f)));
  EXPECT_FLOAT_EQ(textured.roughness, 0.5f * skin.roughness);
  EXPECT_FLOAT_EQ(textured.roughness2, 0.5f * skin.roughness2);
  EXPECT_TRUE(textured.subsurface->meanFreePath.isApprox(skin.subsurface->meanFreePath * Color(2.0f, 1.0f, 0.5f)));
  const auto diffuse = std::get<DiffuseParams>(applyTextureValues(DiffuseParams{Color::Constant(0.8f)}, values));
  EXPECT_TRUE(diffuse.albedo.isApprox(Color(0.4f, 0.8f, 0.2f)));
}

TEST(TextureValues, NormalMapFrameFollowsUvTangentsWithGreenUpTheImage) {
  const Vec3 ns(0, 0, 1), dpdu(2, 0, 0), dpdv(0, 3, 0);
  EXPECT_TRUE(applyNormalMap(Vec3(0, 0, 1), ns, dpdu, dpdv).isApprox(ns));
  EXPECT_TRUE(applyNormalMap(Vec3(1, 0, 0), ns, dpdu, dpdv).isApprox(Vec3(1, 0, 0)));
  EXPECT_TRUE(applyNormalMap(Vec3(0, 1, 0), ns, dpdu, dpdv).isApprox(Vec3(0, -1, 0)));  // against dP/dv
  EXPECT_TRUE(applyNormalMap(Vec3(1, 0, 0), ns, Vec3::Zero(), dpdv).isApprox(ns));      // no tangent: unchanged
}

TEST(TextureValues, SrgbCurveMatchesItsReferencePoints) {
  EXPECT_FLOAT_EQ(srgbToLinear(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(srgbToLinear(1.0f), 1.0f);
  EXPECT_NEAR(srgbToLinear(0.5f), 0.2140f, 1e-4f);
  EXPECT_NEAR(srgbToLinear(0.04045f), 0.04045f / 12.92f, 1e-7f);
}

}  // namespace texture_values_test
}  // namespace lacrima
