// Environment map: direction convention, bilinear lookup, rotation, sampling consistent with
// pdf()/radiance() (pdf > 0 wherever the radiance is), unbiased Monte Carlo integral, chi-square
// test of sample() against pdf(), loading and errors.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lacrima/base/error.hpp"
#include "lacrima/renderer/sampler.hpp"
#include "lacrima/renderer/environment.hpp"

namespace lacrima {
namespace environment_test {

namespace fs = std::filesystem;

constexpr int kW = 64, kH = 32;
constexpr double kPiD = 3.14159265358979323846;

// 64x32: a smooth gradient, a bright 3x2 "sun", and a black band (zero luminance) so that the
// pdf has zeros and a large dynamic range.
std::vector<float> syntheticTexels() {
  std::vector<float> rgb(std::size_t(kW) * kH * 3);
  for (int j = 0; j < kH; ++j) {
    for (int i = 0; i < kW; ++i) {
      float* p = &rgb[(std::size_t(j) * kW + i) * 3];
      p[0] = 0.2f + 0.8f * float(i) / kW;
      p[1] = 0.5f + 0.5f * float(j) / kH;
      p[2] = 0.1f + 0.05f * float((i * 7 + j * 3) % 11);
      if (j >= 20 && j < 23) p[0] = p[1] = p[2] = 0.0f;  // black band below the horizon
      if (j >= 9 && j < 11 && i >= 40 && i < 43) {       // the sun
        p[0] = 500.0f;
        p[1] = 450.0f;
        p[2] = 400.0f;
      }
    }
  }
  return rgb;
}

EnvironmentMap syntheticMap(float intensity = 1.0f, float rotation = 0.0f) {
  return EnvironmentMap(kW, kH, syntheticTexels(), intensity, rotation);
}

// Direction through the centre of texel (i, j) of a w x h map, with the documented convention
// (independent of the implementation): theta from +Y, u = 0.5 -> -Z, u = 0.75 -> +X.
Vec3 texelCentre(int i, int j, int w, int h) {
  const double theta = kPiD * (j + 0.5) / h, phi = 2.0 * kPiD * (i + 0.5) / w;
  return Vec3(float(-std::sin(theta) * std::sin(phi)), float(std::cos(theta)), float(std::sin(theta) * std::cos(phi)));
}

Color texel(const std::vector<float>& rgb, int w, int i, int j) {
  const float* p = &rgb[(std::size_t(j) * w + i) * 3];
  return Color(p[0], p[1], p[2]);
}

// Integral of the map's (bilinear) radiance over the sphere: midpoint rule with sub x sub points
// per texel and the exact solid angle of each point's cell.
Eigen::Array3d radianceIntegral(const EnvironmentMap& map, int sub) {
  const int nTheta = map.height() * sub, nPhi = map.width() * sub;
  Eigen::Array3d sum = Eigen::Array3d::Zero();
  for (int a = 0; a < nTheta; ++a) {
    const double t0 = kPiD * a / nTheta, t1 = kPiD * (a + 1) / nTheta, tm = 0.5 * (t0 + t1);
    const double solidAngle = 2.0 * kPiD / nPhi * (std::cos(t0) - std::cos(t1));
    for (int b = 0; b < nPhi; ++b) {
      const double phi = 2.0 * kPiD * (b + 0.5) / nPhi;
      const Vec3 d(float(-std::sin(tm) * std::sin(phi)), float(std::cos(tm)), float(std::sin(tm) * std::cos(phi)));
      sum += map.radiance(d).cast<double>() * solidAngle;
    }
  }
  return sum;
}

// A float colour equal to `expected` up to rounding of the bilinear weights (a direction's float
// rounding moves them by about 1e-6), which blend in neighbours as bright as `scale`.
void expectColorNear(const Color& actual, const Color& expected, const std::string& where, float scale = 1.0f) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(actual[c], expected[c], 1e-5f * std::max({1.0f, expected[c], scale})) << where;
}

// The brightest channel among texel (i, j) and its 8 neighbours (wrapped and clamped).
float neighbourhoodMax(const std::vector<float>& rgb, int w, int h, int i, int j) {
  float m = 0.0f;
  for (int dj = -1; dj <= 1; ++dj)
    for (int di = -1; di <= 1; ++di)
      m = std::max(m, texel(rgb, w, (i + di + w) % w, std::clamp(j + dj, 0, h - 1)).maxCoeff());
  return m;
}

Vec2 randomPair(uint64_t seed, int index) { return PixelSampler(seed, 0, index, 0, 0).get2D(); }

TEST(EnvironmentMap, DirectionConvention) {
  // One bright texel per axis direction; each must be seen in its documented direction. Texel
  // centres are where the bilinear lookup returns the texel itself.
  std::vector<float> rgb(std::size_t(kW) * kH * 3, 0.0f);
  const auto set = [&](int i, int j, float value) { rgb[(std::size_t(j) * kW + i) * 3 + 1] = value; };
  set(kW / 2, kH / 2, 1.0f);          // u = 0.5 on the equator: -Z
  set(3 * kW / 4, kH / 2, 2.0f);      // u = 0.75: +X
  set(kW / 4, kH / 2, 3.0f);          // u = 0.25: -X
  set(0, kH / 2, 4.0f);               // u = 0: +Z
  for (int i = 0; i < kW; ++i) set(i, 0, 5.0f);       // top row: +Y
  for (int i = 0; i < kW; ++i) set(i, kH - 1, 6.0f);  // bottom row: -Y
  const EnvironmentMap map(kW, kH, rgb, 1.0f, 0.0f);
  // The axes themselves are texel corners: look at each texel's centre, half a texel off the axis
  // (texelCentre() follows the documented convention, not the implementation).
  const auto near = [](const Vec3& d, const Vec3& axis) { return d.dot(axis) > 0.99f; };
  ASSERT_TRUE(near(texelCentre(kW / 2, kH / 2, kW, kH), Vec3(0, 0, -1)));
  ASSERT_TRUE(near(texelCentre(3 * kW / 4, kH / 2, kW, kH), Vec3(1, 0, 0)));
  ASSERT_TRUE(near(texelCentre(kW / 4, kH / 2, kW, kH), Vec3(-1, 0, 0)));
  ASSERT_TRUE(near(texelCentre(0, kH / 2, kW, kH), Vec3(0, 0, 1)));
  EXPECT_NEAR(map.radiance(texelCentre(kW / 2, kH / 2, kW, kH)).y(), 1.0f, 1e-4f);
  EXPECT_NEAR(map.radiance(texelCentre(3 * kW / 4, kH / 2, kW, kH)).y(), 2.0f, 1e-4f);
  EXPECT_NEAR(map.radiance(texelCentre(kW / 4, kH / 2, kW, kH)).y(), 3.0f, 1e-4f);
  EXPECT_NEAR(map.radiance(texelCentre(0, kH / 2, kW, kH)).y(), 4.0f, 1e-4f);
  // Above the first row's centres (below the last row's) the row itself: clamped, not wrapped.
  EXPECT_EQ(map.radiance(Vec3(0.01f, 1, 0)).y(), 5.0f);
  EXPECT_EQ(map.radiance(Vec3(0.01f, -1, 0)).y(), 6.0f);
}

// Direction with map coordinates (u, v) for an unrotated map (the documented convention).
Vec3 uvDirection(double u, double v) {
  const double theta = kPiD * v, phi = 2.0 * kPiD * u;
  return Vec3(float(-std::sin(theta) * std::sin(phi)), float(std::cos(theta)), float(std::sin(theta) * std::cos(phi)));
}

TEST(EnvironmentMap, LookupIsBilinearBetweenTexelCentres) {
  // A 4x2 map, texel (i, j) = (10 i + 100 j + 1) in red; green 1 everywhere.
  constexpr int w = 4, h = 2;
  std::vector<float> rgb(w * h * 3);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      rgb[(j * w + i) * 3 + 0] = float(10 * i + 100 * j + 1);
      rgb[(j * w + i) * 3 + 1] = 1.0f;
    }
  const EnvironmentMap map(w, h, rgb, 2.0f, 0.0f);
  const auto red = [&](double u, double v) { return map.radiance(uvDirection(u, v)).x() / 2.0f; };
  const auto green = [&](double u, double v) { return map.radiance(uvDirection(u, v)).y() / 2.0f; };
  // Centres are the texels.
  EXPECT_NEAR(red(1.5 / w, 0.5 / h), 11.0f, 1e-4f);
  EXPECT_NEAR(red(2.5 / w, 1.5 / h), 121.0f, 1e-4f);
  // Halfway and a quarter of the way between two centres of a row.
  EXPECT_NEAR(red(2.0 / w, 0.5 / h), 16.0f, 1e-4f);
  EXPECT_NEAR(red(1.75 / w, 0.5 / h), 13.5f, 1e-4f);
  // Between the rows (the equator) and in the middle of four centres.
  EXPECT_NEAR(red(1.5 / w, 0.5), 61.0f, 1e-3f);
  EXPECT_NEAR(red(2.0 / w, 0.75 / h), 16.0f + 0.25f * 100.0f, 1e-3f);
  // Across the seam: halfway between the last column (31) and the first (1) of row 0, and
  // 0.004 of a texel before it.
  EXPECT_NEAR(red(0.0, 0.5 / h), 16.0f, 1e-4f);
  EXPECT_NEAR(red(0.999, 0.5 / h), 16.0f + 30.0f * 0.004f, 1e-3f);
  // Clamped in latitude: near the poles, the first and last rows only.
  EXPECT_NEAR(red(1.5 / w, 0.1 / h), 11.0f, 1e-4f);
  EXPECT_NEAR(red(1.5 / w, 1.0 - 0.1 / h), 111.0f, 1e-4f);
  // A constant channel stays exactly constant.
  for (int k = 0; k < 100; ++k) EXPECT_NEAR(green(0.013 * k, 0.0099 * k), 1.0f, 1e-6f) << k;
}

