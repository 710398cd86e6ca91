#pragma once
// One pixel's running sums over its camera samples, and the pixel's value made from them.
#include <algorithm>

#include "lacrima/geometry/math.hpp"

namespace lacrima {

// Beauty and alpha are filter-weighted; the AOVs (albedo, normal, depth) are plain averages over
// the samples that hit something. The radiance summed over the first 2^k samples is kept for the
// two largest powers of two taken so far: adaptive sampling compares the whole estimate with the
// estimate over such a prefix (adaptive_sampling.hpp).
struct PixelSums {
  Color weightedRadiance = Color::Zero();  // sum of w L
  Color radiance = Color::Zero();          // sum of L
  Color prefixRadiance = Color::Zero();          // sum of L over the first 2^k samples, 2^k <= samples the largest
  Color previousPrefixRadiance = Color::Zero();  // the same over the first 2^(k-1)
  float weightedCoverage = 0.0f;           // sum of w * hit
  float coverage = 0.0f;                   // sum of hit
  float weight = 0.0f;                     // sum of w
  int samples = 0;                         // samples taken (a non-finite one counts, as black)
  Color albedo = Color::Zero();
  Vec3 normal = Vec3::Zero();
  float depth = 0.0f;
  int depthSamples = 0;
};

// Adds one sample's radiance to the plain sums (the filter-weighted ones are the caller's).
inline void addRadiance(PixelSums& sum, const Color& L) {
  sum.radiance += L;
  ++sum.samples;
  if ((sum.samples & (sum.samples - 1)) == 0) {  // a power of two: a new prefix
    sum.previousPrefixRadiance = sum.prefixRadiance;
    sum.prefixRadiance = sum.radiance;
  }
}

struct PixelValue {
  Color radiance;
  float alpha;
};

// The pixel is the weighted average sum(w L) / sum(w) (pbrt-v4's RGBFilm does the same), not
// sum(w L) / N: both are consistent, but the ratio reproduces a constant radiance exactly
// whatever the weights, so a flat sky keeps no noise from a filter's negative lobes. Without
// negative lobes every w is exactly 1 and this is the plain mean, bitwise. With them (Mitchell),
// w = +-c and sum(w) can be 0 or negative with few samples (2 samples of opposite signs); such a
// pixel takes the plain mean instead, the estimate of the filter |f|.
inline PixelValue pixelValue(const PixelSums& sum) {
  if (sum.samples == 0) return {Color::Zero(), 0.0f};
  if (sum.weight > 0.0f) {
    const float inv = 1.0f / sum.weight;
    // Coverage is a fraction: a negative lobe may ring the colour but not the alpha past [0, 1].
    return {sum.weightedRadiance * inv, std::clamp(sum.weightedCoverage * inv, 0.0f, 1.0f)};
  }
  const float inv = 1.0f / float(sum.samples);
  return {sum.radiance * inv, sum.coverage * inv};
}

}  // namespace lacrima
