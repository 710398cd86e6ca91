// Tests of the test: the chi-square survival function against tabulated values, and samplers
// with deliberately wrong densities that the chi-square routine must reject.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "chi2_support.hpp"
#include "lacrima/materials/microfacet.hpp"
#include "lacrima/materials/sampling.hpp"
#include "materials_support.hpp"

namespace lacrima {
namespace chi2_self_test {

TEST(Chi2Math, SurvivalFunctionMatchesTables) {
  // Q(1, x) = exp(-x); 2 dof: exp(-chi2/2).
  EXPECT_NEAR(test::regularizedGammaQ(1.0, 2.5), std::exp(-2.5), 1e-12);
  EXPECT_NEAR(test::chiSquareSurvival(3.0, 2), std::exp(-1.5), 1e-12);
  // 1% critical values of the chi-square distribution (NIST/SEMATECH e-Handbook, table 1.3.6.7.4).
  EXPECT_NEAR(test::chiSquareSurvival(6.635, 1), 0.01, 1e-4);
  EXPECT_NEAR(test::chiSquareSurvival(23.209, 10), 0.01, 1e-4);
  EXPECT_NEAR(test::chiSquareSurvival(135.807, 100), 0.01, 1e-4);
  // Median of chi-square with 200 dof is about 199.33.
  EXPECT_NEAR(test::chiSquareSurvival(199.334, 200), 0.5, 1e-3);
  EXPECT_NEAR(test::sidakSignificance(0.01, 1), 0.01, 1e-15);
  EXPECT_NEAR(test::sidakSignificance(0.01, 20), 5.024e-4, 1e-6);
}

test::Chi2Options wrongSamplerOptions(uint64_t seed) {
  test::Chi2Options options;
  options.testCount = test::kChi2TestCount;
  options.seed = seed;
  return options;
}

TEST(Chi2SelfTest, RejectsCosineSamplesClaimedUniform) {
  const auto r = test::runChi2Test(
      [](float, const Vec2& u) -> std::optional<Vec3> { return sampleCosineHemisphere(u); },
      [](const Vec3& w) { return w.z() > 0.0f ? 1.0 / (2.0 * std::numbers::pi) : 0.0; }, wrongSamplerOptions(101));
  std::printf("[chi2-wrong] cosine sampled, uniform claimed:  %s\n", r.message.c_str());
  EXPECT_FALSE(r.passed) << r.message;
}

TEST(Chi2SelfTest, RejectsGgxDensityWithTenPercentWrongAlpha) {
  const GgxDistribution sampled(0.25f);
  const GgxDistribution claimed(0.275f);
  const Vec3 wo = test::directionFromCosPhi(0.7, 0.4);
  const auto r = test::runChi2Test(
      [&](float, const Vec2& u) -> std::optional<Vec3> { return sampled.sampleVisibleNormal(wo, u); },
      [&](const Vec3& wm) { return double(claimed.visibleD(wo, wm)); }, wrongSamplerOptions(102));
  std::printf("[chi2-wrong] GGX alpha 0.25 sampled, 0.275 claimed: %s\n", r.message.c_str());
  EXPECT_FALSE(r.passed) << r.message;
}

TEST(Chi2SelfTest, RejectsSamplerThatSilentlyDropsSamples) {
  // Right density, but 1% of the draws fail: the "no sample" cell expects none.
  const auto r = test::runChi2Test(
      [](float uLobe, const Vec2& u) -> std::optional<Vec3> {
        if (uLobe < 0.01f) return std::nullopt;
        return sampleCosineHemisphere(u);
      },
      [](const Vec3& w) { return double(cosineHemispherePdf(w.z())); }, wrongSamplerOptions(103));
  std::printf("[chi2-wrong] cosine sampler dropping 1%%:       %s\n", r.message.c_str());
  EXPECT_FALSE(r.passed) << r.message;
}

TEST(Chi2SelfTest, AcceptsTheRightDensity) {
  // The same cosine sampler with its true density passes (the control for the tests above).
  const auto r = test::runChi2Test(
      [](float, const Vec2& u) -> std::optional<Vec3> { return sampleCosineHemisphere(u); },
      [](const Vec3& w) { return double(cosineHemispherePdf(w.z())); }, wrongSamplerOptions(104));
  std::printf("[chi2-control] cosine sampled, cosine claimed:  %s\n", r.message.c_str());
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace chi2_self_test
}  // namespace lacrima
