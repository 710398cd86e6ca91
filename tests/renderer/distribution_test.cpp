// Piecewise-constant distributions (renderer/src/distribution.hpp): the guide table's search
// returns exactly the bin of the plain search, including for zero-probability bins, for u at
// and next to the guide's cell boundaries, and for the largest u below 1.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "distribution.hpp"

namespace lacrima::detail {
namespace distribution_test {

void expectSameSample(const CdfSample& plain, const CdfSample& guided, float u) {
  ASSERT_EQ(plain.index, guided.index) << "u = " << u;
  ASSERT_EQ(plain.offset, guided.offset) << "u = " << u;
  ASSERT_EQ(plain.probability, guided.probability) << "u = " << u;
}

void checkGuideMatchesPlainSearch(const std::vector<double>& weights, int guideCells) {
  std::vector<float> cdf(weights.size() + 1);
  buildCdf(weights, cdf);
  std::vector<int> guide(size_t(guideCells) + 1);
  buildGuide(cdf, guide);
  std::vector<float> us = {0.0f, 0x1.fffffep-1f, -0.5f, 2.0f};
  for (int k = 0; k <= guideCells; ++k) {  // each guide boundary and its float neighbours
    const float b = float(double(k) / guideCells);
    us.insert(us.end(), {b, std::nextafter(b, 0.0f), std::nextafter(b, 1.0f)});
  }
  for (float c : cdf) us.insert(us.end(), {c, std::nextafter(c, 0.0f), std::nextafter(c, 1.0f)});
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i < 20000; ++i) us.push_back(uniform(rng));
  for (float u : us) expectSameSample(sampleCdf(cdf, u), sampleCdf(cdf, guide, u), u);
}

TEST(Distribution, GuidedSearchMatchesPlainSearchOnASkewedDistribution) {
  std::vector<double> weights(2049);
  for (size_t i = 0; i < weights.size(); ++i) weights[i] = std::exp(-0.01 * double(i)) + (i == 900 ? 500.0 : 0.0);
  checkGuideMatchesPlainSearch(weights, int(weights.size()));
  checkGuideMatchesPlainSearch(weights, 7);
}

TEST(Distribution, GuidedSearchSkipsZeroBinsAsThePlainSearchDoes) {
  std::vector<double> weights(300, 0.0);
  weights[0] = 1.0;
  weights[150] = 2.0;
  weights[151] = 1e-30;  // below float resolution of the CDF: probability 0
  weights[299] = 1.0;
  checkGuideMatchesPlainSearch(weights, 301);
  checkGuideMatchesPlainSearch(weights, 1);
}

TEST(Distribution, GuidedSearchOnAUniformAndABlackDistribution) {
  checkGuideMatchesPlainSearch(std::vector<double>(64, 1.0), 65);
  checkGuideMatchesPlainSearch(std::vector<double>(10, 0.0), 11);  // made uniform
  checkGuideMatchesPlainSearch(std::vector<double>(1, 3.0), 2);
}

}  // namespace distribution_test
}  // namespace lacrima::detail