TEST(EnvironmentMap, PdfIsPositiveWhereverTheBilinearRadianceIs) {
  // One lit texel in a black map: its light spreads to the neighbours' half texels, and the
  // sampling density must cover all of that (MIS needs pdf > 0 wherever the radiance is).
  constexpr int w = 16, h = 8;
  std::vector<float> rgb(w * h * 3, 0.0f);
  rgb[(3 * w + 15) * 3 + 2] = 1.0f;  // blue only (a small luminance), next to the seam
  const EnvironmentMap map(w, h, rgb, 1.0f, 0.0f);
  int lit = 0, dark = 0;
  for (int a = 0; a < 8 * h; ++a) {
    for (int b = 0; b < 8 * w; ++b) {
      const Vec3 d = uvDirection((b + 0.5) / (8 * w), (a + 0.5) / (8 * h));
      const bool positive = map.radiance(d).maxCoeff() > 0.0f;
      lit += positive ? 1 : 0;
      if (positive) {
        EXPECT_GT(map.pdf(d), 0.0f) << a << "," << b;
      } else {
        dark += map.pdf(d) == 0.0f ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(lit, 16 * 16) << "the texel's bilinear footprint is 2 x 2 texels";
  EXPECT_GT(dark, 8 * h * 8 * w - 16 * 16 - 1) << "pdf > 0 only where the radiance is";
  for (int k = 0; k < 2000; ++k) {
    const EnvironmentSample s = map.sample(randomPair(23, k));
    ASSERT_GT(s.radiance.z(), 0.0f) << k;
    ASSERT_EQ(s.pdf, map.pdf(s.direction)) << k;
  }
}

TEST(EnvironmentMap, SamplesAgreeWithPdfAndRadiance) {
  const std::vector<float> rgb = syntheticTexels();
  const float intensity = 2.5f;
  const EnvironmentMap map(kW, kH, rgb, intensity, 0.4f);
  int inSun = 0;
  for (int k = 0; k < 20000; ++k) {
    const EnvironmentSample s = map.sample(randomPair(11, k));
    ASSERT_NEAR(s.direction.norm(), 1.0f, 1e-5f);
    ASSERT_GT(s.pdf, 0.0f) << "sample " << k;
    ASSERT_EQ(s.pdf, map.pdf(s.direction)) << "sample " << k;
    ASSERT_TRUE((s.radiance == map.radiance(s.direction)).all()) << "sample " << k;
    ASSERT_GT(s.radiance.maxCoeff(), 0.0f) << "a black texel was sampled";
    inSun += s.radiance.x() > 100.0f ? 1 : 0;
  }
  // The sun holds most of the luminance; importance sampling must go there most of the time.
  EXPECT_GT(inSun, 20000 / 2);

  // At texel centres the lookup is the texel; the pdf is positive wherever the radiance is, and
  // zero (no floor) inside the black band, whose middle row has black neighbours above and below.
  const EnvironmentMap unrotated = syntheticMap(intensity);
  for (int j = 0; j < kH; ++j) {
    for (int i = 0; i < kW; ++i) {
      const Vec3 d = texelCentre(i, j, kW, kH);
      if (unrotated.radiance(d).maxCoeff() > 0.0f) {
        EXPECT_GT(unrotated.pdf(d), 0.0f) << i << "," << j;
      }
      if (j == 21) {
        EXPECT_EQ(unrotated.pdf(d), 0.0f) << i << "," << j;
      }
      expectColorNear(unrotated.radiance(d), texel(rgb, kW, i, j) * intensity,
                      std::to_string(i) + "," + std::to_string(j), neighbourhoodMax(rgb, kW, kH, i, j) * intensity);
    }
  }
}

// Estimates the integral of radiance over the sphere as the mean of radiance / pdf and checks it
// against a fine quadrature of radiance(), within 5 standard errors.
void expectUnbiasedIntegral(const EnvironmentMap& map, const Eigen::Array3d& exact, int n, uint64_t seed) {
  Eigen::Array3d sum = Eigen::Array3d::Zero(), sumSq = Eigen::Array3d::Zero();
  for (int k = 0; k < n; ++k) {
    const EnvironmentSample s = map.sample(randomPair(seed, k));
    if (s.pdf == 0.0f) continue;  // contributes 0, as in the integrator
    const Eigen::Array3d f = s.radiance.cast<double>() / double(s.pdf);
    sum += f;
    sumSq += f * f;
  }
  const Eigen::Array3d mean = sum / n;
  const Eigen::Array3d stdError = ((sumSq / n - mean * mean).max(0.0) / n).sqrt();
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(mean[c], exact[c], 5.0 * stdError[c] + 1e-4 * exact[c])
        << "channel " << c << ", standard error " << stdError[c];
  }
}

TEST(EnvironmentMap, MonteCarloIntegralMatchesExactIntegral) {
  const std::vector<float> rgb = syntheticTexels();
  const float intensity = 0.7f;
  const EnvironmentMap map(kW, kH, rgb, intensity, 0.0f);
  const Eigen::Array3d exact = radianceIntegral(map, 16);
  expectUnbiasedIntegral(map, exact, 100000, 3);
  expectUnbiasedIntegral(EnvironmentMap(kW, kH, rgb, intensity, 2.0f), exact, 100000, 4);  // rotation keeps it
}

// Upper tail of the chi-square distribution, Wilson-Hilferty approximation (good for dof >~ 30).
double chiSquareZScore(double chi2, double dof) {
  const double a = 2.0 / (9.0 * dof);
  return (std::cbrt(chi2 / dof) - (1.0 - a)) / std::sqrt(a);
}

TEST(EnvironmentMap, ChiSquareOfSamplesAgainstPdf) {
  // Bins in world (theta, phi); expected counts from pdf() integrated over each bin with a fine
  // midpoint rule (4x4 points per texel, exact solid angle per cell). The rotation is a whole
  // number of texels so the integration cells never straddle a texel edge.
  constexpr int kThetaBins = 16, kPhiBins = 32, kSub = 4;
  const float rotation = float(2.0 * kPiD * 5.0 / kW);
  const EnvironmentMap map = syntheticMap(1.0f, rotation);
  std::vector<double> expected(kThetaBins * kPhiBins, 0.0);
  const int nTheta = kH * kSub, nPhi = kW * kSub;
  for (int a = 0; a < nTheta; ++a) {
    const double t0 = kPiD * a / nTheta, t1 = kPiD * (a + 1) / nTheta, tm = 0.5 * (t0 + t1);
    for (int b = 0; b < nPhi; ++b) {
      const double phi = 2.0 * kPiD * (b + 0.5) / nPhi;
      const Vec3 d(float(-std::sin(tm) * std::sin(phi)), float(std::cos(tm)), float(std::sin(tm) * std::cos(phi)));
      const double solidAngle = 2.0 * kPiD / nPhi * (std::cos(t0) - std::cos(t1));
      expected[(a * kThetaBins / nTheta) * kPhiBins + b * kPhiBins / nPhi] += map.pdf(d) * solidAngle;
    }
  }
  double totalProbability = 0.0;
  for (double e : expected) totalProbability += e;
  EXPECT_NEAR(totalProbability, 1.0, 1e-3) << "pdf() does not integrate to 1";

  constexpr int kSamples = 400000;
  std::vector<double> observed(expected.size(), 0.0);
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 d = map.sample(randomPair(29, k)).direction;
    const double theta = std::acos(std::clamp(double(d.y()), -1.0, 1.0));
    double phi = std::atan2(-double(d.x()), double(d.z()));
    if (phi < 0.0) phi += 2.0 * kPiD;
    const int a = std::min(int(theta / kPiD * kThetaBins), kThetaBins - 1);
    const int b = std::min(int(phi / (2.0 * kPiD) * kPhiBins), kPhiBins - 1);
    observed[a * kPhiBins + b] += 1.0;
  }

  // Pool bins with fewer than 5 expected samples (Nori's chi2test); zero-probability bins must
  // receive no samples at all.
  double chi2 = 0.0, pooledExpected = 0.0, pooledObserved = 0.0;
  int dof = -1;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const double e = expected[k] * kSamples;
    if (expected[k] == 0.0) {
      EXPECT_EQ(observed[k], 0.0) << "samples in a bin where pdf() is 0: " << k;
      continue;
    }
    if (e < 5.0) {
      pooledExpected += e;
      pooledObserved += observed[k];
      continue;
    }
    chi2 += (observed[k] - e) * (observed[k] - e) / e;
    ++dof;
  }
  if (pooledExpected > 0.0) {
    chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
    ++dof;
  }
  ASSERT_GT(dof, 100);
  // z = 3.7 is a p-value of about 1e-4; the samples are deterministic, so this never flickers.
  EXPECT_LT(chiSquareZScore(chi2, dof), 3.7) << "chi2 " << chi2 << " for " << dof << " degrees of freedom";
}

