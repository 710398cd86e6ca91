// FLIP and HDR-FLIP; see flip.hpp for the papers. Equation numbers refer to the HPG 2020 FLIP
// paper unless "HDR-FLIP" is named.
#include "diff/flip.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lacrima::diff {

namespace {

constexpr double kPi = std::numbers::pi;
// Colour and feature exponents q_c, q_f, error redistribution p_c, p_t, edge width w (degrees):
// FLIP Sections 4.1-4.3.
constexpr double kQc = 0.7, kQf = 0.5, kPc = 0.4, kPt = 0.95, kFeatureWidth = 0.082;
// The D65 white in XYZ: the row sums of the sRGB -> XYZ matrix below.
constexpr Color kWhite = {0.950428545, 1.0, 1.088900371};

// Single plane of doubles for the filters.
struct Plane {
  int width = 0, height = 0;
  std::vector<double> v;
  Plane(int w, int h) : width(w), height(h), v(size_t(w) * size_t(h), 0.0) {}
  double& at(int x, int y) { return v[size_t(y) * size_t(width) + size_t(x)]; }
  double at(int x, int y) const { return v[size_t(y) * size_t(width) + size_t(x)]; }
};

// Separable convolution, borders replicated (the reference implementation's border rule).
Plane convolve(const Plane& in, const std::vector<double>& alongX, const std::vector<double>& alongY) {
  const int rx = int(alongX.size() / 2), ry = int(alongY.size() / 2);
  Plane rows(in.width, in.height), out(in.width, in.height);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      double sum = 0;
      for (int k = -rx; k <= rx; ++k) sum += alongX[size_t(k + rx)] * in.at(std::clamp(x + k, 0, in.width - 1), y);
      rows.at(x, y) = sum;
    }
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      double sum = 0;
      for (int k = -ry; k <= ry; ++k) sum += alongY[size_t(k + ry)] * rows.at(x, std::clamp(y + k, 0, in.height - 1));
      out.at(x, y) = sum;
    }
  return out;
}

Plane channelPlane(const RgbImage& image, int channel) {
  Plane p(image.width, image.height);
  for (size_t i = 0; i < image.pixels.size(); ++i) p.v[i] = image.pixels[i][size_t(channel)];
  return p;
}

// FLIP Eq. 2: the CSF of each opponent channel as a sum of two Gaussians, a * sqrt(pi/b) *
// exp(-pi^2 x^2 / b), with (a1, b1, a2, b2) from Table 1 (a2 = 0: one Gaussian).
struct CsfConstants {
  double a1, b1, a2, b2;
};
constexpr CsfConstants kCsf[3] = {{1.0, 0.0047, 0.0, 1e-5}, {1.0, 0.0053, 0.0, 1e-5}, {34.1, 0.04, 13.5, 0.025}};

int spatialFilterRadius(double ppd) {
  double widest = 0;
  for (const CsfConstants& c : kCsf) widest = std::max({widest, c.b1, c.b2});
  // Three standard deviations of the widest Gaussian, sd = sqrt(b / (2 pi^2)) degrees.
  return int(std::ceil(3.0 * std::sqrt(widest / (2.0 * kPi * kPi)) * ppd));
}

SeparableTerm gaussianTerm(double a, double b, int radius, double ppd) {
  SeparableTerm term;
  term.weight = a * std::sqrt(kPi / b);
  for (int i = -radius; i <= radius; ++i) {
    const double x = i / ppd;  // degrees
    term.taps.push_back(std::exp(-kPi * kPi * x * x / b));
  }
  return term;
}

// The opponent image filtered by each channel's CSF (FLIP Section 4.1, first step).
RgbImage spatiallyFiltered(const RgbImage& yCxCz, double ppd) {
  RgbImage out(yCxCz.width, yCxCz.height);
  for (int c = 0; c < 3; ++c) {
    const std::vector<SeparableTerm> terms = spatialFilterTerms(c, ppd);
    const double sum = kernelSum(terms);
    const Plane in = channelPlane(yCxCz, c);
    Plane filtered(in.width, in.height);
    for (const SeparableTerm& t : terms) {
      const Plane part = convolve(in, t.taps, t.taps);
      for (size_t i = 0; i < part.v.size(); ++i) filtered.v[i] += t.weight * part.v[i] / sum;
    }
    for (size_t i = 0; i < filtered.v.size(); ++i) out.pixels[i][size_t(c)] = filtered.v[i];
  }
  return out;
}

RgbImage toYCxCz(const RgbImage& srgb) {
  RgbImage out(srgb.width, srgb.height);
  for (size_t i = 0; i < srgb.pixels.size(); ++i) out.pixels[i] = xyzToYCxCz(linearRgbToXyz(srgbToLinear(srgb.pixels[i])));
  return out;
}

