// Wet skin (wet_skin.hpp): bitwise the skin when dry, the coverage law, the Lekner & Dorf darkening
// checked against a photon random walk in the film, the wet skin's base albedo (the skin's own
// surface already traps light) against a random walk through skin and film, the lost sheen and
// a sharper highlight.
// Chi-square, consistency, reciprocity and energy cases live in bsdf_cases_support.hpp /
// bsdf_properties_test.cpp with the other BSDFs.
#include <gtest/gtest.h>

#include <cmath>

#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/sampling.hpp"
#include "lacrima/materials/wet_skin.hpp"
#include "materials_support.hpp"

namespace lacrima {
namespace wet_skin_test {

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
  EXPECT_GT(wetFilmCoverage(20e-6f), 0.9999f);  // a fresh trail (LiquidTearParams::filmThickness)
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

// Photons in skin under an optional water film (parallel, specular interfaces, so a photon keeps
// n sin(theta) for good): the skin's body, albedo a0, absorbs 1 - a0 per scattering, else sends
// the photon up cosine-weighted; at each interface it is reflected with the exact Fresnel
// (total reflection included) or goes through. Returns the fraction that escapes into air.
double randomWalkSkinAlbedo(double a0, float skinIor, bool film, int photons) {
  test::TestRng rng(777);
  const float skinToWater = skinIor / kWaterIor;  // eta of the skin-water interface (skin inside)
  long escaped = 0;
  for (int k = 0; k < photons; ++k) {
    bool done = false;
    while (!done) {
      if (rng.uniform() >= a0) break;  // absorbed in the skin
      const float cosSkin = sampleCosineHemisphere(rng.uniform2()).z();
      const float sinSkin = std::sqrt(std::max(0.0f, 1.0f - cosSkin * cosSkin));
      if (!film) {  // the skin's own surface against air
        if (rng.uniform() >= fresnelDielectric(-cosSkin, skinIor)) ++escaped, done = true;
        continue;
      }
      if (rng.uniform() < fresnelDielectric(-cosSkin, skinToWater)) continue;  // back into the skin
      const float sinWater = sinSkin * skinToWater;  // < 1: it went through
      const float cosWater = std::sqrt(std::max(0.0f, 1.0f - sinWater * sinWater));
      for (;;) {  // in the film: up to the air, down to the skin, until it leaves one way
        if (rng.uniform() >= fresnelDielectric(-cosWater, kWaterIor)) {
          ++escaped, done = true;
          break;
        }
        if (rng.uniform() >= fresnelDielectric(cosWater, skinToWater)) break;  // into the skin
      }
    }
  }
  return double(escaped) / photons;
}

TEST(WetSkinBsdf, WetSkinBaseAlbedoMatchesARandomWalkThroughSkinAndFilm) {
  const float fbarWater = fresnelHemisphericalReflectance(kWaterIor);
  for (const double a0 : {0.3, 0.7, 0.95}) {
    const int photons = 300000;
    const double dry = randomWalkSkinAlbedo(a0, 1.4f, false, photons);
    const double wet = randomWalkSkinAlbedo(a0, 1.4f, true, photons);
    const double model = wetSkinBaseAlbedo(Color::Constant(float(dry)), 1.4f, kWaterIor, fbarWater).x();
    const double stdErr = std::sqrt(wet * (1.0 - wet) / photons);
    // The model neglects the skin-water interface's reflection inside the escape cone (< 0.1%).
    EXPECT_NEAR(model, wet, 5.0 * stdErr + 2e-3) << "a0 " << a0;
    // Lekner & Dorf's film over a base that meets air when dry would darken it much more.
    EXPECT_LT(leknerDorfWetAlbedo(Color::Constant(float(dry)), kWaterIor).x(), wet - 0.04) << "a0 " << a0;
  }
}

TEST(WetSkinBsdf, WetSkinBaseAlbedoLimits) {
  const float fbarWater = fresnelHemisphericalReflectance(kWaterIor);
  const Color dry(0.56f, 0.37f, 0.29f);  // the default shot's skin
  // Skin of the water's index: the film only replaces the skin's own surface.
  const Color same = wetSkinBaseAlbedo(dry, kWaterIor, kWaterIor, fbarWater);
  EXPECT_TRUE(((same - dry).cwiseAbs() < 1e-5f).all()) << same.transpose();
  // A base of index 1 meets air directly: Lekner & Dorf's darkening in full.
  const Color bare = wetSkinBaseAlbedo(dry, 1.0f, kWaterIor, fbarWater);
  const Color leknerDorf = leknerDorfWetAlbedo(dry, kWaterIor);
  EXPECT_TRUE(((bare - leknerDorf).cwiseAbs() < 1e-5f).all()) << bare.transpose();
  // Skin of index 1.4: within 1% of the dry albedo, where Lekner & Dorf's film alone is a
  // quarter darker or more (the brownish stain of the first wet trails).
  const Color skin = wetSkinBaseAlbedo(dry, 1.4f, kWaterIor, fbarWater);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(skin[c], dry[c], 0.01f * dry[c]) << c;
    EXPECT_LT(leknerDorf[c], 0.75f * dry[c]) << c;
  }
}

TEST(WetSkinBsdf, WetSkinLosesTheSkinsBroadSheen) {
  // The default shot's skin: a sharp and a broad specular lobe over its base.
  SkinParams params;
  params.albedo = Color(0.56f, 0.37f, 0.29f);
  params.roughness = 0.35f;
  params.roughness2 = 0.6f;
  params.lobeMix = 0.3f;
  params.ior = 1.4f;
  const SkinBsdf skin(params);
  const WetSkinBsdf wet(skin, 1.0f);
  // 25 degrees off the mirror direction the dry sheen still adds light; the film's sharp
  // highlight has none there, and its base is the dry one: the trail is darker, a little when
  // seen and lit from near the normal, more towards grazing, where the dry sheen is strong.
  for (const double cosO : {0.9, 0.6}) {
    const Vec3 wo = test::directionFromCosPhi(cosO, 0.0);
    const Vec3 off = test::directionFromCosPhi(std::cos(std::acos(cosO) + 25.0 * kPi / 180.0), kPi);
    const Color dryF = skin.eval(wo, off), wetF = wet.eval(wo, off);
    EXPECT_LT(wetF.x(), 0.97f * dryF.x()) << cosO;
    if (cosO > 0.8) {
      EXPECT_GT(wetF.x(), 0.8f * dryF.x()) << "only a little";
    }
  }
  // Half coverage lies in between.
  const Vec3 wo = test::directionFromCosPhi(0.9, 0.0);
  const Vec3 off = test::directionFromCosPhi(std::cos(std::acos(0.9) + 25.0 * kPi / 180.0), kPi);
  const WetSkinBsdf half(skin, 0.5f);
  EXPECT_LT(half.eval(wo, off).x(), skin.eval(wo, off).x());
  EXPECT_GT(half.eval(wo, off).x(), wet.eval(wo, off).x());
}

TEST(WetSkinBsdf, HighlightIsSharperAndBrighterAtTheMirrorDirection) {
  const SkinBsdf skin{SkinParams{}};
  const WetSkinBsdf wet(skin, 1.0f);
  for (const double cosO : {0.95, 0.4}) {
    const Vec3 wo = test::directionFromCosPhi(cosO, 0.5);
    const Vec3 mirror(-wo.x(), -wo.y(), wo.z());
    EXPECT_GT(wet.eval(wo, mirror).x(), 20.0f * skin.eval(wo, mirror).x()) << cosO;
    // 10 degrees off the mirror direction the coat has fallen off to the diffuse base (about 1%
    // of the peak): the highlight is narrow.
    const Vec3 off = test::directionFromCosPhi(std::cos(std::acos(cosO) + 10.0 * kPi / 180.0), 0.5 + kPi);
    EXPECT_LT(wet.eval(wo, off).x(), 0.02f * wet.eval(wo, mirror).x()) << cosO;
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

}  // namespace wet_skin_test
}  // namespace lacrima