TEST(EnvironmentMap, SamplesAreUniformWithinTheirCells) {
  // The density is constant in (u, v) inside a sampling cell, the square between four texel
  // centres, so the position of a sample inside its cell must be uniform: chi-square over an 8x8
  // grid of in-cell positions (away from the half-height cells at the poles).
  const EnvironmentMap map = syntheticMap();
  constexpr int kGrid = 8, kSamples = 128000;
  std::vector<double> observed(kGrid * kGrid, 0.0);
  int counted = 0;
  for (int k = 0; k < kSamples; ++k) {
    const Vec3 d = map.sample(randomPair(31, k)).direction;
    double u = std::atan2(-double(d.x()), double(d.z())) / (2.0 * kPiD);
    u -= std::floor(u);
    const double v = std::acos(std::clamp(double(d.y()), -1.0, 1.0)) / kPiD;
    const double x = u * kW - 0.5, y = v * kH - 0.5;
    if (y < 0.0 || y >= kH - 1) continue;
    const double fu = x - std::floor(x), fv = y - std::floor(y);
    observed[std::min(int(fv * kGrid), kGrid - 1) * kGrid + std::min(int(fu * kGrid), kGrid - 1)] += 1.0;
    ++counted;
  }
  ASSERT_GT(counted, kSamples / 2);
  const double e = double(counted) / (kGrid * kGrid);
  double chi2 = 0.0;
  for (double o : observed) chi2 += (o - e) * (o - e) / e;
  EXPECT_LT(chiSquareZScore(chi2, kGrid * kGrid - 1), 3.7) << "chi2 " << chi2;
}

