// Perlin's gradient noise (gradient_noise.hpp): lattice zeros, range, smoothness, statistics.
#include "lacrima/base/gradient_noise.hpp"

#include "lacrima/base/hash.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lacrima {
namespace gradient_noise_test {

Vec3 randomPoint(std::mt19937& rng, float extent) {
  std::uniform_real_distribution<float> u(-extent, extent);
  return Vec3(u(rng), u(rng), u(rng));
}

TEST(GradientNoise, IsZeroAtEveryLatticePoint) {
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j)
      for (int k = -3; k <= 3; ++k) EXPECT_EQ(gradientNoise(Vec3(float(i), float(j), float(k)), 7), 0.0f);
}

TEST(GradientNoise, IsAPureFunctionOfPointAndSeed) {
  const Vec3 p(0.3f, -1.7f, 2.45f);
  EXPECT_EQ(gradientNoise(p, 1), gradientNoise(p, 1));
  int differing = 0;
  std::mt19937 rng(3);
  for (int n = 0; n < 100; ++n) {
    const Vec3 q = randomPoint(rng, 10.0f);
    differing += gradientNoise(q, 1) != gradientNoise(q, 2);
  }
  EXPECT_GT(differing, 90);  // another seed, another field
}

TEST(GradientNoise, StaysInRangeWithZeroMeanAndAUsefulSpread) {
  std::mt19937 rng(5);
  double sum = 0.0, sum2 = 0.0;
  float lowest = 1.0f, highest = -1.0f;
  const int count = 200000;
  for (int n = 0; n < count; ++n) {
    const float v = gradientNoise(randomPoint(rng, 50.0f), 11);
    lowest = std::min(lowest, v);
    highest = std::max(highest, v);
    sum += v;
    sum2 += double(v) * v;
  }
  const double mean = sum / count, deviation = std::sqrt(sum2 / count - mean * mean);
  EXPECT_GE(lowest, -1.0f);
  EXPECT_LE(highest, 1.0f);
  EXPECT_NEAR(mean, 0.0, 0.01);
  // Perlin noise with edge gradients has a standard deviation near 0.2-0.3; a broken blend
  // (all zero, or hash collisions making it constant) would not.
  EXPECT_GT(deviation, 0.15);
  EXPECT_LT(deviation, 0.4);
  EXPECT_GT(highest - lowest, 1.0f);
}

TEST(GradientNoise, IsContinuousAcrossCellFaces) {
  // The gradient is bounded (each ramp's slope is at most |g| = sqrt 2, the fade's at most 15/8),
  // so a step of 1e-3 changes the value by well under 1e-2, also across integer faces.
  std::mt19937 rng(9);
  for (int n = 0; n < 20000; ++n) {
    Vec3 p = randomPoint(rng, 20.0f);
    p.x() = std::round(p.x()) - 5e-4f;  // straddle a cell face
    const Vec3 q = p + Vec3(1e-3f, 0.0f, 0.0f);
    EXPECT_LT(std::abs(gradientNoise(p, 4) - gradientNoise(q, 4)), 1e-2f) << p.transpose();
  }
}

TEST(GradientNoise, DecorrelatesBeyondOneCell) {
  std::mt19937 rng(13);
  double near = 0.0, far = 0.0, variance = 0.0;
  const int count = 50000;
  for (int n = 0; n < count; ++n) {
    const Vec3 p = randomPoint(rng, 100.0f);
    const double v = gradientNoise(p, 21);
    variance += v * v;
    near += v * gradientNoise(p + Vec3(0.1f, 0.0f, 0.0f), 21);
    far += v * gradientNoise(p + Vec3(3.0f, 0.0f, 0.0f), 21);
  }
  EXPECT_GT(near / variance, 0.8);           // close points alike
  EXPECT_LT(std::abs(far / variance), 0.05);  // points cells apart unrelated
}

TEST(FractalGradientNoise, OneOctaveIsTheNoiseAndMoreOctavesAddDetailWithinRange) {
  std::mt19937 rng(17);
  // Small-step change relative to the field's spread: finer octaves raise it (each octave has the
  // same slope, while the normalisation shrinks the spread).
  double stepOne = 0.0, stepThree = 0.0, squareOne = 0.0, squareThree = 0.0;
  const int count = 20000;
  for (int n = 0; n < count; ++n) {
    const Vec3 p = randomPoint(rng, 10.0f), q = p + Vec3(0.0f, 0.05f, 0.0f);
    const float one = fractalGradientNoise(p, 1, 3), three = fractalGradientNoise(p, 3, 3);
    EXPECT_EQ(one, gradientNoise(p, hashCombine(3, 0)));
    EXPECT_GE(three, -1.0f);
    EXPECT_LE(three, 1.0f);
    stepOne += std::abs(fractalGradientNoise(q, 1, 3) - one);
    stepThree += std::abs(fractalGradientNoise(q, 3, 3) - three);
    squareOne += double(one) * one;
    squareThree += double(three) * three;
  }
  const double relativeOne = stepOne / std::sqrt(squareOne), relativeThree = stepThree / std::sqrt(squareThree);
  EXPECT_GT(relativeThree, 1.3 * relativeOne);
}

}  // namespace gradient_noise_test
}  // namespace lacrima
