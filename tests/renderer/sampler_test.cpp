// The deterministic per-pixel sampler: a pure function of its key, uniform over each component.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "lacrima/renderer/sampler.hpp"

namespace lacrima {
namespace sampler_test {

TEST(PixelSampler, SameKeyGivesSameValues) {
  PixelSampler a(42, 3, 10, 20, 5), b(42, 3, 10, 20, 5);
  for (int d = 0; d < 64; ++d) EXPECT_EQ(a.get1D(), b.get1D());
  EXPECT_EQ(a.dimension(), 64u);
}

TEST(PixelSampler, EveryKeyComponentChangesTheValues) {
  const auto first8 = [](PixelSampler s) {
    std::vector<float> v;
    for (int i = 0; i < 8; ++i) v.push_back(s.get1D());
    return v;
  };
  const std::vector<float> base = first8(PixelSampler(42, 3, 10, 20, 5));
  EXPECT_NE(base, first8(PixelSampler(43, 3, 10, 20, 5)));  // seed
  EXPECT_NE(base, first8(PixelSampler(42, 4, 10, 20, 5)));  // frame
  EXPECT_NE(base, first8(PixelSampler(42, 3, 11, 20, 5)));  // pixel x
  EXPECT_NE(base, first8(PixelSampler(42, 3, 10, 21, 5)));  // pixel y
  EXPECT_NE(base, first8(PixelSampler(42, 3, 20, 10, 5)));  // x and y swapped
  EXPECT_NE(base, first8(PixelSampler(42, 3, 10, 20, 6)));  // sample index
  // Different dimensions of one sample differ too.
  EXPECT_EQ(std::set<float>(base.begin(), base.end()).size(), base.size());
}

// Mean of N uniform values has standard deviation sqrt(1/12/N); allow 5 sigma.
void expectUniformMean(const std::vector<float>& values) {
  double sum = 0.0, sumSq = 0.0;
  for (float v : values) {
    ASSERT_GE(v, 0.0f);
    ASSERT_LT(v, 1.0f);
    sum += v;
    sumSq += double(v) * v;
  }
  const double n = double(values.size());
  const double mean = sum / n;
  const double sigma = std::sqrt(1.0 / 12.0 / n);
  EXPECT_NEAR(mean, 0.5, 5.0 * sigma);
  // Variance of U(0,1) is 1/12; its estimator has std sqrt(1/180/n) (4th central moment 1/80).
  const double variance = sumSq / n - mean * mean;
  EXPECT_NEAR(variance, 1.0 / 12.0, 5.0 * std::sqrt((1.0 / 80.0 - 1.0 / 144.0) / n));
}

TEST(PixelSampler, UniformAcrossPixels) {
  std::vector<float> values;
  for (int i = 0; i < 100000; ++i) values.push_back(PixelSampler(1, 0, i % 317, i / 317, 0).get1D());
  expectUniformMean(values);
}

TEST(PixelSampler, UniformAcrossDimensions) {
  PixelSampler s(9, 1, 2, 3, 4);
  std::vector<float> values;
  for (int i = 0; i < 100000; ++i) values.push_back(s.get1D());
  expectUniformMean(values);
}

TEST(PixelSampler, UniformAcrossSampleIndices) {
  std::vector<float> values;
  for (int i = 0; i < 100000; ++i) values.push_back(PixelSampler(5, 7, 64, 64, i).get2D().y());
  expectUniformMean(values);
}

}  // namespace sampler_test
}  // namespace lacrima