TEST(EnvironmentMap, RotationTurnsTheMapAboutY) {
  const std::vector<float> rgb = syntheticTexels();
  const float r = 0.7f;
  const EnvironmentMap plain(kW, kH, rgb, 1.0f, 0.0f), rotated(kW, kH, rgb, 1.0f, r);
  const Mat3 rotate = Eigen::AngleAxisf(r, Vec3::UnitY()).toRotationMatrix();
  int differing = 0;
  for (int j = 0; j < kH; ++j) {
    for (int i = 0; i < kW; ++i) {
      const Vec3 d = texelCentre(i, j, kW, kH);
      expectColorNear(rotated.radiance(rotate * d), plain.radiance(d), std::to_string(i) + "," + std::to_string(j),
                      neighbourhoodMax(rgb, kW, kH, i, j));
      // The pdf is constant per sampling cell, between texel centres: compare at cell centres.
      const Vec3 cellCentre = uvDirection((i + 1.0) / kW, (j + 1.0) / kH);
      EXPECT_NEAR(rotated.pdf(rotate * cellCentre), plain.pdf(cellCentre), 1e-4f * plain.pdf(cellCentre))
          << i << "," << j;
      differing += (rotated.radiance(d) != plain.radiance(d)).any() ? 1 : 0;
    }
  }
  EXPECT_GT(differing, kW * kH / 2) << "the rotation had no effect";
}

