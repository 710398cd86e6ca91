#pragma once
// The pixel reconstruction filter and its importance sampler.
//
// A pixel's value is the filter-weighted average of the radiance around its centre,
//   I(x, y) = integral f(s - x, t - y) L(s, t) ds dt,   integral f = 1.
// Filter importance sampling (Ernst, Stamminger & Greiner 2006, "Filter Importance Sampling")
// estimates it without splatting: each camera sample of the pixel draws its offset from the
// density p ~ |f| and carries the weight f / p. Every pixel traces only its own samples, so the
// image stays deterministic and independent of the thread count.
//
// The filters are separable, f(x, y) = f1(x) f1(y) (as in pbrt-v4), so one 1D table per filter
// serves both axes: its bins hold the exact integral of f1 over the bin, the offset is drawn by
// inverting the table's CDF (monotone in the random number, so a stratified sequence stays
// stratified), and the weight of a bin is sign(bin) * integral |f1| / integral f1. The filter
// realised is thus f1 averaged over bins 1/256 of the support wide. A filter without negative
// lobes has the weight exactly 1 for every sample.
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima {

enum class FilterType { Box, Gaussian, BlackmanHarris, Mitchell };

struct PixelFilter {
  FilterType type = FilterType::BlackmanHarris;
  float width = 1.5f;  // full width of the support in pixels (Cycles' "filter width"): radius = width / 2
};

// The width a shot gets when it names a type without a width: 1 px box (the old jitter), 3 px
// Gaussian (pbrt-v4: radius 1.5, sigma 0.5), 1.5 px Blackman-Harris (Cycles), 4 px Mitchell
// (pbrt-v4 and Mitchell & Netravali: radius 2).
float defaultFilterWidth(FilterType type);
bool hasNegativeLobes(FilterType type);
// The shot file's name of the type: "box", "gaussian", "blackman-harris", "mitchell".
const char* filterTypeName(FilterType type);

// The 1D profile f1 in pixels, normalized to integrate to 1 over [-width/2, width/2], 0 outside.
double filterProfile(const PixelFilter& filter, double x);

struct FilterSample {
  Vec2 offset;   // from the pixel centre, in pixels, each component in [-width/2, width/2]
  float weight;  // f / p, normalized so that its expectation is 1; +-1-ish with negative lobes
};

class FilterSampler {
 public:
  explicit FilterSampler(const PixelFilter& filter);

  // One offset per 2D random number u in [0, 1)^2: u.x() gives the x offset, u.y() the y offset.
  FilterSample sample(const Vec2& u) const;
  // The density of sample()'s offsets (per pixel^2), 0 outside the support.
  double pdf(const Vec2& offset) const;

  static constexpr int kBins = 256;

 private:
  struct AxisSample {
    float offset;
    float weight;
  };
  AxisSample sampleAxis(float u) const;
  double pdfAxis(float x) const;

  float radius_;
  std::vector<float> cdf_;         // kBins + 1, over [-radius, radius], proportional to |bin integral|
  std::vector<float> binWeight_;   // kBins: sign(bin integral) * integral |f1| / integral f1
  std::vector<int> guide_;         // kBins + 1: the CDF's guide table (distribution.hpp)
};

}  // namespace lacrima
