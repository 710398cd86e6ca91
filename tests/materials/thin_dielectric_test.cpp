// ThinDielectricBsdf (materials/thin_dielectric.hpp): the slab reflectance against its closed
// form, energy (R + T = 1 for a clear sheet, from either side), and sampling weights that agree
// with the straight transmittance used by shadow rays.
#include <gtest/gtest.h>

#include <cmath>

#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/thin_dielectric.hpp"

namespace lacrima {
namespace thin_dielectric_test {

Vec3 direction(float cosTheta, bool frontSide) {
  const float sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
  return Vec3(sinTheta, 0.0f, frontSide ? cosTheta : -cosTheta);
}

TEST(ThinDielectric, NormalIncidenceReflectsTwoFacesWorth) {
  // One face of water reflects R0 = ((n - 1) / (n + 1))^2 at normal incidence; the slab with all
  // its inter-reflections 2 R0 / (1 + R0).
  const float n = 1.337f, r0 = (n - 1.0f) * (n - 1.0f) / ((n + 1.0f) * (n + 1.0f));
  const ThinDielectricBsdf sheet(n, Color::Ones());
  EXPECT_NEAR(sheet.reflectance(1.0f), 2.0f * r0 / (1.0f + r0), 1e-6f);
  EXPECT_NEAR(sheet.reflectance(1.0f), 0.0408f, 1e-4f);
}

TEST(ThinDielectric, BothSidesAlikeAndNoTotalInternalReflection) {
  const ThinDielectricBsdf sheet(1.337f, Color::Ones());
  for (float c : {0.95f, 0.6f, 0.3f, 0.05f}) {
    EXPECT_FLOAT_EQ(sheet.reflectance(c), sheet.reflectance(-c));
    // Seen from inside water the same angle would be beyond the critical angle at c = 0.3.
    EXPECT_LT(sheet.reflectance(-c), 1.0f);
    EXPECT_GE(sheet.reflectance(c), fresnelDielectric(c, 1.337f));
  }
}

TEST(ThinDielectric, SampledWeightsSumToOneAndTransmitStraight) {
  const ThinDielectricBsdf sheet(1.337f, Color::Ones());
  for (bool front : {true, false})
    for (float c : {0.9f, 0.5f, 0.1f}) {
      const Vec3 wo = direction(c, front);
      const float R = sheet.reflectance(c);
      // uLobe below R reflects, above transmits: weights f |cos| / pdf are 1 each, so the
      // expected throughput R * 1 + T * 1 = 1.
      const auto reflected = sheet.sample(wo, 0.5f * R, Vec2(0.3f, 0.7f));
      const auto transmitted = sheet.sample(wo, R + 0.5f * (1.0f - R), Vec2(0.3f, 0.7f));
      ASSERT_TRUE(reflected && transmitted);
      EXPECT_FALSE(reflected->transmitted);
      EXPECT_TRUE(transmitted->transmitted);
      EXPECT_FLOAT_EQ(transmitted->eta, 1.0f);
      EXPECT_TRUE(transmitted->wi.isApprox(-wo));
      EXPECT_NEAR(reflected->pdf + transmitted->pdf, 1.0f, 1e-6f);
      EXPECT_NEAR((reflected->f * std::abs(reflected->wi.z()) / reflected->pdf)[0], 1.0f, 1e-5f);
      EXPECT_NEAR((transmitted->f * std::abs(transmitted->wi.z()) / transmitted->pdf)[0], 1.0f, 1e-5f);
      EXPECT_NEAR(sheet.straightTransmittance(wo)[0], transmitted->pdf, 1e-6f);
    }
}

TEST(ThinDielectric, TintColoursTheTransmissionOnly) {
  const ThinDielectricBsdf sheet(1.337f, Color(1.0f, 0.5f, 0.25f));
  const Vec3 wo = direction(0.8f, true);
  const float R = sheet.reflectance(0.8f);
  const auto transmitted = sheet.sample(wo, 0.99f, Vec2(0.5f, 0.5f));
  ASSERT_TRUE(transmitted && transmitted->transmitted);
  const Color weight = transmitted->f * std::abs(transmitted->wi.z()) / transmitted->pdf;
  EXPECT_NEAR(weight[1], 0.5f, 1e-5f);
  EXPECT_NEAR(sheet.straightTransmittance(wo)[2], 0.25f * (1.0f - R), 1e-6f);
  const auto reflected = sheet.sample(wo, 0.0f, Vec2(0.5f, 0.5f));
  ASSERT_TRUE(reflected);
  EXPECT_NEAR((reflected->f * std::abs(reflected->wi.z()) / reflected->pdf)[2], 1.0f, 1e-5f);
}

}  // namespace thin_dielectric_test
}  // namespace lacrima
