// GGX distribution: normalisation of D, the projected-area identity that defines G1, the visible
// normal density and its sampler.
#include <gtest/gtest.h>

#include <cmath>

#include "chi2_support.hpp"
#include "lacrima/materials/microfacet.hpp"
#include "materials_support.hpp"

namespace lacrima {
namespace microfacet_test {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

TEST(Ggx, RoughnessMapsToAlphaSquaredWithFloor) {
  EXPECT_FLOAT_EQ(roughnessToAlpha(0.5f), 0.25f);
  EXPECT_FLOAT_EQ(roughnessToAlpha(0.0f), kMinAlpha);
  EXPECT_FLOAT_EQ(GgxDistribution(0.0f).alpha(), kMinAlpha);
}

TEST(Ggx, ProjectedMicrofacetAreaIsOne) {
  // integral D(wm) cos(theta_m) dwm = 1 (Walter 2007 eq. 4).
  for (const float alpha : {0.01f, 0.09f, 0.3f, 0.7f, 1.0f}) {
    const GgxDistribution d(alpha);
    const double integral = test::integrate2D(
        [&](double c, double phi) { return d.D(test::directionFromCosPhi(c, phi)) * c; }, 0.0, 1.0, 0.0, kTwoPi, 16, 1e-8, 1e-5,
        /*maxDepth=*/16);  // alpha 0.01 is a peak 1e-4 wide in cos(theta)
    EXPECT_NEAR(integral, 1.0, 1e-5) << "alpha " << alpha;
  }
}

TEST(Ggx, NarrowestLobeIsFiniteAndPreciseAtThePole) {
  // At alpha = kMinAlpha the lobe is ~1e-6 wide in cos(theta): D must come from x^2 + y^2, not
  // 1 - z^2, or float cancellation distorts it. Compare with the double-precision formula.
  const GgxDistribution d(kMinAlpha);
  EXPECT_NEAR(d.D(Vec3(0.0f, 0.0f, 1.0f)), 1.0 / (std::numbers::pi * kMinAlpha * kMinAlpha), 1.0);
  for (const double theta : {1e-4, 5e-4, 1e-3, 3e-3}) {
    const Vec3 wm = test::directionFromCosPhi(std::cos(theta), 0.5);
    const double a2 = double(kMinAlpha) * kMinAlpha;
    const double s2 = std::sin(theta) * std::sin(theta);
    const double c2 = std::cos(theta) * std::cos(theta);
    const double expected = a2 / (std::numbers::pi * (s2 + a2 * c2) * (s2 + a2 * c2));
    EXPECT_NEAR(d.D(wm), expected, 1e-4 * expected) << "theta " << theta;
  }
}

TEST(Ggx, MaskingIsProjectedAreaRatio) {
  // cos(theta_o) = G1(wo) integral max(0, wo.wm) D(wm) dwm (Walter 2007 eq. 5 with Smith G1);
  // equivalently the visible normal density integrates to 1 (Heitz 2018 eq. 1).
  for (const float alpha : {0.05f, 0.3f, 0.8f}) {
    const GgxDistribution d(alpha);
    for (const double cosO : {0.99, 0.6, 0.2, 0.05}) {
      const Vec3 wo = test::directionFromCosPhi(cosO, 1.1);
      const double projected = test::integrate2D(
          [&](double c, double phi) {
            const Vec3 wm = test::directionFromCosPhi(c, phi);
            return std::max(0.0f, wo.dot(wm)) * d.D(wm);
          },
          0.0, 1.0, 0.0, kTwoPi, 16, 1e-8, 1e-5,
        /*maxDepth=*/16);  // alpha 0.01 is a peak 1e-4 wide in cos(theta)
      EXPECT_NEAR(d.G1(wo) * projected, cosO, 3e-4 * cosO + 1e-5) << "alpha " << alpha << " cos_o " << cosO;
      const double visible = test::integrate2D(
          [&](double c, double phi) { return d.visibleD(wo, test::directionFromCosPhi(c, phi)); }, 0.0, 1.0, 0.0,
          kTwoPi, 16);
      EXPECT_NEAR(visible, 1.0, 3e-4) << "alpha " << alpha << " cos_o " << cosO;
      // From below, the visible distribution is that of the mirrored direction.
      EXPECT_FLOAT_EQ(d.visibleD(-wo, Vec3(0.1f, 0.2f, 0.97f).normalized()),
                      d.visibleD(wo, Vec3(0.1f, 0.2f, 0.97f).normalized()));
    }
  }
}

TEST(Ggx, HeightCorrelatedShadowingBounds) {
  const GgxDistribution d(0.4f);
  test::TestRng rng(3);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 a = rng.sphere();
    const Vec3 b = rng.sphere();
    const float g = d.G(a, b);
    // Height-correlated G2 lies between the uncorrelated product and the smaller G1 (Heitz 2014 §6),
    // and it is symmetric.
    EXPECT_GE(g + 1e-6f, d.G1(a) * d.G1(b));
    EXPECT_LE(g, std::min(d.G1(a), d.G1(b)) + 1e-6f);
    EXPECT_NEAR(g, d.G(b, a), 1e-6f);
  }
  EXPECT_FLOAT_EQ(d.G1(Vec3(0.0f, 0.0f, 1.0f)), 1.0f);
}

TEST(Ggx, SampledVisibleNormalsAreUnitAndUpward) {
  test::TestRng rng(11);
  for (const float alpha : {0.001f, 0.2f, 1.0f}) {
    const GgxDistribution d(alpha);
    for (int k = 0; k < 10000; ++k) {
      const Vec3 w = rng.sphere();
      const Vec3 wm = d.sampleVisibleNormal(w, rng.uniform2());
      ASSERT_NEAR(wm.norm(), 1.0f, 1e-5f);
      ASSERT_GT(wm.z(), 0.0f);
      // Visible: facing w, or facing -w when w is below the surface.
      ASSERT_GE(std::copysign(1.0f, w.z()) * w.dot(wm), -1e-5f);
    }
  }
}

}  // namespace microfacet_test
}  // namespace lacrima
