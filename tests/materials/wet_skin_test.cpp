// Wet skin (wet_skin.hpp): bitwise the skin when dry, the coverage law, the Lekner & Dorf darkening
// checked against a photon random walk in the film, darker diffuse and a sharper highlight.
// Chi-square, consistency, reciprocity and energy cases live in bsdf_cases.hpp /
// bsdf_properties_test.cpp with the other BSDFs.
#include <gtest/gtest.h>

#include <cmath>

#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/sampling.hpp"
#include "lacrima/materials/wet_skin.hpp"
#include "test_support.hpp"

namespace lacrima {
namespace {

SkinParams poredDualLobeSkin() {
  SkinParams p;
  p.roughness2 = 0.6f;
  p.lobeMix = 0.3f;
  p.poreDepth = 4e-5f;
  return p;
}

TEST(WetSkinBsdf, ZeroCoverageIsBitwiseTheSkin) {
  const SkinBsdf skin(poredDualLobeSkin());
  const WetSkinBsdf dry(skin, wetFilmCoverage(0.0f));
  test::TestRng rng(11);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 wo = rng.sphere(), wi = rng.sphere();
    const float uLobe = rng.uniform();
    const Vec2 u = rng.uniform2();
    EXPECT_TRUE((dry.eval(wo, wi) == skin.eval(wo, wi)).all());
    EXPECT_EQ(dry.pdf(wo, wi), skin.pdf(wo, wi));
    const auto a = dry.sample(wo, uLobe, u), b = skin.sample(wo, uLobe, u);
    ASSERT_EQ(a.has_value(), b.has_value());
    if (a) {
      EXPECT_EQ(a->wi, b->wi);
      EXPECT_TRUE((a->f == b->f).all());
      EXPECT_EQ(a->pdf, b->pdf);
    }
    const Vec3 position = 0.01f * rng.sphere();
    EXPECT_EQ(dry.perturbShadingNormal(position, Vec3::UnitZ(), Vec3::UnitZ()),
              skin.perturbShadingNormal(position, Vec3::UnitZ(), Vec3::UnitZ()));
  }
  EXPECT_TRUE((dry.albedo() == skin.albedo()).all());
}

TEST(WetSkinBsdf, CoverageGrowsWithFilmThickness) {
  EXPECT_EQ(wetFilmCoverage(0.0f), 0.0f);
  EXPECT_EQ(wetFilmCoverage(-1e-6f), 0.0f);
  EXPECT_NEAR(wetFilmCoverage(kWetFilmCoverageThickness * std::log(2.0f)), 0.5f, 1e-6f);
  EXPECT_GT(wetFilmCoverage(20e-6f), 0.9999f);  // a fresh trail (TearLiquidParams::filmThickness)
  EXPECT_LT(wetFilmCoverage(20e-6f), 1.0f);
  float previous = 0.0f;
  for (float d = 1e-7f; d < 3e-5f; d *= 1.5f) {
    EXPECT_GT(wetFilmCoverage(d), previous) << d;
    previous = wetFilmCoverage(d);
  }
}

// Photons in the film: a Lambertian base of albedo a (absorbs 1 - a per hit, else scatters
// cosine-weighted), the film's top reflects with the exact internal Fresnel (total reflection
// beyond the critical angle). The fraction that escapes is Lekner & Dorf's wet albedo.
double randomWalkWetAlbedo(double a, float n, int photons) {
  test::TestRng rng(4242);
  long escaped = 0;
  for (int k = 0; k < photons; ++k) {
    for (;;) {
      if (rng.uniform() >= a) break;  // absorbed by the base
      const Vec3 up = sampleCosineHemisphere(rng.uniform2());
      // Arriving at the top from inside the film: cos < 0 in fresnelDielectric's convention.
      if (rng.uniform() >= fresnelDielectric(-up.z(), n)) {
        ++escaped;
        break;
      }
    }
  }
  return double(escaped) / photons;
}

TEST(WetSkinBsdf, LeknerDorfAlbedoMatchesARandomWalkInTheFilm) {
  for (const double a : {0.2, 0.62, 0.95}) {
    const int photons = 400000;
    const double walk = randomWalkWetAlbedo(a, kWaterIor, photons);
    const double model = leknerDorfWetAlbedo(Color::Constant(float(a)), kWaterIor).x();
    const double stdErr = std::sqrt(walk * (1.0 - walk) / photons);
    EXPECT_NEAR(model, walk, 5.0 * stdErr + 1e-4) << "a " << a;
    EXPECT_LT(model, a) << "darker when wet";
  }
  // The limits: a white base stays white (nothing is absorbed), a black one black.
  EXPECT_NEAR(leknerDorfWetAlbedo(Color::Ones(), kWaterIor).x(), 1.0f, 1e-6f);
  EXPECT_EQ(leknerDorfWetAlbedo(Color::Zero(), kWaterIor).x(), 0.0f);
}

TEST(WetSkinBsdf, WetSkinIsDarkerAndMoreSaturated) {
  const SkinBsdf skin{SkinParams{}};
  const WetSkinBsdf wet(skin, 1.0f);
  const Color dry = skin.albedo(), soaked = wet.wetAlbedo();
  EXPECT_TRUE((soaked < dry).all());
  // Saturation: the ratio of the darkest to the brightest channel falls.
  EXPECT_LT(soaked.z() / soaked.x(), dry.z() / dry.x());
  // Diffuse-dominated reflection away from the mirror direction is darker.
  const Vec3 wo = test::directionFromCosPhi(0.9, 0.0), wi = test::directionFromCosPhi(0.7, 2.0);
  EXPECT_LT(wet.eval(wo, wi).x(), skin.eval(wo, wi).x());
  // Half coverage lies in between.
  const WetSkinBsdf half(skin, 0.5f);
  EXPECT_LT(half.eval(wo, wi).x(), skin.eval(wo, wi).x());
  EXPECT_GT(half.eval(wo, wi).x(), wet.eval(wo, wi).x());
}

TEST(WetSkinBsdf, HighlightIsSharperAndBrighterAtTheMirrorDirection) {
  const SkinBsdf skin{SkinParams{}};
  const WetSkinBsdf wet(skin, 1.0f);
  for (const double cosO : {0.95, 0.4}) {
    const Vec3 wo = test::directionFromCosPhi(cosO, 0.5);
    const Vec3 mirror(-wo.x(), -wo.y(), wo.z());
    EXPECT_GT(wet.eval(wo, mirror).x(), 20.0f * skin.eval(wo, mirror).x()) << cosO;
    // 10 degrees off the mirror direction the coat has fallen off: the highlight is narrow.
    const Vec3 off = test::directionFromCosPhi(std::cos(std::acos(cosO) + 10.0 * kPi / 180.0), 0.5 + kPi);
    EXPECT_LT(wet.eval(wo, off).x(), 0.01f * wet.eval(wo, mirror).x()) << cosO;
  }
}

TEST(WetSkinBsdf, FilmFillsThePores) {
  const SkinBsdf skin(poredDualLobeSkin());
  test::TestRng rng(3);
  double dryTilt = 0.0, halfTilt = 0.0;
  for (int k = 0; k < 500; ++k) {
    const Vec3 position = 0.005f * rng.sphere();
    const Vec3 n = Vec3::UnitZ();
    dryTilt += 1.0 - skin.perturbShadingNormal(position, n, n).z();
    const Vec3 half = WetSkinBsdf(skin, 0.5f).perturbShadingNormal(position, n, n);
    EXPECT_NEAR(half.norm(), 1.0f, 1e-5f);
    halfTilt += 1.0 - half.z();
    EXPECT_EQ(WetSkinBsdf(skin, 1.0f).perturbShadingNormal(position, n, n), n);
  }
  EXPECT_GT(dryTilt, 0.0);
  EXPECT_LT(halfTilt, dryTilt);
}

}  // namespace
}  // namespace lacrima
