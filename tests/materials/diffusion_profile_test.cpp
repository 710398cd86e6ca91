// The Christensen & Burley 2015 diffusion profile (lacrima/materials/diffusion_profile.hpp): its
// integral is the albedo, the radius sampler follows its density (chi-square), and maxRadius
// holds 99 % of the uncut profile's energy.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "chi2_support.hpp"
#include "lacrima/materials/diffusion_profile.hpp"

namespace lacrima {
namespace diffusion_profile_test {

// Integral of f over [a, b] by composite Simpson with n (even) intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += f(a + i * h) * (i % 2 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

// Integral of 2 pi r R_c(r) over [r0, r1]: the energy leaving between those radii. In log r (the
// profile spans decades and 2 pi r R(r) is finite at 0, so the lower end is taken tiny).
double energyBetween(const DiffusionProfile& p, int c, double r0, double r1) {
  return simpson([&](double logR) {
    const double r = std::exp(logR);
    return 2.0 * kPi * r * p.eval(float(r))[c] * r;  // dr = r dlogr
  }, std::log(r0), std::log(r1), 20000);
}

TEST(DiffusionProfile, ScalingFollowsChristensenBurleyEquation8) {
  EXPECT_NEAR(burleyDiffuseTransmissionScaling(0.8f), 1.1f, 1e-6f);
  EXPECT_NEAR(burleyDiffuseTransmissionScaling(0.0f), 1.9f + 3.5f * 0.64f, 1e-6f);
  EXPECT_NEAR(burleyDiffuseTransmissionScaling(1.0f), 0.9f + 3.5f * 0.04f, 1e-6f);
  const DiffusionProfile p(Color(0.8f, 0.5f, 0.2f), Color(1e-3f, 2e-3f, 4e-3f));
  EXPECT_NEAR(p.shape()[0], 1e-3f / 1.1f, 1e-9f);
  EXPECT_NEAR(p.shape()[2], 4e-3f / burleyDiffuseTransmissionScaling(0.2f), 1e-9f);
}

// The profile's integral over the plane is the albedo (eq. 2 integrates to A; the cut at
// maxRadius is scaled back): per channel, for skin-like and extreme albedos. maxRadius holds 99 %
// of the uncut profile's energy, and the profile is zero from there on.
TEST(DiffusionProfile, IntegratesToTheAlbedo) {
  const DiffusionProfile p(Color(0.56f, 0.05f, 0.97f), Color(1.3e-3f, 0.5e-3f, 3e-3f));
  for (int c = 0; c < 3; ++c) {
    const double d = p.shape()[c], rMax = p.maxRadius(c);
    EXPECT_NEAR(energyBetween(p, c, 1e-7 * d, std::nextafter(rMax, 0.0)), p.albedo()[c], 1e-4) << "channel " << c;
    EXPECT_EQ(p.eval(float(rMax))[c], 0.0f);
    // The uncut mixture's CDF at maxRadius: 1 - exp(-x)/4 - 3 exp(-x/3)/4, x = rMax / d.
    const double x = rMax / d;
    EXPECT_NEAR(1.0 - 0.25 * std::exp(-x) - 0.75 * std::exp(-x / 3.0), 0.99, 1e-5) << "channel " << c;
  }
}

// The radius density is normalised on [0, maxRadius) and zero outside.
TEST(DiffusionProfile, RadiusDensityIsNormalised) {
  const DiffusionProfile p(Color(0.56f, 0.37f, 0.29f), Color(1.3e-3f, 0.95e-3f, 0.67e-3f));
  for (int c = 0; c < 3; ++c) {
    const double rMax = p.maxRadius(c);
    const double total = simpson([&](double r) { return double(p.radiusPdf(c, float(r))); }, 0.0,
                                 std::nextafter(rMax, 0.0), 200000);
    EXPECT_NEAR(total, 1.0, 1e-4) << "channel " << c;
    EXPECT_EQ(p.radiusPdf(c, float(rMax) * 1.01f), 0.0f);
    EXPECT_EQ(p.radiusPdf(c, -1e-6f), 0.0f);
  }
}

// Chi-square of sampled radii against radiusPdf over 40 equal-width bins (pooled below 5
// expected), at significance 0.01 over the three channels (Sidak).
TEST(DiffusionProfile, SampledRadiiFollowTheRadiusDensity) {
  const DiffusionProfile p(Color(0.56f, 0.37f, 0.9f), Color(1.3e-3f, 0.95e-3f, 0.2e-3f));
  constexpr int kBins = 40;
  constexpr long long kSamples = 400000;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int c = 0; c < 3; ++c) {
    const double rMax = p.maxRadius(c), width = rMax / kBins;
    std::vector<double> observed(kBins, 0.0), expected(kBins, 0.0);
    for (long long i = 0; i < kSamples; ++i) {
      const float r = p.sampleRadius(c, uniform(rng));
      ASSERT_GE(r, 0.0f);
      ASSERT_LT(r, rMax);
      observed[std::min(int(r / width), kBins - 1)] += 1.0;
    }
    for (int b = 0; b < kBins; ++b)
      expected[b] = kSamples * simpson([&](double r) { return double(p.radiusPdf(c, float(r))); }, b * width,
                                       std::min((b + 1) * width, std::nextafter(rMax, 0.0)), 200);
    double statistic = 0.0, pooledO = 0.0, pooledE = 0.0;
    int dof = -1;
    for (int b = 0; b < kBins; ++b) {
      pooledO += observed[b];
      pooledE += expected[b];
      if (pooledE < 5.0) continue;
      statistic += (pooledO - pooledE) * (pooledO - pooledE) / pooledE;
      ++dof;
      pooledO = pooledE = 0.0;
    }
    if (pooledE > 0.0) statistic += (pooledO - pooledE) * (pooledO - pooledE) / pooledE;
    const double pValue = test::chiSquareSurvival(statistic, dof);
    std::printf("[diffusion profile] channel %d: chi2 %.1f, dof %d, p %.3f\n", c, statistic, dof, pValue);
    EXPECT_GT(pValue, test::sidakSignificance(0.01, 3)) << "channel " << c;
  }
}

// The sampler can fail: a radius density off by a factor (here the untruncated mixture drawn with
// the wrong component weights) must be rejected by the same statistic.
TEST(DiffusionProfile, ChiSquareRejectsAWrongRadiusDistribution) {
  const DiffusionProfile p(Color::Constant(0.5f), Color::Constant(1e-3f));
  constexpr int kBins = 40;
  constexpr long long kSamples = 400000;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  const double d = p.shape()[0], rMax = p.maxRadius(0), width = rMax / kBins;
  std::vector<double> observed(kBins, 0.0);
  for (long long i = 0; i < kSamples; ++i) {
    const double mean = uniform(rng) < 0.5 ? d : 3.0 * d;  // 1/2 each instead of 1/4 and 3/4
    const double r = -mean * std::log1p(-uniform(rng));
    if (r < rMax) observed[int(r / width)] += 1.0;
  }
  double statistic = 0.0;
  for (int b = 0; b < kBins; ++b) {
    const double e = kSamples * simpson([&](double r) { return double(p.radiusPdf(0, float(r))); }, b * width,
                                        std::min((b + 1) * width, std::nextafter(rMax, 0.0)), 200);
    statistic += (observed[b] - e) * (observed[b] - e) / std::max(e, 5.0);
  }
  EXPECT_LT(test::chiSquareSurvival(statistic, kBins - 1), 1e-6);
}

}  // namespace diffusion_profile_test
}  // namespace lacrima
