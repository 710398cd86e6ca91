// Transparent shadows (integrator.cpp, Caustics::Straight): a shadow ray crosses smooth dielectrics straight, keeping
// their Fresnel transmission, and BSDF paths that reach a light through them are not counted a
// second time. Scene: a Lambertian floor, a water ball above it, a small sphere light straight
// above both; the camera looks obliquely at the floor point under the ball's centre.
#include <gtest/gtest.h>

#include "lacrima/materials/fresnel.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace transparent_shadows_test {

constexpr float kAlbedo = 0.5f;
constexpr float kLightRadius = 0.5f;
constexpr float kLightHeight = 50.0f;

Frame floorUnderWaterBall(bool transparentShadows, int maxDepth) {
  Frame frame;
  frame.materials.push_back(Material{"floor", DiffuseParams{Color::Constant(kAlbedo)}, Color::Zero()});
  frame.materials.push_back(Material{"water", SmoothDielectricParams{kTearIor, Color::Ones()}, Color::Zero()});
  frame.meshes.push_back(test::largeFloor(0));
  frame.spheres.push_back(Sphere{Vec3(0, 1, 0), 0.5f, 1});
  // The unshadowed floor's radiance is 1.
  frame.lights.push_back(test::sphereLightGivingUnitFloor(kAlbedo, kLightRadius, kLightHeight));
  // The camera ray passes 0.89 from the ball's centre (radius 0.5): it sees the floor directly.
  frame.camera = test::lookAt(Vec3(2, 1, 0), Vec3::Zero(), 0.5f);
  frame.settings = test::smallSettings(12, 64, maxDepth);
  // The straight shadow this file tests (caustics_test.cpp: MNEE), or none.
  frame.settings.caustics = transparentShadows ? Caustics::Straight : Caustics::Off;
  return frame;
}

// Straight through the centre: two interfaces at normal incidence, each transmitting 1 - F(0);
// the n^2 radiance scalings of entering and leaving cancel.
double waterBallTransmittance() {
  const double t = 1.0 - fresnelDielectric(1.0f, kTearIor);
  return t * t;
}

TEST(TransparentShadows, DirectLightThroughAWaterBallIsDimmedByFresnelTwice) {
  const Film film = renderFrame(floorUnderWaterBall(true, 1));
  test::expectMean(film, waterBallTransmittance(), 2e-3);
}

TEST(TransparentShadows, WhenOffTheWaterBallCastsABlackShadow) {
  const Film film = renderFrame(floorUnderWaterBall(false, 1));
  for (size_t p = 0; p < film.rgba.size(); p += 4) ASSERT_EQ(film.rgba[p], 0.0f) << "pixel " << p / 4;
}

// With long paths the BSDF strategy also finds the light through the ball (the ball focuses it
// near the floor: a bright caustic). Counted on top of the transparent shadow it would add far
// more than the small indirect light that is really there (mirror bounces off the ball).
TEST(TransparentShadows, LightReachedThroughTheBallIsNotCountedTwice) {
  const Film film = renderFrame(floorUnderWaterBall(true, 8));
  for (int c = 0; c < 3; ++c) {
    const test::MeanEstimate e = test::channelMean(film, c);
    EXPECT_GT(e.mean, waterBallTransmittance() - 5.0 * e.standardError - 2e-3);
    EXPECT_LT(e.mean, waterBallTransmittance() + 0.03) << "+- " << e.standardError;
  }
}

}  // namespace transparent_shadows_test
}  // namespace lacrima