TEST(EnvironmentMap, InvalidTexelsAreClampedAndCounted) {
  std::vector<float> rgb = syntheticTexels();
  rgb[0] = std::nanf("");
  rgb[3 * 5 + 1] = -1.0f;
  rgb[3 * 9 + 2] = INFINITY;
  rgb[3 * 9 + 1] = -INFINITY;  // same texel as the previous one: counted once
  const EnvironmentMap map(kW, kH, rgb, 1.0f, 0.0f);
  EXPECT_EQ(map.clampedTexelCount(), 3u);
  // At the clamped texels' centres, 0 up to the rounding of the bilinear weights of neighbours.
  EXPECT_NEAR(map.radiance(texelCentre(0, 0, kW, kH)).x(), 0.0f, 1e-5f);
  EXPECT_NEAR(map.radiance(texelCentre(5, 0, kW, kH)).y(), 0.0f, 1e-5f);
  EXPECT_TRUE(std::isfinite(map.pdf(texelCentre(9, 0, kW, kH))));
  for (int k = 0; k < 1000; ++k) ASSERT_TRUE(isFinite(map.sample(randomPair(5, k)).radiance));
  // A NaN direction (a bug upstream) must not crash the lookup.
  const Vec3 nan(std::nanf(""), 0.0f, 1.0f);
  EXPECT_TRUE(isFinite(map.radiance(nan)));
  EXPECT_EQ(map.pdf(nan), 0.0f);
}

