// Per-type bounce limits (RenderSettings::bounces, as Cycles' light-path bounces): scenes whose
// answer under a limit is known exactly. A scattering over its kind's limit still sends its ray
// on to gather the light it meets, then the path ends.
#include <gtest/gtest.h>

#include <cmath>

#include "lacrima/materials/fresnel.hpp"
#include "lacrima/renderer/camera.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace bounce_limits_test {

using test::expectMean;
using test::lookAt;
using test::smallSettings;

// A camera inside a closed diffuse emitter (emission 1, albedo a): the path gathers E at every
// vertex, so with a diffuse limit of n it sees sum_{k=0}^{n+1} a^k (the segment after the
// (n+1)-th bounce still gathers), and E / (1 - a) without a limit.
Frame insideEmittingSphere(float albedo, BounceLimits bounces) {
  Frame frame;
  frame.materials.push_back(Material{"emitter", DiffuseParams{Color::Constant(albedo)}, Color::Ones()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 1.0f, 0});
  frame.camera = lookAt(Vec3(0, 0, 0.2f), Vec3(0, 0, -1), 60.0f);
  frame.settings = smallSettings(16, 64, 1000);
  frame.settings.bounces = bounces;
  return frame;
}

TEST(BounceLimits, DiffuseLimitKeepsThatManyBouncesPlusTheLightTheLastOneSees) {
  const float albedo = 0.5f;
  for (const int limit : {0, 2}) {
    SCOPED_TRACE(limit);
    BounceLimits bounces;
    bounces.diffuse = limit;
    double exact = 0.0;
    for (int k = 0; k <= limit + 1; ++k) exact += std::pow(albedo, k);
    expectMean(renderFrame(insideEmittingSphere(albedo, bounces)), exact, 1e-4);
  }
}

// Limits of other kinds leave a scene with only diffuse scattering as it was, bit for bit.
TEST(BounceLimits, GlossyAndTransmissionLimitsLeaveDiffuseScatteringAlone) {
  const Film unlimited = renderFrame(insideEmittingSphere(0.8f, BounceLimits{}));
  const Film limited = renderFrame(insideEmittingSphere(0.8f, BounceLimits{BounceLimits::kUnlimited, 0, 0}));
  EXPECT_TRUE(unlimited.rgba == limited.rgba);
}

// A water sphere (ior 1.5) in a uniform environment of radiance 1, every camera sample through its
// pixel's centre (a 0.001 px box filter), so each pixel has one angle of incidence theta and
// Fresnel reflectance R (the same at the way out, by the sphere's symmetry), T = 1 - R. Without a
// limit every path escapes: 1. Transmission limit 0: the refracted path ends inside, R. Glossy
// limit 0: the outer reflection still gathers the environment, the path that went in escapes only
// straight out (an internal reflection is a second glossy bounce, its segment ends on the
// sphere): R + T^2. Transmission limit 1: going in is the one allowed, going out is over the limit
// but its segment gathers the environment: 1.
struct SpherePixels {
  Frame frame;
  std::vector<double> reflectance;  // per pixel, R at its centre ray; -1 where the ray misses
};

SpherePixels waterSphereInFurnace(BounceLimits bounces) {
  SpherePixels s;
  const float ior = 1.5f;
  s.frame.materials.push_back(Material{"water", SmoothDielectricParams{ior, Color::Ones()}, Color::Zero()});
  s.frame.spheres.push_back(Sphere{Vec3::Zero(), 1.0f, 0});
  s.frame.uniformBackground = Color::Ones();
  s.frame.camera = lookAt(Vec3(0, 0, 4), Vec3::Zero(), 32.0f);
  s.frame.settings = smallSettings(24, 256, 1000);
  s.frame.settings.filter = PixelFilter{FilterType::Box, 1e-3f};
  s.frame.settings.bounces = bounces;
  const int size = s.frame.settings.width;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Ray ray = generateCameraRay(s.frame.camera, size, size, x + 0.5f, y + 0.5f, Vec2(0.5f, 0.5f));
      // Unit sphere at the origin: |o + t d|^2 = 1.
      const double b = ray.origin.cast<double>().dot(ray.direction.cast<double>());
      const double c = ray.origin.cast<double>().squaredNorm() - 1.0;
      const double disc = b * b - c;
      if (disc <= 1e-6) {  // a miss, or too close to the silhouette to call
        s.reflectance.push_back(-1.0);
        continue;
      }
      const Vec3d hit = ray.origin.cast<double>() + (-b - std::sqrt(disc)) * ray.direction.cast<double>();
      const double cosIncidence = -hit.normalized().dot(ray.direction.cast<double>());
      s.reflectance.push_back(fresnelDielectric(float(cosIncidence), ior));
    }
  return s;
}

// Over the pixels the sphere covers, the rendered mean against the mean of `expected(R)`, within
// 5 standard errors of the per-sample Bernoulli estimates (every sample weighs 0 or 1 here).
template <typename Expected>
void expectSphereMean(const SpherePixels& s, const Film& film, Expected expected) {
  double rendered = 0.0, exact = 0.0, variance = 0.0;
  int count = 0;
  for (size_t p = 0; p < s.reflectance.size(); ++p) {
    if (s.reflectance[p] < 0.0) continue;
    const double e = expected(s.reflectance[p]);
    rendered += film.rgba[4 * p];
    exact += e;
    variance += e * (1.0 - e) / s.frame.settings.samplesPerPixel;
    ++count;
  }
  ASSERT_GT(count, 200);
  EXPECT_NEAR(rendered / count, exact / count, 5.0 * std::sqrt(variance) / count + 1e-4);
}

TEST(BounceLimits, TransmissionLimitZeroKeepsOnlyTheOuterReflection) {
  BounceLimits bounces;
  bounces.transmission = 0;
  const SpherePixels s = waterSphereInFurnace(bounces);
  expectSphereMean(s, renderFrame(s.frame), [](double R) { return R; });
}

TEST(BounceLimits, GlossyLimitZeroDropsTheInternalReflections) {
  BounceLimits bounces;
  bounces.glossy = 0;
  const SpherePixels s = waterSphereInFurnace(bounces);
  expectSphereMean(s, renderFrame(s.frame), [](double R) { return R + (1.0 - R) * (1.0 - R); });
}

TEST(BounceLimits, TransmissionLimitOneStillLetsThePathOut) {
  BounceLimits bounces;
  bounces.transmission = 1;
  const SpherePixels s = waterSphereInFurnace(bounces);
  expectSphereMean(s, renderFrame(s.frame), [](double) { return 1.0; });
}

}  // namespace bounce_limits_test
}  // namespace lacrima