// Filtered opponent colours back to linear RGB, clamped to the unit cube, to Hunt-adjusted L*a*b*.
Color perceptualColor(const Color& filteredYCxCz) {
  Color rgb = xyzToLinearRgb(yCxCzToXyz(filteredYCxCz));
  for (double& v : rgb) v = std::clamp(v, 0.0, 1.0);
  return huntAdjust(xyzToLab(linearRgbToXyz(rgb)));
}

// The achromatic channel of YCxCz normalised to [0, 1]: (Y + 16) / 116 (Section 4.2).
Plane normalisedLuminance(const RgbImage& yCxCz) {
  Plane p = channelPlane(yCxCz, 0);
  for (double& v : p.v) v = (v + 16.0) / 116.0;
  return p;
}

// HDR-FLIP Section 3: the ACES fit as (k0 x^2 + k1 x + k2) / (k3 x^2 + k4 x + k5), with the fit's
// pre-exposure of 0.6 folded into the coefficients.
constexpr double kAces[6] = {0.6 * 0.6 * 2.51, 0.6 * 0.03, 0.0, 0.6 * 0.6 * 2.43, 0.6 * 0.59, 0.14};

// The input x that the tone mapper maps to `t` (the positive root of the quadratic).
double acesInverse(double t) {
  const double c0 = (kAces[1] - kAces[4] * t) / (kAces[0] - kAces[3] * t);
  const double c1 = (kAces[2] - kAces[5] * t) / (kAces[0] - kAces[3] * t);
  return -0.5 * c0 + std::sqrt(0.25 * c0 * c0 - c1);
}

double luminance(const Color& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

// Negative components are tone mapped as they are, not set to 0 first: the curve maps values below
// -0.02 to a positive value (below about -0.41 to white), and that is what NVIDIA's reference
// implementation does, so a render with out-of-gamut pixels gets the same HDR-FLIP from both.
RgbImage exposedSrgb(const RgbImage& linear, double exposure) {
  RgbImage out(linear.width, linear.height);
  const double scale = std::exp2(exposure);
  for (size_t i = 0; i < linear.pixels.size(); ++i)
    for (size_t c = 0; c < 3; ++c) {
      const double v = linear.pixels[i][c];
      out.pixels[i][c] = acesToneMap(std::isnan(v) ? 0.0 : scale * v);
    }
  for (Color& c : out.pixels) c = linearToSrgb(c);
  return out;
}

}  // namespace

double pixelsPerDegree(double distance, double monitorWidth, double resolutionX) {
  return distance * (resolutionX / monitorWidth) * (kPi / 180.0);
}

double defaultPixelsPerDegree() { return pixelsPerDegree(0.7, 0.7, 3840.0); }

Color srgbToLinear(const Color& c) {
  Color out;
  for (size_t i = 0; i < 3; ++i)
    out[i] = c[i] > 0.04045 ? std::pow((c[i] + 0.055) / 1.055, 2.4) : c[i] / 12.92;
  return out;
}

Color linearToSrgb(const Color& c) {
  Color out;
  for (size_t i = 0; i < 3; ++i)
    out[i] = c[i] > 0.0031308 ? 1.055 * std::pow(c[i], 1.0 / 2.4) - 0.055 : 12.92 * c[i];
  return out;
}

// The sRGB (Rec. 709 primaries, D65) matrix in the exact rational form (IEC 61966-2-1).
Color linearRgbToXyz(const Color& c) {
  return {(10135552.0 * c[0] + 8788810.0 * c[1] + 4435075.0 * c[2]) / 24577794.0,
          (2613072.0 * c[0] + 8788810.0 * c[1] + 887015.0 * c[2]) / 12288897.0,
          (1425312.0 * c[0] + 8788810.0 * c[1] + 70074185.0 * c[2]) / 73733382.0};
}

// The inverse of the matrix above.
Color xyzToLinearRgb(const Color& c) {
  return {3.241003275 * c[0] - 1.537398934 * c[1] - 0.498615861 * c[2],
          -0.969224334 * c[0] + 1.875930071 * c[1] + 0.041554224 * c[2],
          0.055639423 * c[0] - 0.204011202 * c[1] + 1.057148933 * c[2]};
}