TEST(EnvironmentMap, BlackMapStillHasAValidDistribution) {
  // No luminance to follow: each texel is chosen by its solid angle. The density must still be
  // right: the mean of 1 / pdf estimates the area of the sphere.
  const EnvironmentMap map(8, 4, std::vector<float>(8 * 4 * 3, 0.0f), 1.0f, 0.0f);
  constexpr int n = 200000;
  double sum = 0.0, sumSq = 0.0;
  for (int k = 0; k < n; ++k) {
    const EnvironmentSample s = map.sample(randomPair(7, k));
    ASSERT_GT(s.pdf, 0.0f);
    ASSERT_EQ(s.pdf, map.pdf(s.direction));
    ASSERT_EQ(s.radiance.maxCoeff(), 0.0f);
    sum += 1.0 / s.pdf;
    sumSq += 1.0 / (double(s.pdf) * s.pdf);
  }
  const double mean = sum / n, stdError = std::sqrt((sumSq / n - mean * mean) / n);
  EXPECT_NEAR(mean, 4.0 * kPiD, 5.0 * stdError);
  // Per sampling cell (between texel centres; half-height caps at the poles), the probability is
  // its solid angle over 4 pi, spread uniformly in (u, v). Cell row r spans v from the centre of
  // texel row r - 1 to that of row r; at the centre of a cell row:
  for (int r = 1; r < 4; ++r) {
    const double v0 = (r - 0.5) / 4, v1 = (r + 0.5) / 4, vm = 0.5 * (v0 + v1);
    const double probability = 2.0 * kPiD / 8 * (std::cos(kPiD * v0) - std::cos(kPiD * v1)) / (4.0 * kPiD);
    const double expected = probability * 8 / (v1 - v0) / (2.0 * kPiD * kPiD * std::sin(kPiD * vm));
    for (int c = 0; c < 8; ++c) {
      const Vec3 d = uvDirection((c + 1.0) / 8, vm);
      EXPECT_NEAR(map.pdf(d), expected, 1e-5 * expected) << c << "," << r;
    }
  }
}

