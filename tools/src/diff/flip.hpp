#pragma once
// FLIP, the perceptual image difference of Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom
// and Fairchild, "FLIP: A Difference Evaluator for Alternating Images" (HPG 2020), and HDR-FLIP
// of Andersson, Nilsson, Shirley and Akenine-Moller, "Visualizing Errors in Rendered High Dynamic
// Range Images" (Eurographics 2021 short papers). Implemented from the papers; the results agree
// with NVIDIA's reference implementation (github.com/NVlabs/flip) to 1e-8 on the image pairs of
// tests/data/flip (tests/tools/flip_conformance_test.cpp); docs/diff.md says where and why they differ.
#include <array>
#include <cstddef>
#include <vector>

namespace lacrima::diff {

using Color = std::array<double, 3>;

// An RGB image, row-major, top row first.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<Color> pixels;

  RgbImage() = default;
  RgbImage(int w, int h, Color fill = {0, 0, 0}) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), fill) {}
  Color& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
  const Color& at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// Pixels per degree of visual angle of an observer `distance` metres from a monitor `monitorWidth`
// metres wide showing `resolutionX` pixels across (FLIP paper, Section 4 and its Eq. for ppd).
double pixelsPerDegree(double distance, double monitorWidth, double resolutionX);
// The papers' default observer: 0.7 m from a 0.7 m wide 3840-pixel monitor, 67.02 ppd.
double defaultPixelsPerDegree();

// Colour spaces of the colour pipeline (FLIP Section 4.1): sRGB, linear sRGB (Rec. 709 primaries),
// CIE XYZ (D65), the opponent space YCxCz and CIE L*a*b*, both relative to the D65 white.
Color srgbToLinear(const Color& c);
Color linearToSrgb(const Color& c);
Color linearRgbToXyz(const Color& c);
Color xyzToLinearRgb(const Color& c);
Color xyzToYCxCz(const Color& c);
Color yCxCzToXyz(const Color& c);
Color xyzToLab(const Color& c);
// Hunt adjustment: a* and b* scaled by 0.01 L* (FLIP Eq. 3).
Color huntAdjust(const Color& lab);
// HyAB distance |dL| + ||(da, db)|| (FLIP Eq. 4).
double hyab(const Color& a, const Color& b);
// The largest colour difference in Hunt-adjusted L*a*b*, between pure green and pure blue, raised
// to q_c = 0.7 (FLIP Section 4.1, "c_max").
double maxColorDifference();
// Maps the HyAB distance raised to q_c into [0, 1]: [0, p_c c_max) linearly onto [0, p_t), the rest
// onto [p_t, 1] (FLIP Eq. 5, p_c = 0.4, p_t = 0.95).
double redistributeColorError(double hyabPowQc, double cmaxPowQc);

// One separable part of a spatial filter: weight * taps(x) * taps(y), for x, y in [-r, r].
struct SeparableTerm {
  double weight = 0;
  std::vector<double> taps;  // 2r + 1 values, not normalised
};

// The contrast sensitivity filters of the achromatic (0), red-green (1) and blue-yellow (2)
// channels as sums of Gaussians (FLIP Eq. 2 and Table 1), over the radius of the widest one.
// The terms' 2D kernel sums to `kernelSum`; filtering divides by it so that the kernel sums to 1.
std::vector<SeparableTerm> spatialFilterTerms(int channel, double ppd);
double kernelSum(const std::vector<SeparableTerm>& terms);

// The edge (first derivative of a Gaussian) and point (second derivative) detectors of the
// feature pipeline (FLIP Section 4.2, w = 0.082 degrees): 2D kernel = derivative(x) * gaussian(y),
// the derivative normalised so its positive taps sum to 1 and its negative taps to -1, the
// Gaussian to sum 1.
enum class Feature { Edge, Point };
struct FeatureFilter {
  std::vector<double> derivative, gaussian;
};
FeatureFilter featureFilter(Feature feature, double ppd);
// The magnitude of the feature filter's x and y responses at each pixel of a luminance plane
// (row-major, borders replicated).
std::vector<double> featureResponse(const std::vector<double>& luminance, int width, int height, Feature feature,
                                    double ppd);

// The per-pixel FLIP error in [0, 1] of two sRGB-encoded LDR images of the same size (FLIP Eq. 8).
std::vector<double> ldrFlip(const RgbImage& referenceSrgb, const RgbImage& testSrgb, double ppd);

// HDR-FLIP's exposures (HDR-FLIP Section 3): from `start` (the reference's brightest pixel at 0.85
// after tone mapping) to `stop` (its median luminance at 0.85, the median being element n/2 of the
// sorted luminances as in NVIDIA's code), `count` = max(2, ceil(stop - start)) evenly spaced stops.
struct ExposureRange {
  double start = 0, stop = 0;
  int count = 2;
};
ExposureRange hdrExposureRange(const RgbImage& referenceLinear);
// The ACES filmic curve of HDR-FLIP (Narkowicz's fit, pre-exposure 0.6 folded in), clamped to [0, 1].
double acesToneMap(double x);

// The per-pixel HDR-FLIP error: the maximum LDR-FLIP over the exposures, each image exposed by
// 2^exposure, tone mapped (negative values included, not clamped first) and sRGB-encoded
// (HDR-FLIP Eq. 1). Linear Rec. 709 inputs.
std::vector<double> hdrFlip(const RgbImage& referenceLinear, const RgbImage& testLinear, double ppd,
                            const ExposureRange& exposures);

// The magma colour map (matplotlib, CC0) used by FLIP's error images, t in [0, 1] -> sRGB in [0, 1].
Color magma(double t);

}  // namespace lacrima::diff
