// Adaptive sampling (renderer/include/lacrima/renderer/adaptive_sampling.hpp): the error estimate,
// the schedule of sample counts, the choice of the pixels that go on (with their neighbours), and
// on rendered scenes: converged regions stop at the minimum, edges take more, the sample-count
// AOV says so, the image is the same for any thread count, and at equal total samples the error
// is lower than with the same samples spread evenly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "lacrima/renderer/adaptive_sampling.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace adaptive_sampling_test {

using test::lookAt;

PixelSums sumsOf(const std::vector<Color>& samples) {
  PixelSums sum;
  for (const Color& L : samples) {
    sum.weightedRadiance += L;
    sum.weight += 1.0f;
    addRadiance(sum, L);
  }
  return sum;
}

std::vector<Color> steps(int ones, int zeros, float value = 1.0f) {
  std::vector<Color> samples(size_t(ones), Color::Constant(value));
  samples.resize(size_t(ones + zeros), Color::Zero());
  return samples;
}

TEST(AdaptiveSampling, ErrorComparesTheWholeWithItsFirstPowerOfTwoSamples) {
  EXPECT_LT(pixelError(sumsOf(std::vector<Color>(16, Color(0.3f, 0.2f, 0.1f)))), 1e-6f);  // rounding only
  EXPECT_EQ(pixelError(sumsOf(std::vector<Color>(16, Color::Zero()))), 0.0f);
  // 16 samples, the first 8 at 1 and the next 8 at 0: whole 0.5, first half 1, 3 * 0.5 / sqrt(1.5).
  EXPECT_NEAR(pixelError(sumsOf(steps(8, 8))), 1.5f / (1e-4f + std::sqrt(1.5f)), 1e-5f);
  // Alternating 1, 0, 1, 0 ...: the first 8 agree with all 16 (what a stratified pixel looks like).
  std::vector<Color> alternating;
  for (int i = 0; i < 16; ++i) alternating.push_back(Color::Constant(i % 2 == 0 ? 1.0f : 0.0f));
  EXPECT_LT(pixelError(sumsOf(alternating)), 1e-6f);
  // 24 samples: against the first 16, the difference scaled by sqrt(16 / 8). Whole 16/24, first 1.
  EXPECT_NEAR(pixelError(sumsOf(steps(16, 8))),
              3.0f * (1.0f - 16.0f / 24.0f) * std::sqrt(2.0f) / (1e-4f + std::sqrt(3.0f * 16.0f / 24.0f)), 1e-5f);
  // Relative to the square root of the value: ten times brighter, sqrt(10) times the error.
  EXPECT_NEAR(pixelError(sumsOf(steps(8, 8, 10.0f))) / pixelError(sumsOf(steps(8, 8))), std::sqrt(10.0f), 1e-3f);
  EXPECT_TRUE(std::isinf(pixelError(sumsOf({Color::Ones()}))));  // one sample has nothing to compare
}

TEST(AdaptiveSampling, SampleCountsGoFromTheMinimumInPowerOfTwoStepsToTheMaximum) {
  const AdaptiveSampling settings{true, 0.01f, 16};
  std::vector<int> counts{0};
  while (counts.back() < 100) counts.push_back(nextSampleCount(counts.back(), settings, 100));
  EXPECT_EQ(counts, (std::vector<int>{0, 16, 20, 24, 28, 32, 40, 48, 56, 64, 80, 96, 100}));
  EXPECT_EQ(nextSampleCount(0, settings, 8), 8);  // a minimum over the maximum stops at the maximum
  EXPECT_EQ(nextSampleCount(5, settings, 100), 16);
}

TEST(AdaptiveSampling, AnUnconvergedPixelKeepsItselfAndItsEightNeighboursActive) {
  const int w = 6, h = 5;
  const AdaptiveSampling settings{true, 0.01f, 4};
  std::vector<PixelSums> sums(size_t(w) * h, sumsOf(std::vector<Color>(8, Color::Constant(0.5f))));
  sums[size_t(2) * w + 3] = sumsOf(steps(4, 4));     // (3, 2): not converged
  sums[size_t(1) * w + 4] = sumsOf(std::vector<Color>(64, Color::Constant(0.5f)));  // its neighbour at the maximum
  sums[size_t(4) * w + 0] = sumsOf({Color::Ones(), Color::Ones()});  // under the minimum: goes on
  std::vector<uint8_t> active;
  const int count = selectActivePixels(sums, w, h, settings, 64, active);
  std::vector<uint8_t> expected(size_t(w) * h, 0);
  for (int y = 1; y <= 3; ++y)
    for (int x = 2; x <= 4; ++x) expected[size_t(y) * w + x] = 1;
  expected[size_t(1) * w + 4] = 0;  // at the maximum: done whatever its neighbours say
  expected[size_t(4) * w + 0] = 1;
  expected[size_t(3) * w + 0] = expected[size_t(3) * w + 1] = expected[size_t(4) * w + 1] = 1;
  EXPECT_EQ(active, expected);
  EXPECT_EQ(count, std::accumulate(expected.begin(), expected.end(), 0));
}

