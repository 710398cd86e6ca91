// Bsdf::evalLobes (bsdf.hpp), the split the light-path AOVs rely on: the lobes add up to eval in
// every direction for every BSDF family, and each family puts its light in the right kind (a
// Lambertian base diffuse, skin's specular and a film's coat glossy, a dielectric's reflection
// glossy and its refraction transmission, delta lobes nothing).
#include <gtest/gtest.h>

#include "bsdf_cases_support.hpp"
#include "lacrima/base/hash.hpp"
#include "lacrima/materials/skin.hpp"

namespace lacrima {
namespace bsdf_lobes_test {

// Directions spread over the sphere (both hemispheres), deterministic.
std::vector<Vec3> sphereDirections(int count) {
  std::vector<Vec3> directions;
  for (int i = 0; i < count; ++i) {
    const double cosTheta = 1.0 - 2.0 * (double(i) + 0.5) / double(count);
    directions.push_back(test::directionFromCosPhi(cosTheta, 2.399963 * double(i)));
  }
  return directions;
}

float relativeError(const Color& a, const Color& b) {
  return ((a - b).abs() / b.abs().max(1e-6f)).maxCoeff();
}

TEST(BsdfLobes, TheLobesAddUpToEvalForEveryFamily) {
  for (const test::BsdfCase& c : test::chi2Cases()) {
    const auto bsdf = test::makeCaseBsdf(c.params, c.wetCoverage);
    const Vec3 wo = test::caseWo(c);
    float worst = 0.0f;
    for (const Vec3& wi : sphereDirections(2000)) {
      const Color f = bsdf->eval(wo, wi);
      worst = std::max(worst, relativeError(bsdf->evalLobes(wo, wi).sum(), f));
    }
    EXPECT_LT(worst, 1e-6f) << c.name;
  }
}

TEST(BsdfLobes, EachFamilyPutsItsLightInTheRightKind) {
  const Vec3 wo = test::directionFromCosPhi(0.8, 0.3);
  const Vec3 above = test::directionFromCosPhi(0.6, 2.0);
  const Vec3 mirror(-wo.x(), -wo.y(), wo.z());
  // Snell's refraction of wo into water (index 1.33): where a rough interface transmits most.
  const float eta = 1.33f, sin2 = (wo.x() * wo.x() + wo.y() * wo.y()) / (eta * eta);
  const Vec3 below(-wo.x() / eta, -wo.y() / eta, -std::sqrt(1.0f - sin2));

  const BsdfLobes diffuse = makeBsdf(DiffuseParams{})->evalLobes(wo, above);
  EXPECT_GT(diffuse.diffuse.minCoeff(), 0.0f);
  EXPECT_TRUE((diffuse.glossy == 0.0f).all() && (diffuse.transmission == 0.0f).all());

  SkinParams skin;
  const BsdfLobes dry = makeBsdf(skin)->evalLobes(wo, mirror);
  EXPECT_GT(dry.diffuse.minCoeff(), 0.0f) << "the Lambertian base";
  EXPECT_GT(dry.glossy.minCoeff(), 0.0f) << "the specular lobes";
  EXPECT_TRUE((dry.transmission == 0.0f).all());
  const BsdfLobes wet = WetSkinBsdf(SkinBsdf(skin), 1.0f).evalLobes(wo, mirror);
  EXPECT_GT(wet.glossy.minCoeff(), dry.glossy.minCoeff()) << "a film's smooth coat shines brighter at the mirror";
  EXPECT_GT(wet.diffuse.minCoeff(), 0.0f) << "the base seen through the film";
  skin.subsurface = SubsurfaceParams{};
  const BsdfLobes subsurface = makeBsdf(skin)->evalLobes(wo, mirror);
  EXPECT_TRUE((subsurface.diffuse == 0.0f).all()) << "the walk below replaces the base";
  EXPECT_GT(subsurface.glossy.minCoeff(), 0.0f);

  RoughDielectricParams water;
  water.roughness = 0.3f;
  const auto rough = makeBsdf(water);
  const BsdfLobes reflected = rough->evalLobes(wo, mirror), refracted = rough->evalLobes(wo, below);
  EXPECT_GT(reflected.glossy.minCoeff(), 0.0f);
  EXPECT_TRUE((reflected.diffuse == 0.0f).all() && (reflected.transmission == 0.0f).all());
  EXPECT_GT(refracted.transmission.minCoeff(), 0.0f);
  EXPECT_TRUE((refracted.diffuse == 0.0f).all() && (refracted.glossy == 0.0f).all());

  const BsdfLobes delta = makeBsdf(SmoothDielectricParams{})->evalLobes(wo, mirror);
  EXPECT_TRUE((delta.sum() == 0.0f).all()) << "delta lobes are not evaluated (the integrator classifies their samples)";
}

}  // namespace bsdf_lobes_test
}  // namespace lacrima
