// The stratified sampler's building blocks (sobol.hpp) and PixelSampler's Sobol mode: the
// sequence's known values, the (0,m,2)-net property with and without Owen scrambling, the index
// permutation being a bijection, and the points' discrepancy against independent random numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <vector>

#include "lacrima/renderer/sampler.hpp"
#include "lacrima/renderer/sobol.hpp"

namespace lacrima {
namespace sobol_test {

using Point = std::pair<double, double>;

double unit(uint32_t bits) { return double(bits) * 0x1p-32; }

// True when each elementary interval of area 2^-m of every shape 2^-a x 2^-(m-a) holds exactly
// one of the 2^m points (Niederreiter 1992, def. 4.1: a (0,m,2)-net in base 2).
bool isZeroNet(const std::vector<Point>& points, int m) {
  const size_t n = size_t(1) << m;
  if (points.size() != n) return false;
  for (int a = 0; a <= m; ++a) {
    std::vector<int> count(n, 0);
    for (const auto& [x, y] : points) {
      const size_t i = size_t(x * double(1 << a)), j = size_t(y * double(1 << (m - a)));
      ++count[(i << (m - a)) | j];
    }
    if (std::any_of(count.begin(), count.end(), [](int c) { return c != 1; })) return false;
  }
  return true;
}

// L2 star discrepancy (Warnock 1972): the root mean square, over boxes [0,t), of the difference
// between the fraction of points inside and the box's area.
double l2StarDiscrepancy(const std::vector<Point>& p) {
  const double n = double(p.size());
  double sum1 = 0.0, sum2 = 0.0;
  for (const auto& [x, y] : p) sum1 += (1.0 - x * x) * (1.0 - y * y);
  for (const auto& [xi, yi] : p)
    for (const auto& [xj, yj] : p) sum2 += (1.0 - std::max(xi, xj)) * (1.0 - std::max(yi, yj));
  return std::sqrt(1.0 / 9.0 - sum1 / (2.0 * n) + sum2 / (n * n));
}

TEST(Sobol, ReverseBitsIsAnInvolutionWithKnownValues) {
  EXPECT_EQ(reverseBits32(1u), 0x80000000u);
  EXPECT_EQ(reverseBits32(0x0000000Fu), 0xF0000000u);
  EXPECT_EQ(reverseBits32(0x12345678u), 0x1E6A2C48u);
  for (uint32_t v : {0u, 7u, 0xdeadbeefu, 0xffffffffu}) EXPECT_EQ(reverseBits32(reverseBits32(v)), v);
}

// The sampler's hot path reads the reversed table and scrambles in reversed order: it must give
// exactly the points and scrambles of the plain definitions.
TEST(Sobol, ReversedTableAndScrambleMatchThePlainDefinitions) {
  EXPECT_EQ(reverseBits32Constexpr(0x12345678u), 0x1E6A2C48u);
  for (int dimension = 0; dimension < 4; ++dimension)
    for (uint32_t i = 0; i < 5000; i += (i < 1100 ? 1 : 37)) {
      ASSERT_EQ(sobolSampleReversed(i, dimension), reverseBits32(sobolSample(i, dimension))) << dimension << " " << i;
      const uint32_t seed = 0x9e3779b9u * (i + 1) + uint32_t(dimension);
      ASSERT_EQ(reverseBits32(owenScrambleReversed(sobolSampleReversed(i, dimension), seed)),
                owenScramble(sobolSample(i, dimension), seed));
    }
  EXPECT_EQ(sobolSample(0xffffffffu, 0), 0xffffffffu);  // every direction number of dimension 0
}

// The first eight points of the Sobol sequence's first two dimensions in natural (not Gray-code) order
// (Sobol' 1967; Joe & Kuo 2008).
TEST(Sobol, FirstPointsMatchTheSequence) {
  const double x[] = {0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  const double y[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  const double z[] = {0, 0.5, 0.75, 0.25, 0.375, 0.875, 0.625, 0.125};
  for (uint32_t i = 0; i < 8; ++i) {
    EXPECT_EQ(unit(sobolDimension0(i)), x[i]) << i;
    EXPECT_EQ(unit(sobolSample(i, 0)), x[i]) << i;
    EXPECT_EQ(unit(sobolSample(i, 1)), y[i]) << i;
    EXPECT_EQ(unit(sobolSample(i, 2)), z[i]) << i;
  }
}

// Each dimension alone is a (0,1)-sequence: its k-th direction number m_k / 2^(k+1) has m_k odd, so
// its lowest set bit is fraction bit k + 1 (the generator matrix is triangular with a unit
// diagonal), and every aligned block of 2^m indices fills each interval of length 2^-m once.
TEST(Sobol, EachOfTheFourDimensionsIsStratifiedAlone) {
  for (int dimension = 0; dimension < 4; ++dimension) {
    for (int k = 0; k < 32; ++k) {
      const uint32_t v = kSobolDirections.v[dimension][k];
      EXPECT_EQ((v >> (31 - k)) & 1u, 1u) << dimension << " " << k;
      if (k < 31) {
        EXPECT_EQ(v & ((1u << (31 - k)) - 1u), 0u) << dimension << " " << k;
      }
    }
    for (int m : {3, 8}) {
      std::vector<int> count(size_t(1) << m, 0);
      for (uint32_t i = 0; i < (1u << m); ++i) ++count[sobolSample(i + (3u << m), dimension) >> (32 - m)];
      EXPECT_TRUE(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; })) << dimension << " " << m;
    }
  }
}

std::vector<Point> sobolBlock(uint32_t first, int m, uint32_t seedX, uint32_t seedY, bool scrambled) {
  std::vector<Point> points;
  for (uint32_t i = first; i < first + (1u << m); ++i) {
    const uint32_t x = sobolSample(i, 0), y = sobolSample(i, 1);
    points.emplace_back(unit(scrambled ? owenScramble(x, seedX) : x), unit(scrambled ? owenScramble(y, seedY) : y));
  }
  return points;
}

TEST(Sobol, EveryAlignedBlockOfTwoToTheMPointsIsANet) {
  for (int m = 0; m <= 10; ++m)
    for (uint32_t block : {0u, 1u, 5u}) EXPECT_TRUE(isZeroNet(sobolBlock(block << m, m, 0, 0, false), m)) << m;
}

TEST(Sobol, OwenScramblingKeepsTheNetAndChangesThePoints) {
  for (int m = 1; m <= 10; ++m)
    for (uint32_t seed : {1u, 0x9e3779b9u, 0xdeadbeefu}) {
      const auto scrambled = sobolBlock(0, m, seed, seed * 7919u + 1, true);
      EXPECT_TRUE(isZeroNet(scrambled, m)) << "m " << m << " seed " << seed;
      EXPECT_NE(scrambled, sobolBlock(0, m, 0, 0, false));
    }
}

TEST(Sobol, OwenScrambleIsABijectionOnEveryBitPrefix) {
  // Nested: the top k bits of the output depend only on the top k bits of the input, and the map
  // of those k bits is a permutation of the 2^k values.
  for (int k : {1, 4, 8}) {
    std::set<uint32_t> images;
    for (uint32_t top = 0; top < (1u << k); ++top) {
      const uint32_t input = top << (32 - k);
      const uint32_t image = owenScramble(input, 12345u) >> (32 - k);
      EXPECT_EQ(owenScramble(input | 0x5a5a5u, 12345u) >> (32 - k), image) << "lower bits changed the top bits";
      images.insert(image);
    }
    EXPECT_EQ(images.size(), size_t(1) << k);
  }
}

TEST(Sobol, PermutationElementIsABijectionForAnyCount) {
  for (uint32_t n : {1u, 2u, 3u, 5u, 16u, 17u, 100u, 1000u})
    for (uint32_t seed : {0u, 1u, 0xabcdef12u}) {
      std::vector<uint32_t> image(n);
      for (uint32_t i = 0; i < n; ++i) image[i] = permutationElement(i, n, seed);
      std::vector<uint32_t> sorted = image;
      std::sort(sorted.begin(), sorted.end());
      std::vector<uint32_t> identity(n);
      std::iota(identity.begin(), identity.end(), 0u);
      EXPECT_EQ(sorted, identity) << "n " << n << " seed " << seed;
    }
  std::vector<uint32_t> a, b;
  for (uint32_t i = 0; i < 64; ++i) {
    a.push_back(permutationElement(i, 64, 1u));
    b.push_back(permutationElement(i, 64, 2u));
  }
  EXPECT_NE(a, b);
}

TEST(Sobol, ProgressiveElementMapsEveryPowerOfTwoPrefixOntoOneAlignedBlock) {
  for (uint32_t n : {2u, 16u, 100u, 1024u})
    for (uint32_t seed : {0u, 7u, 0x9e3779b9u}) {
      uint32_t size = 1;
      while (size < n) size <<= 1;
      std::vector<uint32_t> image(size);
      for (uint32_t i = 0; i < size; ++i) image[i] = progressiveElement(i, n, seed);
      std::vector<uint32_t> sorted = image;
      std::sort(sorted.begin(), sorted.end());
      std::vector<uint32_t> identity(size);
      std::iota(identity.begin(), identity.end(), 0u);
      ASSERT_EQ(sorted, identity) << "n " << n << " seed " << seed;
      for (uint32_t block = 1; block <= size; block <<= 1) {
        const uint32_t base = image[0] / block * block;
        for (uint32_t i = 0; i < block; ++i)
          EXPECT_EQ(image[i] / block * block, base) << "n " << n << " prefix " << block << " index " << i;
      }
    }
  // Not the identity: the prefix's block and its order depend on the seed.
  std::vector<uint32_t> a, b;
  for (uint32_t i = 0; i < 64; ++i) {
    a.push_back(progressiveElement(i, 64, 1u));
    b.push_back(progressiveElement(i, 64, 2u));
  }
  EXPECT_NE(a, b);
}

std::vector<Point> pixelPoints(SamplerKind kind, int x, int y, int spp, uint32_t dimension,
                               SampleOrder order = SampleOrder::Shuffled, int count = -1) {
  std::vector<Point> points;
  for (int i = 0; i < (count < 0 ? spp : count); ++i) {
    PixelSampler sampler(kind, 42, 3, x, y, i, spp, order);
    sampler.setDimension(dimension);
    const Vec2 u = sampler.get2D();
    points.emplace_back(u.x(), u.y());
  }
  return points;
}

TEST(PixelSamplerSobol, EachDimensionPairOfAPixelIsANetForPowerOfTwoCounts) {
  for (int m : {0, 2, 4, 6, 8})
    for (uint32_t dimension : {0u, 2u, 9u, 100u}) {
      // The floats keep 24 of the 32 bits: the net's intervals (at most 2^8 here) are unaffected.
      EXPECT_TRUE(isZeroNet(pixelPoints(SamplerKind::Sobol, 5, 9, 1 << m, dimension), m))
          << "spp " << (1 << m) << " dimension " << dimension;
    }
}

// Adaptive sampling stops a pixel early: with the progressive order every power-of-two prefix of
// the maximum count is a net, where the shuffled order's prefix is a random subset that is not.
TEST(PixelSamplerSobol, ProgressiveOrderKeepsEveryPowerOfTwoPrefixANet) {
  const int maxSpp = 256;
  int shuffledNets = 0;
  for (int m : {2, 4, 6, 8})
    for (uint32_t dimension : {0u, 2u, 9u, 100u}) {
      EXPECT_TRUE(isZeroNet(pixelPoints(SamplerKind::Sobol, 5, 9, maxSpp, dimension, SampleOrder::Progressive, 1 << m), m))
          << "prefix " << (1 << m) << " dimension " << dimension;
      shuffledNets += isZeroNet(pixelPoints(SamplerKind::Sobol, 5, 9, maxSpp, dimension, SampleOrder::Shuffled, 1 << m), m);
    }
  EXPECT_LT(shuffledNets, 8);  // the full count (m = 8) is a net in either order
}

TEST(PixelSamplerSobol, OneDimensionIsStratifiedIntoOnePointPerInterval) {
  const int spp = 64;
  std::vector<int> count(spp, 0);
  for (int i = 0; i < spp; ++i) {
    PixelSampler sampler(SamplerKind::Sobol, 1, 0, 7, 8, i, spp);
    sampler.setDimension(13);
    ++count[size_t(sampler.get1D() * spp)];
  }
  EXPECT_TRUE(std::all_of(count.begin(), count.end(), [](int c) { return c == 1; }));
}

TEST(PixelSamplerSobol, PairsPixelsAndKeysAreDecorrelated) {
  const auto base = pixelPoints(SamplerKind::Sobol, 5, 9, 16, 0);
  EXPECT_NE(base, pixelPoints(SamplerKind::Sobol, 6, 9, 16, 0));  // another pixel
  EXPECT_NE(base, pixelPoints(SamplerKind::Sobol, 5, 9, 16, 2));  // another pair
  EXPECT_EQ(base, pixelPoints(SamplerKind::Sobol, 5, 9, 16, 0));  // deterministic
  // Two pairs of the same samples: the correlation of their x over 256 samples is small (the
  // shared Sobol index would make them equal without the per-pair shuffle and scramble).
  const auto first = pixelPoints(SamplerKind::Sobol, 1, 1, 256, 0), second = pixelPoints(SamplerKind::Sobol, 1, 1, 256, 2);
  double sxy = 0, sx = 0, sy = 0, sxx = 0, syy = 0;
  for (size_t i = 0; i < first.size(); ++i) {
    const double a = first[i].first, b = second[i].first;
    sxy += a * b, sx += a, sy += b, sxx += a * a, syy += b * b;
  }
  const double n = double(first.size());
  const double correlation = (sxy / n - sx * sy / (n * n)) /
                             std::sqrt((sxx / n - sx * sx / (n * n)) * (syy / n - sy * sy / (n * n)));
  EXPECT_LT(std::abs(correlation), 0.2);  // 3.2 standard deviations of independent samples
}

TEST(PixelSamplerSobol, DiscrepancyIsFarBelowIndependentSamples) {
  // Averaged over pixels: independent points have E[D^2] = (1/4 - 1/9) / n (the variance of the
  // box indicator), Sobol nets about O(log n / n).
  for (int spp : {16, 64, 256}) {
    double sobol = 0.0, independent = 0.0;
    for (int pixel = 0; pixel < 16; ++pixel) {
      sobol += l2StarDiscrepancy(pixelPoints(SamplerKind::Sobol, pixel, 0, spp, 4));
      independent += l2StarDiscrepancy(pixelPoints(SamplerKind::Independent, pixel, 0, spp, 4));
    }
    EXPECT_LT(sobol, 0.5 * independent) << "spp " << spp;
    EXPECT_NEAR(independent / 16, std::sqrt((0.25 - 1.0 / 9.0) / spp), 0.5 * std::sqrt((0.25 - 1.0 / 9.0) / spp))
        << "spp " << spp;
  }
}

TEST(PixelSamplerSobol, IndependentStreamDoesNotMoveTheSamplersDimension) {
  PixelSampler sampler(SamplerKind::Sobol, 1, 2, 3, 4, 5, 16);
  sampler.setDimension(7);
  PixelSampler stream = sampler.independentStream(7);
  const float a = stream.get1D(), b = stream.get1D();
  EXPECT_NE(a, b);
  EXPECT_EQ(sampler.dimension(), 7u);
  EXPECT_NE(sampler.independentStream(8).get1D(), a);
}

}  // namespace sobol_test
}  // namespace lacrima