// An emitting sphere seen out of focus on black (as in sampler_convergence_test.cpp): black
// pixels and the sphere's inside are exact from the first sample, only the blurred edge is noisy.
Frame defocusedEdgeScene() {
  Frame frame;
  frame.materials.push_back(Material{"glow", DiffuseParams{Color::Zero()}, Color::Ones()});
  frame.spheres.push_back(Sphere{Vec3(0, 0, 0), 0.5f, 0});
  frame.camera = lookAt(Vec3(0.3f, 0.1f, 2.0f), Vec3(0.3f, 0.1f, 0), 30.0f);
  frame.camera.lensRadius = 0.05f;
  frame.camera.focusDistance = 6.0f;
  frame.settings = test::smallSettings(24, 256, 0);
  frame.settings.adaptive = AdaptiveSampling{true, 0.01f, 16};
  return frame;
}

TEST(AdaptiveSampling, ExactRegionsStopAtTheMinimumAndTheBlurredEdgeTakesMore) {
  const Frame frame = defocusedEdgeScene();
  RenderStats stats;
  const Film film = renderFrame(frame, &stats);
  ASSERT_EQ(film.sampleCount.size(), size_t(24 * 24));
  int atMinimum = 0, atMaximum = 0;
  double total = 0.0;
  for (size_t p = 0; p < film.sampleCount.size(); ++p) {
    const float n = film.sampleCount[p];
    total += n;
    atMinimum += n == 16.0f;
    atMaximum += n == 256.0f;
    const float value = film.rgba[4 * p];
    // A pixel all black or all sphere (the same value from every sample) stops at the minimum
    // unless a neighbour is on the edge.
    if (value == 0.0f || value == 1.0f) {
      const int x = int(p % 24), y = int(p / 24);
      bool nearEdge = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= 24 || ny >= 24) continue;
          const float v = film.rgba[4 * (size_t(ny) * 24 + nx)];
          nearEdge |= v != 0.0f && v != 1.0f;
        }
      if (!nearEdge) {
        EXPECT_EQ(n, 16.0f) << "pixel " << x << ", " << y;
      }
    }
  }
  EXPECT_GT(atMinimum, 24 * 24 / 3);
  EXPECT_GT(atMaximum, 0);  // the edge pixels are still short of 1 % at 256 samples
  EXPECT_EQ(stats.cameraPaths, uint64_t(total));
  EXPECT_LT(total, 0.5 * 24 * 24 * 256);
}

TEST(AdaptiveSampling, TheImageAndItsSampleCountsAreTheSameForAnyThreadCount) {
  Frame frame = defocusedEdgeScene();
  frame.settings.threads = 1;
  const Film one = renderFrame(frame);
  frame.settings.threads = 2;
  const Film two = renderFrame(frame);
  EXPECT_EQ(one.rgba, two.rgba);
  EXPECT_EQ(one.sampleCount, two.sampleCount);
}

TEST(AdaptiveSampling, WithoutItTheFilmHasNoSampleCounts) {
  Frame frame = defocusedEdgeScene();
  frame.settings.adaptive.enabled = false;
  frame.settings.samplesPerPixel = 4;
  EXPECT_TRUE(renderFrame(frame).sampleCount.empty());
}

double rmse(const Film& image, const Film& reference) {
  double sum = 0.0;
  for (size_t p = 0; p < image.rgba.size(); p += 4)
    for (int c = 0; c < 3; ++c) sum += std::pow(double(image.rgba[p + c]) - reference.rgba[p + c], 2);
  return std::sqrt(sum / double(3 * image.rgba.size() / 4));
}

// The point of it: the same number of camera samples, spent where the error is, gives a lower
// error than spread evenly. Each error is the mean over four seeds against a 4096-spp reference.
TEST(AdaptiveSampling, AtEqualTotalSamplesTheErrorIsLowerThanSpreadEvenly) {
  Frame frame = defocusedEdgeScene();
  frame.settings.adaptive.enabled = false;
  frame.settings.samplesPerPixel = 4096;
  frame.settings.seed = 1000;
  const Film reference = renderFrame(frame);
  double adaptiveError = 0.0, evenError = 0.0, adaptiveSamples = 0.0;
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    Frame adaptive = defocusedEdgeScene();
    adaptive.settings.seed = seed;
    RenderStats stats;
    adaptiveError += rmse(renderFrame(adaptive, &stats), reference) / 4.0;
    adaptiveSamples += double(stats.cameraPaths) / 4.0;
    Frame even = defocusedEdgeScene();
    even.settings.adaptive.enabled = false;
    even.settings.seed = seed;
    even.settings.samplesPerPixel = int(std::lround(double(stats.cameraPaths) / (24.0 * 24.0)));
    evenError += rmse(renderFrame(even), reference) / 4.0;
  }
  std::printf("mean spp %.1f: RMSE adaptive %.5f, even %.5f\n", adaptiveSamples / (24.0 * 24.0), adaptiveError,
              evenError);
  EXPECT_LT(adaptiveError, 0.7 * evenError);
}

}  // namespace adaptive_sampling_test
}  // namespace lacrima
