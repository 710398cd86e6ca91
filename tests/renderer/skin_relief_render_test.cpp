// The skin's relief in renders (skin_relief.hpp): with `cavity` the hollows of the pores and
// furrows darken what the camera sees and the first-hit albedo the denoiser reads, by the factor
// the relief has where the camera's rays land; without `cavity` nothing changes.
#include <gtest/gtest.h>

#include "lacrima/materials/skin_relief.hpp"
#include "lacrima/renderer/camera.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace skin_relief_render_test {

SkinParams reliefSkin(float cavity) {
  SkinParams skin;
  skin.albedo = Color(0.6f, 0.4f, 0.3f);
  skin.poreScale = 3e-4f;
  skin.poreDepth = 4e-5f;
  skin.furrowScale = 5e-4f;
  skin.furrowDepth = 2e-5f;
  skin.cavity = cavity;
  return skin;
}

// A skin floor (y = 0), about 1.5 cm of it seen from 45 degrees above, under a uniform
// environment of radiance 1: one bounce, so the picture is linear in the albedo.
Frame reliefFloor(const SkinParams& skin) {
  Frame frame;
  frame.materials.push_back(Material{"skin", skin, Color::Zero()});
  frame.meshes.push_back(test::largeFloor(0));
  frame.camera = test::lookAt(Vec3(0.0f, 0.02f, 0.02f), Vec3::Zero(), 30.0f);
  frame.settings = test::smallSettings(48, 16, 1);
  frame.uniformBackground = Color::Ones();
  return frame;
}

Color meanOf(const std::vector<float>& values, int stride) {
  Color sum = Color::Zero();
  for (size_t p = 0; p < values.size(); p += stride) sum += Color(values[p], values[p + 1], values[p + 2]);
  return sum / float(values.size() / stride);
}

// The relief's albedo factor averaged where rays through a 4x4 grid in each pixel meet the floor.
float meanFactorSeen(const Frame& frame, const SkinParams& skin) {
  const RenderSettings& s = frame.settings;
  double sum = 0.0;
  int count = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      for (int k = 0; k < 16; ++k) {
        const Ray ray = generateCameraRay(frame.camera, s.width, s.height, x + (k % 4 + 0.5f) / 4, y + (k / 4 + 0.5f) / 4,
                                          Vec2(0.5f, 0.5f));
        const Vec3 p = ray.origin + (-ray.origin.y() / ray.direction.y()) * ray.direction;
        sum += cavityAlbedoFactor(skin, skinReliefAt(skin, p));
        ++count;
      }
  return float(sum / count);
}

TEST(SkinReliefRender, CavityDarkensThePictureAndTheAlbedoByTheFactorWhereRaysLand) {
  const SkinParams withCavity = reliefSkin(1.0f);
  const Frame frame = reliefFloor(withCavity);
  const float factor = meanFactorSeen(frame, withCavity);
  std::printf("[ relief ] mean albedo factor where the camera looks: %.4f\n", factor);
  ASSERT_LT(factor, 0.98f);  // the hollows cover enough of the floor for the test to see them
  // The same relief with a uniform albedo times the mean factor (and no cavity): the same normals,
  // and a picture linear in the albedo, so the same mean.
  SkinParams uniformlyDarker = reliefSkin(0.0f);
  uniformlyDarker.albedo *= factor;
  const Film relief = renderFrame(frame), uniform = renderFrame(reliefFloor(uniformlyDarker));
  const Color reliefBeauty = meanOf(relief.rgba, 4), uniformBeauty = meanOf(uniform.rgba, 4);
  const Color reliefAlbedo = meanOf(relief.albedo, 3);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(reliefBeauty[c], uniformBeauty[c], 0.01f * uniformBeauty[c]) << "channel " << c;
    EXPECT_NEAR(reliefAlbedo[c], withCavity.albedo[c] * factor, 0.005f * withCavity.albedo[c]) << "channel " << c;
  }
  // And darker than without the cavity by about (1 - factor) of the diffuse light.
  const Color noCavity = meanOf(renderFrame(reliefFloor(reliefSkin(0.0f))).rgba, 4);
  EXPECT_LT(reliefBeauty.x(), noCavity.x() * (1.0f - 0.5f * (1.0f - factor)));
}

TEST(SkinReliefRender, WithoutCavityTheAlbedoIsUntouched) {
  const Film film = renderFrame(reliefFloor(reliefSkin(0.0f)));
  const Color albedo = meanOf(film.albedo, 3);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(albedo[c], reliefSkin(0.0f).albedo[c], 1e-4f);  // float sums of the filter
}

}  // namespace skin_relief_render_test
}  // namespace lacrima