// YCxCz: L*a*b* without the cube root, i.e. linear in XYZ (FLIP Eq. 1).
Color xyzToYCxCz(const Color& c) {
  const double x = c[0] / kWhite[0], y = c[1] / kWhite[1], z = c[2] / kWhite[2];
  return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

Color yCxCzToXyz(const Color& c) {
  const double y = (c[0] + 16.0) / 116.0;
  return {(y + c[1] / 500.0) * kWhite[0], y * kWhite[1], (y - c[2] / 200.0) * kWhite[2]};
}

Color xyzToLab(const Color& c) {
  constexpr double delta = 6.0 / 29.0;
  auto f = [](double t) { return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0; };
  const double fx = f(c[0] / kWhite[0]), fy = f(c[1] / kWhite[1]), fz = f(c[2] / kWhite[2]);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

Color huntAdjust(const Color& lab) { return {lab[0], 0.01 * lab[0] * lab[1], 0.01 * lab[0] * lab[2]}; }

double hyab(const Color& a, const Color& b) { return std::abs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]); }

double maxColorDifference() {
  const Color green = huntAdjust(xyzToLab(linearRgbToXyz({0, 1, 0})));
  const Color blue = huntAdjust(xyzToLab(linearRgbToXyz({0, 0, 1})));
  return std::pow(hyab(green, blue), kQc);
}

double redistributeColorError(double hyabPowQc, double cmaxPowQc) {
  const double knee = kPc * cmaxPowQc;
  if (hyabPowQc < knee) return kPt * hyabPowQc / knee;
  return std::min(1.0, kPt + (hyabPowQc - knee) / (cmaxPowQc - knee) * (1.0 - kPt));
}

std::vector<SeparableTerm> spatialFilterTerms(int channel, double ppd) {
  const CsfConstants& c = kCsf[channel];
  const int radius = spatialFilterRadius(ppd);
  std::vector<SeparableTerm> terms{gaussianTerm(c.a1, c.b1, radius, ppd)};
  if (c.a2 != 0.0) terms.push_back(gaussianTerm(c.a2, c.b2, radius, ppd));
  return terms;
}

double kernelSum(const std::vector<SeparableTerm>& terms) {
  double sum = 0;
  for (const SeparableTerm& t : terms) {
    double line = 0;
    for (double v : t.taps) line += v;
    sum += t.weight * line * line;
  }
  return sum;
}

FeatureFilter featureFilter(Feature feature, double ppd) {
  const double sd = 0.5 * kFeatureWidth * ppd;  // pixels
  const int radius = int(std::ceil(3.0 * sd));
  FeatureFilter f;
  double positive = 0, negative = 0, gaussianSum = 0;
  for (int i = -radius; i <= radius; ++i) {
    const double x = i, g = std::exp(-x * x / (2.0 * sd * sd));
    const double d = feature == Feature::Edge ? -x * g : (x * x / (sd * sd) - 1.0) * g;
    f.gaussian.push_back(g);
    f.derivative.push_back(d);
    gaussianSum += g;
    (d > 0 ? positive : negative) += d;
  }
  for (double& g : f.gaussian) g /= gaussianSum;
  for (double& d : f.derivative) d = d > 0 ? d / positive : d < 0 ? d / -negative : 0.0;
  return f;
}

std::vector<double> featureResponse(const std::vector<double>& luminance, int width, int height, Feature feature,
                                    double ppd) {
  Plane plane(width, height);
  plane.v = luminance;
  const FeatureFilter f = featureFilter(feature, ppd);
  const Plane alongX = convolve(plane, f.derivative, f.gaussian);
  const Plane alongY = convolve(plane, f.gaussian, f.derivative);
  std::vector<double> magnitude(luminance.size());
  for (size_t i = 0; i < magnitude.size(); ++i) magnitude[i] = std::hypot(alongX.v[i], alongY.v[i]);
  return magnitude;
}

std::vector<double> ldrFlip(const RgbImage& referenceSrgb, const RgbImage& testSrgb, double ppd) {
  const RgbImage reference = toYCxCz(referenceSrgb), test = toYCxCz(testSrgb);
  const RgbImage filteredReference = spatiallyFiltered(reference, ppd), filteredTest = spatiallyFiltered(test, ppd);
  const Plane yReference = normalisedLuminance(reference), yTest = normalisedLuminance(test);
  const int w = reference.width, h = reference.height;
  const std::vector<double> edgesReference = featureResponse(yReference.v, w, h, Feature::Edge, ppd);
  const std::vector<double> edgesTest = featureResponse(yTest.v, w, h, Feature::Edge, ppd);
  const std::vector<double> pointsReference = featureResponse(yReference.v, w, h, Feature::Point, ppd);
  const std::vector<double> pointsTest = featureResponse(yTest.v, w, h, Feature::Point, ppd);
  const double cmax = maxColorDifference();

  std::vector<double> error(reference.pixels.size());
  for (size_t i = 0; i < error.size(); ++i) {
    const double colorDistance =
        hyab(perceptualColor(filteredReference.pixels[i]), perceptualColor(filteredTest.pixels[i]));
    const double colorError = redistributeColorError(std::pow(colorDistance, kQc), cmax);
    // Eq. 7: the larger of the edge and point differences, scaled into [0, 1], raised to q_f.
    const double featureDifference = std::max(std::abs(edgesReference[i] - edgesTest[i]),
                                              std::abs(pointsReference[i] - pointsTest[i]));
    const double featureError = std::pow(featureDifference / std::sqrt(2.0), kQf);
    error[i] = std::pow(colorError, 1.0 - featureError);  // Eq. 8
  }
  return error;
}

