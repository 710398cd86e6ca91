// Pixel filter profiles and the tabulated filter importance sampler (see pixel_filter.hpp).
#include "lacrima/renderer/pixel_filter.hpp"

#include <numbers>
#include <algorithm>
#include <cmath>
#include <span>

#include "distribution.hpp"

namespace lacrima {

namespace {


// Box: constant over the support. Width 1 is the uniform jitter of a pixel's square.
double boxProfile(double width) { return 1.0 / width; }

// Gaussian with sigma = width / 6 (the support is +-3 sigma), minus its value at the edge so that
// it reaches 0 there without a step (Pharr, Jakob & Humphreys 2023, "Physically Based Rendering",
// 4th ed., section 8.8.4, "Gaussian Filter"). Normalized with the exact integral of that profile:
// sigma sqrt(2 pi) erf(r / (sigma sqrt 2)) - 2 r g(r).
double gaussianProfile(double width, double x) {
  const double r = 0.5 * width, sigma = width / 6.0;
  const auto g = [sigma](double t) { return std::exp(-t * t / (2.0 * sigma * sigma)); };
  const double integral = sigma * std::sqrt(2.0 * std::numbers::pi) * std::erf(r / (sigma * std::sqrt(2.0))) - 2.0 * r * g(r);
  return std::max(0.0, g(x) - g(r)) / integral;
}

// The 4-term Blackman-Harris window (Harris 1978, "On the use of windows for harmonic analysis
// with the discrete Fourier transform", the minimum 4-term window with -92 dB side lobes), over
// the full width as Cycles' filter_func_blackman_harris does: t = x / width + 1/2 in [0, 1]. The
// cosines integrate to 0 over whole periods, so the window's integral is a0 * width.
double blackmanHarrisProfile(double width, double x) {
  constexpr double a0 = 0.35875, a1 = 0.48829, a2 = 0.14128, a3 = 0.01168;
  const double phase = 2.0 * std::numbers::pi * (x / width + 0.5);
  const double window = a0 - a1 * std::cos(phase) + a2 * std::cos(2.0 * phase) - a3 * std::cos(3.0 * phase);
  return window / (a0 * width);
}

// Mitchell & Netravali 1988, "Reconstruction filters in computer graphics", eq. 8, with their
// recommended B = C = 1/3, on [-2, 2]. It integrates to 1 (its shifts sum to 1); scaling its
// support to the filter's radius r maps x to 2 x / r and multiplies by 2 / r.
double mitchellKernel(double x) {
  constexpr double B = 1.0 / 3.0, C = 1.0 / 3.0;
  x = std::abs(x);
  if (x < 1.0) return ((12 - 9 * B - 6 * C) * x * x * x + (-18 + 12 * B + 6 * C) * x * x + (6 - 2 * B)) / 6.0;
  if (x < 2.0)
    return ((-B - 6 * C) * x * x * x + (6 * B + 30 * C) * x * x + (-12 * B - 48 * C) * x + (8 * B + 24 * C)) / 6.0;
  return 0.0;
}

// Integral of the profile over [a, b] by composite Simpson (the profiles are smooth inside a bin
// apart from Mitchell's C1 knot; 16 intervals leave errors far below float resolution).
double integrateProfile(const PixelFilter& filter, double a, double b) {
  constexpr int n = 16;
  const double h = (b - a) / n;
  double sum = filterProfile(filter, a) + filterProfile(filter, b);
  for (int k = 1; k < n; ++k) sum += (k % 2 ? 4.0 : 2.0) * filterProfile(filter, a + k * h);
  return sum * h / 3.0;
}

}  // namespace

float defaultFilterWidth(FilterType type) {
  switch (type) {
    case FilterType::Box: return 1.0f;
    case FilterType::Gaussian: return 3.0f;
    case FilterType::BlackmanHarris: return 1.5f;
    case FilterType::Mitchell: return 4.0f;
  }
  return 1.5f;
}

bool hasNegativeLobes(FilterType type) { return type == FilterType::Mitchell; }

const char* filterTypeName(FilterType type) {
  switch (type) {
    case FilterType::Box: return "box";
    case FilterType::Gaussian: return "gaussian";
    case FilterType::BlackmanHarris: return "blackman-harris";
    case FilterType::Mitchell: return "mitchell";
  }
  return "unknown";
}

double filterProfile(const PixelFilter& filter, double x) {
  const double width = filter.width;
  if (!(std::abs(x) <= 0.5 * width)) return 0.0;
  switch (filter.type) {
    case FilterType::Box: return boxProfile(width);
    case FilterType::Gaussian: return gaussianProfile(width, x);
    case FilterType::BlackmanHarris: return blackmanHarrisProfile(width, x);
    case FilterType::Mitchell: return mitchellKernel(4.0 * x / width) * 4.0 / width;
  }
  return 0.0;
}

FilterSampler::FilterSampler(const PixelFilter& filter)
    : radius_(0.5f * filter.width), cdf_(kBins + 1), binWeight_(kBins), guide_(kBins + 1) {
  std::vector<double> binIntegral(kBins), magnitude(kBins);
  const double binWidth = double(filter.width) / kBins;
  double sum = 0.0, sumAbs = 0.0;
  for (int i = 0; i < kBins; ++i) {
    const double a = -double(radius_) + i * binWidth;
    binIntegral[i] = integrateProfile(filter, a, a + binWidth);
    magnitude[i] = std::abs(binIntegral[i]);
    sum += binIntegral[i];
    sumAbs += magnitude[i];
  }
  detail::buildCdf(magnitude, cdf_);
  detail::buildGuide(cdf_, guide_);
  // f / p for a sample in bin i: (b_i / binWidth) / (|b_i| / sumAbs / binWidth), divided by the
  // realised filter's integral `sum` so that E[weight] = 1. Without negative lobes sumAbs and sum
  // are the same double, and the weight is exactly 1.
  const double scale = sumAbs / sum;
  for (int i = 0; i < kBins; ++i) binWeight_[i] = float(binIntegral[i] < 0.0 ? -scale : scale);
}

FilterSampler::AxisSample FilterSampler::sampleAxis(float u) const {
  const detail::CdfSample s = detail::sampleCdf(cdf_, guide_, u);
  const float x = -radius_ + (float(s.index) + s.offset) * (2.0f * radius_ / float(kBins));
  return {std::clamp(x, -radius_, radius_), binWeight_[s.index]};
}

FilterSample FilterSampler::sample(const Vec2& u) const {
  const AxisSample sx = sampleAxis(u.x()), sy = sampleAxis(u.y());
  return {Vec2(sx.offset, sy.offset), sx.weight * sy.weight};
}

double FilterSampler::pdfAxis(float x) const {
  if (!(std::abs(x) <= radius_)) return 0.0;
  const double binWidth = 2.0 * radius_ / kBins;
  const int bin = std::clamp(int((double(x) + radius_) / binWidth), 0, kBins - 1);
  return detail::binProbability(cdf_, bin) / binWidth;
}

double FilterSampler::pdf(const Vec2& offset) const { return pdfAxis(offset.x()) * pdfAxis(offset.y()); }

}  // namespace lacrima
