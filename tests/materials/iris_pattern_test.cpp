// The procedural iris (iris_pattern.hpp) over the iris's disc uvs (eye.hpp): its mean, its layers
// where the anatomy puts them, its determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "lacrima/face/eye.hpp"
#include "lacrima/base/hash.hpp"
#include "lacrima/materials/iris_pattern.hpp"

namespace lacrima {
namespace iris_pattern_test {

// The uv of the point `across` of the way from the pupil margin (0) to the root (1), at angle phi.
Vec2 irisUv(float across, float phi) {
  const float radius = kIrisUvPupilRadius + (1.0f - kIrisUvPupilRadius) * across;
  return {0.5f + 0.5f * radius * std::cos(phi), 0.5f - 0.5f * radius * std::sin(phi)};
}

// The mean factor (all channels) on the circle `across`, over 2048 angles.
float ringMean(const IrisPattern& pattern, float across) {
  constexpr int kAngles = 2048;
  float sum = 0.0f;
  for (int i = 0; i < kAngles; ++i) sum += pattern.factorAt(irisUv(across, 2.0f * kPi * (float(i) + 0.5f) / kAngles)).mean();
  return sum / kAngles;
}

TEST(IrisPattern, TheFactorsAverageOneOverTheIrisSoTheAlbedoIsItsMeanColour) {
  // Points uniform over the annulus's area (independent of the constructor's polar grid).
  for (const uint64_t seed : {1u, 7u}) {
    const IrisPattern pattern(seed);
    constexpr int kPoints = 200000;
    Color sum(0.0f, 0.0f, 0.0f);
    for (int i = 0; i < kPoints; ++i) {
      const float u1 = uint64ToUnitFloat(hashCombine(42, uint64_t(2 * i)));
      const float u2 = uint64ToUnitFloat(hashCombine(42, uint64_t(2 * i + 1)));
      const float inner = kIrisUvPupilRadius * kIrisUvPupilRadius;
      const float radius = std::sqrt(inner + u1 * (1.0f - inner));
      const float across = (radius - kIrisUvPupilRadius) / (1.0f - kIrisUvPupilRadius);
      sum += pattern.factorAt(irisUv(across, 2.0f * kPi * u2));
    }
    const Color mean = sum / float(kPoints);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], 1.0f, 0.01f) << "seed " << seed << ", channel " << c;
  }
}

TEST(IrisPattern, FibresRunRadially) {
  // Between 0.6 and 0.8 of the way to the root (past the crypts, before the limbal ring), the
  // factor changes much more from one point to the next around the iris than along its radius.
  const IrisPattern pattern(1);
  constexpr float kStep = 0.004f;  // uv units, both ways
  double around = 0.0, across = 0.0;
  for (int i = 0; i < 4096; ++i) {
    const float phi = 2.0f * kPi * float(i) / 4096.0f;
    const float x = 0.6f + 0.2f * float(i % 17) / 16.0f;
    const float radius = 0.5f * (kIrisUvPupilRadius + (1.0f - kIrisUvPupilRadius) * x);
    const Color here = pattern.factorAt(irisUv(x, phi));
    around += std::abs((pattern.factorAt(irisUv(x, phi + kStep / radius)) - here).mean());
    across += std::abs((pattern.factorAt(irisUv(x + kStep / (0.5f * (1.0f - kIrisUvPupilRadius)), phi)) - here).mean());
  }
  std::printf("[ info     ] mean change over 0.004 uv: around %.4f, across %.4f\n", around / 4096, across / 4096);
  EXPECT_GT(around, 3.0 * across);
}

TEST(IrisPattern, TheRuffAndTheLimbalRingAreDarkTheCollaretteLightAndWarm) {
  const IrisPattern pattern(1);
  const float stroma = ringMean(pattern, 0.65f);
  EXPECT_LT(ringMean(pattern, 0.005f), 0.5f * stroma);  // pupillary ruff
  EXPECT_LT(ringMean(pattern, 0.995f), 0.5f * stroma);  // limbal ring
  // The collarette wanders between 0.25 and 0.35 of the way: its brightest point on each radius.
  float brightest = 0.0f, redOverBlue = 0.0f;
  constexpr int kAngles = 512;
  for (int i = 0; i < kAngles; ++i) {
    const float phi = 2.0f * kPi * float(i) / kAngles;
    Color best(0.0f, 0.0f, 0.0f);
    for (float x = 0.2f; x <= 0.4f; x += 0.005f) {
      const Color c = pattern.factorAt(irisUv(x, phi));
      if (c.mean() > best.mean()) best = c;
    }
    brightest += best.mean() / kAngles;
    redOverBlue += best[0] / best[2] / kAngles;
  }
  EXPECT_GT(brightest, 1.3f * stroma);
  const Color mid = pattern.factorAt(irisUv(0.65f, 0.3f));
  EXPECT_GT(redOverBlue, 1.2f * mid[0] / mid[2]);
}

TEST(IrisPattern, TheSameSeedGivesTheSameIrisAnotherSeedAnother) {
  const IrisPattern a(3), b(3), c(4);
  int differ = 0;
  for (int i = 0; i < 1000; ++i) {
    const Vec2 uv = irisUv(float(i % 50) / 49.0f, 0.37f * float(i));
    EXPECT_TRUE((a.factorAt(uv) == b.factorAt(uv)).all());
    if ((a.factorAt(uv) - c.factorAt(uv)).abs().maxCoeff() > 0.05f) ++differ;
  }
  EXPECT_GT(differ, 500);
}

TEST(IrisPattern, InsideThePupilAndBeyondTheRootTheEdgesHold) {
  const IrisPattern pattern(1);
  for (const float phi : {0.3f, 2.0f, 4.5f}) {
    // The same angle up to atan2's rounding at another radius.
    EXPECT_LT((pattern.factorAt(irisUv(-0.5f, phi)) - pattern.factorAt(irisUv(0.0f, phi))).abs().maxCoeff(), 1e-3f);
    EXPECT_LT((pattern.factorAt(irisUv(1.3f, phi)) - pattern.factorAt(irisUv(1.0f, phi))).abs().maxCoeff(), 1e-3f);
  }
  const Color centre = pattern.factorAt(Vec2(0.5f, 0.5f));
  EXPECT_TRUE(centre.allFinite());
}

}  // namespace iris_pattern_test
}  // namespace lacrima
