// The pixel filters (renderer/include/lacrima/renderer/pixel_filter.hpp): their profiles
// integrate to 1, the importance sampler's offsets follow |f| (chi-square), its weights are 1
// without negative lobes and carry the sign of Mitchell's lobes, and the mapping from random
// numbers to offsets is monotone (stratification carries over) and deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "lacrima/renderer/sampler.hpp"
#include "lacrima/renderer/pixel_filter.hpp"

namespace lacrima {
namespace pixel_filter_test {

const std::vector<PixelFilter> kFilters = {
    {FilterType::Box, 1.0f},           {FilterType::Box, 2.0f},      {FilterType::Gaussian, 3.0f},
    {FilterType::Gaussian, 1.5f},      {FilterType::BlackmanHarris, 1.5f}, {FilterType::BlackmanHarris, 4.0f},
    {FilterType::Mitchell, 4.0f},      {FilterType::Mitchell, 2.5f}};

std::string nameOf(const PixelFilter& f) { return std::string(filterTypeName(f.type)) + " " + std::to_string(f.width); }

// Integral of g over [a, b], composite Simpson with n (even) intervals.
template <typename G>
double simpson(G&& g, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = g(a) + g(b);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * g(a + k * h);
  return sum * h / 3.0;
}

Vec2 randomPair(uint64_t seed, int index) { return PixelSampler(seed, 0, index, 0, 0).get2D(); }

// Upper tail of the chi-square distribution, Wilson-Hilferty approximation (good for dof >~ 30).
double chiSquareZScore(double chi2, double dof) {
  const double a = 2.0 / (9.0 * dof);
  return (std::cbrt(chi2 / dof) - (1.0 - a)) / std::sqrt(a);
}

TEST(PixelFilter, ProfilesIntegrateToOneOverTheirSupportAndVanishOutside) {
  for (const PixelFilter& f : kFilters) {
    const double r = 0.5 * f.width;
    const double integral = simpson([&](double x) { return filterProfile(f, x); }, -r, r, 20000);
    EXPECT_NEAR(integral, 1.0, 1e-6) << nameOf(f);
    EXPECT_EQ(filterProfile(f, r * 1.001), 0.0) << nameOf(f);
    EXPECT_EQ(filterProfile(f, -r * 1.001), 0.0) << nameOf(f);
    if (!hasNegativeLobes(f.type)) {
      for (int k = 0; k <= 1000; ++k) ASSERT_GE(filterProfile(f, -r + 2.0 * r * k / 1000), 0.0) << nameOf(f);
    }
  }
}

TEST(PixelFilter, KnownValues) {
  // Blackman-Harris: the coefficients sum to 1 at the centre; 6e-5 at the edge (Harris 1978).
  const PixelFilter bh{FilterType::BlackmanHarris, 2.0f};
  EXPECT_NEAR(filterProfile(bh, 0.0), 1.0 / (0.35875 * 2.0), 1e-12);
  EXPECT_NEAR(filterProfile(bh, 1.0), (0.35875 - 0.48829 + 0.14128 - 0.01168) / (0.35875 * 2.0), 1e-12);
  // Gaussian: sigma = width / 6, zero at the edge, the centre-to-1-sigma ratio.
  const PixelFilter gauss{FilterType::Gaussian, 3.0f};
  EXPECT_NEAR(filterProfile(gauss, 1.5), 0.0, 1e-15);
  const double g0 = 1.0 - std::exp(-4.5), g1 = std::exp(-0.5) - std::exp(-4.5);
  EXPECT_NEAR(filterProfile(gauss, 0.5) / filterProfile(gauss, 0.0), g1 / g0, 1e-12);
  // Mitchell-Netravali (B = C = 1/3): k(0) = (6 - 2B) / 6 = 8/9, k(1) = B / 6 = 1/18, and the
  // negative lobe k(1.5) = (-7/3 * 3.375 + 12 * 2.25 - 20 * 1.5 + 32/3) / 6 < 0; width 4 maps
  // x to 2x / 2 = x and scales by 1.
  const PixelFilter mitchell{FilterType::Mitchell, 4.0f};
  EXPECT_NEAR(filterProfile(mitchell, 0.0), 8.0 / 9.0, 1e-12);
  EXPECT_NEAR(filterProfile(mitchell, 1.0), 1.0 / 18.0, 1e-12);
  EXPECT_NEAR(filterProfile(mitchell, 1.5), (-7.0 / 3.0 * 3.375 + 12.0 * 2.25 - 20.0 * 1.5 + 32.0 / 3.0) / 6.0, 1e-12);
  EXPECT_LT(filterProfile(mitchell, 1.5), 0.0);
}

// Offsets against |f| normalized: 16 x 16 bins over the support (aligned with the sampler's 256
// table bins, so the expected probabilities are exactly those of the tabulated filter).
TEST(PixelFilter, SamplesFollowTheNormalizedMagnitudeOfTheFilter) {
  constexpr int kBins = 16, kSamples = 200000;
  for (const PixelFilter& f : kFilters) {
    const double r = 0.5 * f.width, binWidth = 2.0 * r / kBins;
    const auto magnitude = [&](double x) { return std::abs(filterProfile(f, x)); };
    std::vector<double> axis(kBins);
    double total = 0.0;
    for (int b = 0; b < kBins; ++b)
      total += axis[b] = simpson(magnitude, -r + b * binWidth, -r + (b + 1) * binWidth, 256);
    const FilterSampler sampler(f);
    std::vector<double> observed(kBins * kBins, 0.0);
    for (int k = 0; k < kSamples; ++k) {
      const Vec2 o = sampler.sample(randomPair(17, k)).offset;
      ASSERT_LE(std::abs(o.x()), r) << nameOf(f);
      ASSERT_LE(std::abs(o.y()), r) << nameOf(f);
      const int bx = std::clamp(int((o.x() + r) / binWidth), 0, kBins - 1);
      const int by = std::clamp(int((o.y() + r) / binWidth), 0, kBins - 1);
      observed[by * kBins + bx] += 1.0;
    }
    double chi2 = 0.0, pooledExpected = 0.0, pooledObserved = 0.0;
    int dof = -1;
    for (int by = 0; by < kBins; ++by) {
      for (int bx = 0; bx < kBins; ++bx) {
        const double e = axis[bx] / total * axis[by] / total * kSamples, o = observed[by * kBins + bx];
        if (e < 5.0) {  // pooled (Nori's chi2test)
          pooledExpected += e;
          pooledObserved += o;
          continue;
        }
        chi2 += (o - e) * (o - e) / e;
        ++dof;
      }
    }
    if (pooledExpected > 0.0) {
      chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
      ++dof;
    }
    ASSERT_GT(dof, 100) << nameOf(f);
    EXPECT_LT(chiSquareZScore(chi2, dof), 3.7) << nameOf(f) << ": chi2 " << chi2 << " for " << dof << " dof";
  }
}

TEST(PixelFilter, PdfIntegratesToOneAndMatchesTheMagnitude) {
  for (const PixelFilter& f : kFilters) {
    const FilterSampler sampler(f);
    const double r = 0.5 * f.width;
    const double integral = simpson([&](double x) { return sampler.pdf(Vec2(float(x), 0.0f)); }, -r, r, 4096) *
                            simpson([&](double y) { return sampler.pdf(Vec2(0.0f, float(y))) ; }, -r, r, 4096) /
                            sampler.pdf(Vec2(0.0f, 0.0f));
    EXPECT_NEAR(integral, 1.0, 2e-3) << nameOf(f);
    EXPECT_EQ(sampler.pdf(Vec2(float(r) * 1.01f, 0.0f)), 0.0) << nameOf(f);
  }
}

TEST(PixelFilter, WeightsAreExactlyOneWithoutNegativeLobes) {
  for (const PixelFilter& f : kFilters) {
    if (hasNegativeLobes(f.type)) continue;
    const FilterSampler sampler(f);
    for (int k = 0; k < 10000; ++k) ASSERT_EQ(sampler.sample(randomPair(3, k)).weight, 1.0f) << nameOf(f);
  }
}

TEST(PixelFilter, MitchellWeightsCarryTheSignOfItsLobesAndAverageOne) {
  for (float width : {4.0f, 2.5f}) {
    const PixelFilter f{FilterType::Mitchell, width};
    const FilterSampler sampler(f);
    const double peak = filterProfile(f, 0.0);
    constexpr int n = 200000;
    int negative = 0;
    double sum = 0.0, sumSq = 0.0;
    for (int k = 0; k < n; ++k) {
      const FilterSample s = sampler.sample(randomPair(5, k));
      const double fx = filterProfile(f, s.offset.x()), fy = filterProfile(f, s.offset.y());
      // Away from the zero crossings (where a table bin may straddle the sign change).
      if (std::abs(fx) > 1e-2 * peak && std::abs(fy) > 1e-2 * peak) {
        ASSERT_EQ(s.weight < 0.0f, fx * fy < 0.0) << s.offset.transpose() << " weight " << s.weight;
      }
      negative += s.weight < 0.0f ? 1 : 0;
      sum += s.weight;
      sumSq += double(s.weight) * s.weight;
    }
    // The negative lobes hold a few percent of |f| on each axis.
    EXPECT_GT(negative, n / 50) << width;
    EXPECT_LT(negative, n / 5) << width;
    // E[f / p] = integral f = 1.
    const double mean = sum / n, stdError = std::sqrt((sumSq / n - mean * mean) / n);
    EXPECT_NEAR(mean, 1.0, 5.0 * stdError) << width;
  }
}

TEST(PixelFilter, OffsetsAreMonotoneInTheirOwnRandomNumber) {
  // Each axis inverts a CDF: u.x() alone gives the x offset, monotonically, so a stratified
  // pattern of u stays stratified in the filter's measure.
  for (const PixelFilter& f : kFilters) {
    const FilterSampler sampler(f);
    float previous = -1e9f;
    for (int k = 0; k < 4096; ++k) {
      const float u = (k + 0.5f) / 4096.0f;
      const FilterSample a = sampler.sample(Vec2(u, 0.3f)), b = sampler.sample(Vec2(u, 0.9f));
      ASSERT_GE(a.offset.x(), previous) << nameOf(f) << " u " << u;
      ASSERT_EQ(a.offset.x(), b.offset.x()) << nameOf(f);
      ASSERT_EQ(sampler.sample(Vec2(0.3f, u)).offset.y(), a.offset.x()) << nameOf(f) << ": the axes differ";
      previous = a.offset.x();
    }
    EXPECT_NEAR(sampler.sample(Vec2(0.5f, 0.5f)).offset.norm(), 0.0f, 1e-5f) << nameOf(f) << ": median not central";
  }
}

TEST(PixelFilter, SamplingIsDeterministic) {
  const PixelFilter f{FilterType::Mitchell, 4.0f};
  const FilterSampler a(f), b(f);
  for (int k = 0; k < 1000; ++k) {
    const Vec2 u = randomPair(9, k);
    const FilterSample sa = a.sample(u), sb = b.sample(u);
    ASSERT_EQ(sa.offset.x(), sb.offset.x());
    ASSERT_EQ(sa.offset.y(), sb.offset.y());
    ASSERT_EQ(sa.weight, sb.weight);
  }
}

TEST(PixelFilter, DefaultIsBlackmanHarrisOfOneAndAHalfPixels) {
  const PixelFilter f;
  EXPECT_EQ(f.type, FilterType::BlackmanHarris);
  EXPECT_EQ(f.width, 1.5f);
  EXPECT_EQ(defaultFilterWidth(FilterType::BlackmanHarris), 1.5f);
  EXPECT_EQ(defaultFilterWidth(FilterType::Box), 1.0f);
}

}  // namespace pixel_filter_test
}  // namespace lacrima
