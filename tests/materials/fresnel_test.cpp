// Dielectric Fresnel and refraction: exact values for tears, total internal reflection, Fresnel
// reciprocity under the refraction map, Snell's law.
#include <gtest/gtest.h>

#include <cmath>

#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/material.hpp"
#include "materials_support.hpp"

namespace lacrima {
namespace fresnel_test {

TEST(Fresnel, NormalIncidenceTearIsAboutTwoPercent) {
  // R0 = ((n - 1) / (n + 1))^2 (Hecht §4.6): 0.0207949 for n = 1.337.
  const double n = kTearIor;
  const double r0 = std::pow((n - 1.0) / (n + 1.0), 2.0);
  EXPECT_NEAR(r0, 0.0207949, 1e-6);
  EXPECT_NEAR(fresnelDielectric(1.0f, kTearIor), r0, 1e-6);
  // Same reflectance from inside the drop.
  EXPECT_NEAR(fresnelDielectric(-1.0f, kTearIor), r0, 1e-6);
}

TEST(Fresnel, TotalInternalReflectionBeyondCriticalAngle) {
  // Critical angle asin(1/1.337) = 48.41 deg (48.61 deg for pure water, n = 1.333).
  const double critical = std::asin(1.0 / kTearIor) * 180.0 / std::numbers::pi;
  EXPECT_NEAR(critical, 48.41, 0.01);
  const auto insideCos = [](double degrees) { return -float(std::cos(degrees * std::numbers::pi / 180.0)); };
  EXPECT_LT(fresnelDielectric(insideCos(48.3), kTearIor), 1.0f);
  EXPECT_EQ(fresnelDielectric(insideCos(48.5), kTearIor), 1.0f);
  EXPECT_EQ(fresnelDielectric(insideCos(60.0), kTearIor), 1.0f);
  EXPECT_EQ(fresnelDielectric(insideCos(89.0), kTearIor), 1.0f);
  EXPECT_LT(fresnelDielectric(insideCos(48.55), 1.333f), 1.0f);
  EXPECT_EQ(fresnelDielectric(insideCos(48.7), 1.333f), 1.0f);
  // From outside there is never TIR, and R rises to 1 at grazing incidence.
  EXPECT_LT(fresnelDielectric(std::cos(89.0f * kPi / 180.0f), kTearIor), 1.0f);
  EXPECT_GT(fresnelDielectric(1e-4f, kTearIor), 0.99f);
}

TEST(Fresnel, BrewsterAngleReflectsOnlyPerpendicularPolarisation) {
  // At Brewster's angle tan(theta_B) = n, r_par = 0 and theta_i + theta_t = 90 deg, so
  // R = R_perp / 2 = sin^2(theta_i - theta_t) / 2 (Fresnel's sine law, Hecht §4.6.2).
  for (const double n : {1.337, 1.4, 1.5}) {
    const double thetaB = std::atan(n);
    const double thetaT = std::numbers::pi / 2 - thetaB;
    const double expected = 0.5 * std::pow(std::sin(thetaB - thetaT), 2.0);
    EXPECT_NEAR(fresnelDielectric(float(std::cos(thetaB)), float(n)), expected, 2e-6) << "n = " << n;
  }
}

TEST(Fresnel, ReciprocalUnderTheRefractionMap) {
  // Light crossing the interface either way sees the same reflectance: F(cos_i) from outside
  // equals F(cos_t) from inside, where t is the refracted direction (Stokes relations).
  const Vec3 n(0.0f, 0.0f, 1.0f);
  for (int k = 1; k <= 200; ++k) {
    const float cosI = k / 200.0f;
    const Vec3 wi = test::directionFromCosPhi(cosI, 0.7);
    const auto t = refract(wi, n, kTearIor);
    ASSERT_TRUE(t.has_value());
    EXPECT_LT(t->wt.z(), 0.0f);
    // Float rounding of cos_t shows up as ~1e-5 near grazing, where F is steep in cos_t.
    const double tolerance = cosI < 0.05f ? 5e-5 : 1e-5;
    EXPECT_NEAR(fresnelDielectric(cosI, kTearIor), fresnelDielectric(t->wt.z(), kTearIor), tolerance) << "cos_i " << cosI;
    // And the way back: refracting the transmitted ray from inside returns the original.
    const auto back = refract(t->wt, n, kTearIor);
    ASSERT_TRUE(back.has_value());
    EXPECT_LT((back->wt - wi).norm(), 2e-5f);
    EXPECT_NEAR(back->etap, 1.0f / kTearIor, 1e-7f);
  }
}

TEST(Refract, ObeysSnellsLawFromBothSides) {
  const Vec3 n(0.0f, 0.0f, 1.0f);
  test::TestRng rng(7);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 wi = rng.sphere();
    const auto t = refract(wi, n, kTearIor);
    const bool outside = wi.z() > 0.0f;
    const double etaI = outside ? 1.0 : kTearIor;
    const double etaT = outside ? kTearIor : 1.0;
    const double sinI = std::sqrt(std::max(0.0, 1.0 - double(wi.z()) * wi.z()));
    if (!outside && sinI * kTearIor > 1.0 + 1e-5) {
      EXPECT_FALSE(t.has_value()) << "expected TIR";
      continue;
    }
    if (!t) {
      EXPECT_GT(sinI * etaI / etaT, 1.0 - 1e-5);  // right at the critical angle
      continue;
    }
    EXPECT_NEAR(t->wt.norm(), 1.0f, 1e-5f);
    EXPECT_LT(t->wt.z() * wi.z(), 0.0f + 1e-12f);  // other side
    const double sinT = std::sqrt(std::max(0.0, 1.0 - double(t->wt.z()) * t->wt.z()));
    EXPECT_NEAR(etaI * sinI, etaT * sinT, 2e-5);  // Snell
    EXPECT_NEAR(t->etap, etaT / etaI, 1e-6);
    // Refracted ray stays in the plane of incidence, on the opposite azimuth.
    const Vec2 a(wi.x(), wi.y());
    const Vec2 b(t->wt.x(), t->wt.y());
    if (a.norm() > 1e-3f) {
      EXPECT_NEAR(a.x() * b.y() - a.y() * b.x(), 0.0f, 1e-5f);
      EXPECT_LE(a.dot(b), 0.0f);
    }
  }
}

TEST(Reflect, MirrorsAboutTheNormal) {
  const Vec3 n = Vec3(0.2f, -0.3f, 0.9f).normalized();
  const Vec3 w = Vec3(0.5f, 0.1f, 0.4f).normalized();
  const Vec3 r = reflect(w, n);
  EXPECT_NEAR(r.norm(), 1.0f, 1e-6f);
  EXPECT_NEAR(r.dot(n), w.dot(n), 1e-6f);
  EXPECT_LT((r + w - 2.0f * w.dot(n) * n).norm(), 1e-6f);
}

}  // namespace fresnel_test
}  // namespace lacrima