const fs::path kStudio = fs::path(LACRIMA_SOURCE_DIR) / "scenes/assets/hdri/studio.exr";

TEST(EnvironmentMap, LoadsARealHdri) {
  ASSERT_TRUE(fs::exists(kStudio)) << kStudio;
  const EnvironmentMap map = EnvironmentMap::load(kStudio, 1.0f, 0.0f);
  ASSERT_EQ(map.width(), 1024);
  ASSERT_EQ(map.height(), 512);
  // studio.exr has a few tiny negative texels (DWA compression): they are clamped and counted.
  EXPECT_GT(map.clampedTexelCount(), 0u);
  EXPECT_LT(map.clampedTexelCount(), 1000u);

  // Orientation and values match the file read independently (row 0 = +Y).
  auto in = OIIO::ImageInput::open(kStudio.string());
  ASSERT_TRUE(in);
  std::vector<float> rgb(std::size_t(1024) * 512 * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, rgb.data()));
  for (float& x : rgb) x = std::max(x, 0.0f);
  for (int j = 3; j < 512; j += 61) {
    for (int i = 5; i < 1024; i += 97) {
      // Texel centres of a 1024-wide map are 6e-3 rad apart: a direction's float rounding moves
      // the bilinear weights by about 1e-4 of the difference to the neighbours.
      float neighbours = 0.0f;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) neighbours = std::max(neighbours, texel(rgb, 1024, i + di, j + dj).maxCoeff());
      const Color expected = texel(rgb, 1024, i, j), actual = map.radiance(texelCentre(i, j, 1024, 512));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], 1e-3f * neighbours + 1e-6f) << i << "," << j;
    }
  }
  expectUnbiasedIntegral(map, radianceIntegral(map, 2), 100000, 13);
}

TEST(EnvironmentMap, MissingFileIsAnInputErrorNamingIt) {
  const fs::path missing = fs::path(LACRIMA_TEST_OUTPUT_DIR) / "no_such_map.exr";
  try {
    EnvironmentMap::load(missing, 1.0f, 0.0f);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
}

TEST(EnvironmentMap, GarbageFileIsAnInputErrorNamingIt) {
  fs::create_directories(LACRIMA_TEST_OUTPUT_DIR);
  const fs::path garbage = fs::path(LACRIMA_TEST_OUTPUT_DIR) / "garbage_map.exr";
  {
    std::ofstream out(garbage, std::ios::binary);
    out << "this is not an OpenEXR file\n" << std::string(1000, '\x7f');
  }
  // A truncated real EXR: the header may parse, the pixels cannot.
  const fs::path truncated = fs::path(LACRIMA_TEST_OUTPUT_DIR) / "truncated_map.exr";
  fs::copy_file(kStudio, truncated, fs::copy_options::overwrite_existing);
  fs::resize_file(truncated, fs::file_size(truncated) / 3);
  for (const fs::path& bad : {garbage, truncated}) {
    try {
      EnvironmentMap::load(bad, 1.0f, 0.0f);
      ADD_FAILURE() << "no exception for " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
    }
  }
}

}  // namespace environment_test
}  // namespace lacrima