ExposureRange hdrExposureRange(const RgbImage& referenceLinear) {
  // Luminance as it is, negative values included (NVIDIA's reference implementation does not clamp
  // them either); a NaN or infinite pixel counts as black.
  std::vector<double> lum;
  lum.reserve(referenceLinear.pixels.size());
  for (const Color& c : referenceLinear.pixels) {
    const double y = luminance(c);
    lum.push_back(std::isfinite(y) ? y : 0.0);
  }
  ExposureRange range;
  if (lum.empty()) return range;
  std::sort(lum.begin(), lum.end());
  const double brightest = lum.back();
  if (brightest <= 0.0) return range;
  // The median as NVIDIA's implementation takes it: element n/2 of the sorted values (the upper of
  // the two middle values for an even count, not their mean).
  double median = lum[lum.size() / 2];
  // A mostly black reference: the smallest lit pixel instead (the median would give an infinite
  // stop exposure; NVIDIA's tool has no such guard).
  if (median <= 0.0) median = *std::upper_bound(lum.begin(), lum.end(), 0.0);
  range.start = std::log2(acesInverse(0.85) / brightest);
  range.stop = std::log2(acesInverse(0.85) / median);
  range.count = std::max(2, int(std::ceil(range.stop - range.start)));
  return range;
}

double acesToneMap(double x) {
  if (std::isinf(x)) return 1.0;
  const double y = (kAces[0] * x * x + kAces[1] * x + kAces[2]) / (kAces[3] * x * x + kAces[4] * x + kAces[5]);
  return std::clamp(y, 0.0, 1.0);
}

std::vector<double> hdrFlip(const RgbImage& referenceLinear, const RgbImage& testLinear, double ppd,
                            const ExposureRange& exposures) {
  const double step = (exposures.stop - exposures.start) / std::max(exposures.count - 1, 1);
  std::vector<std::vector<double>> perExposure(size_t(exposures.count));
  tbb::parallel_for(0, exposures.count, [&](int i) {
    const double exposure = exposures.start + i * step;
    perExposure[size_t(i)] = ldrFlip(exposedSrgb(referenceLinear, exposure), exposedSrgb(testLinear, exposure), ppd);
  });
  std::vector<double> error(referenceLinear.pixels.size(), 0.0);
  for (const std::vector<double>& e : perExposure)
    for (size_t i = 0; i < error.size(); ++i) error[i] = std::max(error[i], e[i]);
  return error;
}

Color magma(double t) {
  // Every 16th entry of matplotlib's 256-entry magma table (and the last), interpolated linearly.
  static constexpr Color kStops[17] = {
      {0.001462, 0.000466, 0.013866}, {0.039608, 0.031090, 0.133515}, {0.113094, 0.065492, 0.276784},
      {0.211718, 0.061992, 0.418647}, {0.316654, 0.071690, 0.485380}, {0.414709, 0.110431, 0.504662},
      {0.512831, 0.148179, 0.507648}, {0.613617, 0.181811, 0.498536}, {0.716387, 0.214982, 0.475290},
      {0.816914, 0.255895, 0.436461}, {0.904281, 0.319610, 0.388137}, {0.960949, 0.418323, 0.359630},
      {0.986700, 0.535582, 0.382210}, {0.996096, 0.653659, 0.446213}, {0.996898, 0.769591, 0.534892},
      {0.992440, 0.884330, 0.640099}, {0.987053, 0.991438, 0.749504}};
  const double index = std::clamp(std::isnan(t) ? 0.0 : t, 0.0, 1.0) * 255.0;
  const int stop = std::min(int(index / 16.0), 15);
  const double lo = stop * 16.0, hi = stop == 15 ? 255.0 : lo + 16.0;
  const double s = (index - lo) / (hi - lo);
  Color c;
  for (size_t i = 0; i < 3; ++i) c[i] = kStops[stop][i] + s * (kStops[stop + 1][i] - kStops[stop][i]);
  return c;
}

}  // namespace lacrima::diff
