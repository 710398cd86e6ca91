// FLIP and HDR-FLIP (tools/src/diff/flip.*), part by part: the colour pipeline against
// hand-computed and published sRGB values, the filters' normalisation and radii, the feature
// detectors on an edge and a dot, identical images, symmetry and monotonicity in the noise
// amplitude, the exposure range. The whole against NVIDIA's implementation:
// flip_conformance_test.cpp. See docs/diff.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numeric>

#include "diff/flip.hpp"

namespace lacrima::diff {
namespace flip_test {

double sumOf(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }
double meanOf(const std::vector<double>& v) { return sumOf(v) / double(v.size()); }

TEST(Flip, DefaultObserverIs67PixelsPerDegree) {
  // 0.7 m * 3840 px / 0.7 m * pi / 180 (FLIP paper, Section 4).
  EXPECT_NEAR(defaultPixelsPerDegree(), 67.0206, 1e-4);
  EXPECT_NEAR(pixelsPerDegree(1.0, 0.5, 1920.0), 1920.0 / 0.5 * M_PI / 180.0, 1e-9);
}

TEST(Flip, SrgbTransferFunctionRoundTrips) {
  EXPECT_NEAR(srgbToLinear({0.5, 0.5, 0.5})[0], 0.214041, 1e-6);   // ((0.5 + 0.055) / 1.055)^2.4
  EXPECT_NEAR(srgbToLinear({0.02, 0, 0})[0], 0.02 / 12.92, 1e-12);  // the linear toe
  EXPECT_NEAR(linearToSrgb(srgbToLinear({0.73, 0, 0}))[0], 0.73, 1e-12);
}

TEST(Flip, WhiteMapsToTheD65WhiteAndLStar100) {
  const Color white = linearRgbToXyz({1, 1, 1});
  EXPECT_NEAR(white[0], 0.950428545, 1e-9);
  EXPECT_NEAR(white[1], 1.0, 1e-9);
  EXPECT_NEAR(white[2], 1.088900371, 1e-9);
  const Color ycxcz = xyzToYCxCz(white), lab = xyzToLab(white);
  // The white is given to 9 digits, so chroma is 0 to about 500 * 1e-9.
  EXPECT_NEAR(ycxcz[0], 100.0, 1e-6);
  EXPECT_NEAR(ycxcz[1], 0.0, 1e-6);
  EXPECT_NEAR(lab[0], 100.0, 1e-6);
  EXPECT_NEAR(lab[2], 0.0, 1e-6);
}

TEST(Flip, ColourSpaceInversesRoundTrip) {
  const Color rgb = {0.2, 0.6, 0.9};
  const Color back = xyzToLinearRgb(yCxCzToXyz(xyzToYCxCz(linearRgbToXyz(rgb))));
  // The inverse matrix is given to 9 digits.
  for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(back[i], rgb[i], 1e-6);
}

TEST(Flip, LabOfPrimariesMatchesPublishedSrgbValues) {
  // CIE L*a*b* (D65) of the sRGB primaries, as tabulated for sRGB: green (87.74, -86.18, 83.18),
  // blue (32.30, 79.19, -107.86); 18% grey has L* = 116 * 0.18^(1/3) - 16 = 49.50.
  const Color green = xyzToLab(linearRgbToXyz({0, 1, 0})), blue = xyzToLab(linearRgbToXyz({0, 0, 1}));
  EXPECT_NEAR(green[0], 87.74, 0.02);
  EXPECT_NEAR(green[1], -86.18, 0.1);
  EXPECT_NEAR(green[2], 83.18, 0.05);
  EXPECT_NEAR(blue[0], 32.30, 0.02);
  EXPECT_NEAR(blue[1], 79.19, 0.05);
  EXPECT_NEAR(blue[2], -107.86, 0.05);
  EXPECT_NEAR(xyzToLab(linearRgbToXyz({0.18, 0.18, 0.18}))[0], 49.496, 1e-3);
}

TEST(Flip, HuntAdjustmentAndHyab) {
  const Color hunt = huntAdjust({50, 20, -10});
  EXPECT_DOUBLE_EQ(hunt[1], 10.0);  // 0.01 * 50 * 20
  EXPECT_DOUBLE_EQ(hunt[2], -5.0);
  EXPECT_DOUBLE_EQ(hyab({50, 10, 0}, {40, 13, 4}), 10.0 + 5.0);  // |dL| + ||(3, 4)||
  EXPECT_DOUBLE_EQ(hyab({40, 13, 4}, {50, 10, 0}), 15.0);
}

TEST(Flip, MaxColourDifferenceIsGreenToBlue) {
  // From the published Lab values above: Hunt-adjusted green (87.74, -75.61, 72.98), blue
  // (32.30, 25.58, -34.84): HyAB = 55.44 + hypot(101.19, 107.82) = 203.31, raised to 0.7.
  EXPECT_NEAR(maxColorDifference(), std::pow(203.31, 0.7), 0.05);
}

TEST(Flip, ColourErrorRedistribution) {
  const double cmax = maxColorDifference();
  EXPECT_DOUBLE_EQ(redistributeColorError(0.0, cmax), 0.0);
  EXPECT_NEAR(redistributeColorError(0.4 * cmax, cmax), 0.95, 1e-12);  // the knee p_c c_max -> p_t
  EXPECT_NEAR(redistributeColorError(0.4 * cmax - 1e-9, cmax), 0.95, 1e-8);
  EXPECT_NEAR(redistributeColorError(cmax, cmax), 1.0, 1e-12);
  EXPECT_NEAR(redistributeColorError(0.2 * cmax, cmax), 0.475, 1e-12);
}

TEST(Flip, SpatialFiltersCoverThreeSigmaOfTheWidestGaussian) {
  // b = 0.04 deg^2 (blue-yellow): sd = sqrt(0.04 / (2 pi^2)) = 0.0450 deg; 3 sd * 67.02 = 9.05 -> 10.
  for (int channel = 0; channel < 3; ++channel) {
    const std::vector<SeparableTerm> terms = spatialFilterTerms(channel, defaultPixelsPerDegree());
    ASSERT_FALSE(terms.empty());
    EXPECT_EQ(terms[0].taps.size(), 21u);
    EXPECT_GT(kernelSum(terms), 0.0);
  }
  EXPECT_EQ(spatialFilterTerms(0, defaultPixelsPerDegree()).size(), 1u);  // a2 = 0: one Gaussian
  EXPECT_EQ(spatialFilterTerms(2, defaultPixelsPerDegree()).size(), 2u);
}

TEST(Flip, SpatialFilterKernelSumsToOne) {
  // The 2D kernel, built tap by tap from the separable terms, divided by kernelSum, sums to 1.
  for (int channel = 0; channel < 3; ++channel) {
    const std::vector<SeparableTerm> terms = spatialFilterTerms(channel, 30.0);
    double total = 0;
    for (const SeparableTerm& t : terms)
      for (double ty : t.taps)
        for (double tx : t.taps) total += t.weight * tx * ty;
    EXPECT_NEAR(total / kernelSum(terms), 1.0, 1e-12);
    EXPECT_NEAR(kernelSum(terms), total, 1e-9 * total);
  }
}

TEST(Flip, FeatureFiltersAreNormalised) {
  for (Feature feature : {Feature::Edge, Feature::Point}) {
    const FeatureFilter f = featureFilter(feature, defaultPixelsPerDegree());
    double positive = 0, negative = 0;
    for (double d : f.derivative) (d > 0 ? positive : negative) += d;
    EXPECT_NEAR(positive, 1.0, 1e-12);
    EXPECT_NEAR(negative, -1.0, 1e-12);
    EXPECT_NEAR(sumOf(f.gaussian), 1.0, 1e-12);
    // sd = 0.5 * 0.082 * 67.02 = 2.75 px, radius ceil(3 sd) = 9.
    EXPECT_EQ(f.derivative.size(), 19u);
  }
  const FeatureFilter edge = featureFilter(Feature::Edge, 67.02);
  for (size_t i = 0; i < edge.derivative.size(); ++i)
    EXPECT_DOUBLE_EQ(edge.derivative[i], -edge.derivative[edge.derivative.size() - 1 - i]);  // odd
}

TEST(Flip, EdgeDetectorFindsAStepAndNotAFlatArea) {
  const int w = 60, h = 20;
  std::vector<double> step(size_t(w * h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) step[size_t(y * w + x)] = x >= 30 ? 1.0 : 0.0;
  const std::vector<double> edges = featureResponse(step, w, h, Feature::Edge, 67.02);
  // At the first bright column the filter sees all its negative taps on 1s: magnitude exactly 1.
  EXPECT_NEAR(edges[size_t(10 * w + 30)], 1.0, 1e-12);
  EXPECT_NEAR(edges[size_t(10 * w + 5)], 0.0, 1e-12);   // 25 px from the step: flat
  EXPECT_NEAR(edges[size_t(10 * w + 55)], 0.0, 1e-12);
}

TEST(Flip, PointDetectorFindsADotTheEdgeDetectorDoesNot) {
  const int w = 31, h = 31;
  std::vector<double> dot(size_t(w * h), 0.0);
  dot[size_t(15 * w + 15)] = 1.0;
  const std::vector<double> points = featureResponse(dot, w, h, Feature::Point, 67.02);
  const std::vector<double> edges = featureResponse(dot, w, h, Feature::Edge, 67.02);
  EXPECT_NEAR(edges[size_t(15 * w + 15)], 0.0, 1e-12);  // odd filter, centred on a symmetric dot
  EXPECT_GT(points[size_t(15 * w + 15)], 0.01);
}

RgbImage grey(int w, int h, double value) { return RgbImage(w, h, {value, value, value}); }

// Deterministic noise in [-1, 1] (a 64-bit LCG), the same for every amplitude.
RgbImage noisy(const RgbImage& base, double amplitude) {
  RgbImage out = base;
  uint64_t state = 12345;
  for (Color& c : out.pixels)
    for (double& v : c) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      const double u = double(state >> 11) / double(1ull << 53) * 2.0 - 1.0;
      v = std::clamp(v + amplitude * u, 0.0, 1.0);
    }
  return out;
}

TEST(Flip, IdenticalImagesHaveZeroError) {
  const RgbImage image = noisy(grey(24, 16, 0.5), 0.3);
  for (double e : ldrFlip(image, image, 67.02)) EXPECT_EQ(e, 0.0);
  const ExposureRange range = hdrExposureRange(image);
  for (double e : hdrFlip(image, image, 67.02, range)) EXPECT_EQ(e, 0.0);
}

TEST(Flip, LdrFlipIsSymmetricAndInUnitRange) {
  const RgbImage a = grey(24, 16, 0.4), b = noisy(a, 0.2);
  const std::vector<double> ab = ldrFlip(a, b, 67.02), ba = ldrFlip(b, a, 67.02);
  for (size_t i = 0; i < ab.size(); ++i) {
    EXPECT_NEAR(ab[i], ba[i], 1e-12);
    EXPECT_GE(ab[i], 0.0);
    EXPECT_LE(ab[i], 1.0);
  }
}

TEST(Flip, MeanErrorGrowsWithTheNoiseAmplitude) {
  const RgbImage reference = grey(32, 32, 0.5);
  double previous = 0;
  for (double amplitude : {0.01, 0.03, 0.1, 0.3}) {
    const double mean = meanOf(ldrFlip(reference, noisy(reference, amplitude), 67.02));
    EXPECT_GT(mean, previous) << "amplitude " << amplitude;
    previous = mean;
  }
  EXPECT_GT(previous, 0.3);  // heavy noise is plainly visible
}

TEST(Flip, BlackVersusWhiteIsNearTheTopOfTheScale) {
  const double mean = meanOf(ldrFlip(grey(16, 16, 0.0), grey(16, 16, 1.0), 67.02));
  // L* 0 vs 100 with no chroma: HyAB 100, 100^0.7 = 25.12 is above the knee 0.4 * 41.40 = 16.56:
  // 0.95 + (25.12 - 16.56) / (41.40 - 16.56) * 0.05 = 0.967; flat images have no features.
  EXPECT_NEAR(mean, 0.967, 1e-3);
  EXPECT_NEAR(mean, redistributeColorError(std::pow(100.0, 0.7), maxColorDifference()), 1e-6);
}

TEST(Flip, AcesToneMapperAndExposureRange) {
  EXPECT_DOUBLE_EQ(acesToneMap(0.0), 0.0);
  EXPECT_DOUBLE_EQ(acesToneMap(INFINITY), 1.0);
  // x such that the curve gives 0.85: root of 0.16002 x^2 - 0.2829 x - 0.119 = 0, x = 2.1189.
  EXPECT_NEAR(acesToneMap(2.1189), 0.85, 1e-4);
  // Brightest luminance 1, median 0.25: start log2(2.1189), stop two stops later.
  RgbImage image = grey(2, 2, 0.25);
  image.at(0, 0) = {1, 1, 1};
  image.at(1, 0) = {0.25, 0.25, 0.25};
  const ExposureRange range = hdrExposureRange(image);
  EXPECT_NEAR(range.start, std::log2(2.1189), 1e-4);
  EXPECT_NEAR(range.stop - range.start, 2.0, 1e-12);
  EXPECT_EQ(range.count, 2);
}

TEST(Flip, ExposureRangeTakesTheUpperMiddleLuminanceAsMedian) {
  // Luminances 0.1, 0.2, 0.4, 1: the median is element n/2 = 0.4 (as NVIDIA's nth_element takes
  // it), not the mean 0.3 of the two middle values.
  RgbImage image(4, 1);
  const double values[4] = {0.2, 1.0, 0.1, 0.4};
  for (int x = 0; x < 4; ++x) image.at(x, 0) = {values[x], values[x], values[x]};
  const ExposureRange range = hdrExposureRange(image);
  EXPECT_NEAR(range.stop, std::log2(2.1189 / 0.4), 1e-4);
  EXPECT_NEAR(range.stop - range.start, std::log2(1.0 / 0.4), 1e-12);
}

TEST(Flip, NegativeValuesAreToneMappedNotClampedToBlack) {
  // The rational curve is positive for inputs below -0.02: -0.1 maps to 0.064, -0.5 above 1 (clamped).
  EXPECT_DOUBLE_EQ(acesToneMap(-0.5), 1.0);
  EXPECT_NEAR(acesToneMap(-0.1), 0.0638, 1e-4);
  // So a pixel with a negative component differs from one with 0 there (NVIDIA's behaviour; a
  // clamp to 0 before tone mapping would make the two images identical).
  RgbImage a = grey(16, 16, 0.2), b = a;
  b.at(8, 8) = {-0.5, 0.2, 0.2};
  a.at(8, 8) = {0.0, 0.2, 0.2};
  EXPECT_GT(meanOf(hdrFlip(a, b, 67.02, hdrExposureRange(a))), 1e-4);
}

TEST(Flip, HdrFlipSeesDifferencesAboveOne) {
  // Two HDR images that differ only above 1.0: clipped to LDR they are identical, HDR-FLIP's
  // short exposures see the difference.
  RgbImage a = grey(16, 16, 0.2), b = a;
  for (int x = 4; x < 12; ++x) {
    a.at(x, 8) = {4, 4, 4};
    b.at(x, 8) = {16, 16, 16};
  }
  const ExposureRange range = hdrExposureRange(a);
  EXPECT_GT(meanOf(hdrFlip(a, b, 67.02, range)), 0.001);
}

TEST(Flip, MagmaEndsAndStops) {
  const Color first = magma(0.0), last = magma(1.0), middle = magma(128.0 / 255.0);
  EXPECT_NEAR(first[2], 0.013866, 1e-9);
  EXPECT_NEAR(last[0], 0.987053, 1e-9);
  EXPECT_NEAR(last[2], 0.749504, 1e-9);
  EXPECT_NEAR(middle[0], 0.716387, 1e-9);  // matplotlib's magma entry 128
}

}  // namespace flip_test
}  // namespace lacrima::diff
