#pragma once
// One pixel's running sums over its camera samples, and the pixel's value made from them.
#include <algorithm>
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/renderer/cryptomatte.hpp"

namespace lacrima {

// One part of a pixel's radiance (its subsurface light, for the denoiser) summed as the beauty's
// plain sums are: sum, squares, and the sums over the first 2^k and 2^(k-1) samples.
struct PartSums {
  Color sum = Color::Zero();
  Color squared = Color::Zero();
  Color prefix = Color::Zero();
  Color previousPrefix = Color::Zero();
};

// Beauty and alpha are filter-weighted; the AOVs (albedo, normal, depth) are plain averages over
// the samples that hit something. The radiance summed over the first 2^k samples is kept for the
// two largest powers of two taken so far: adaptive sampling compares the whole estimate with the
// estimate over such a prefix (adaptive_sampling.hpp).
struct PixelSums {
  Color weightedRadiance = Color::Zero();  // sum of w L
  Color radiance = Color::Zero();          // sum of L
  Color radianceSquared = Color::Zero();   // sum of L^2 (the sample variance, for the denoiser)
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
  // Cryptomatte's ranking filter (only when the render writes it): the first hits' IDs.
  IdCoverage objectIds, materialIds;
  // Light groups and light paths (only when the render writes them): per split of the radiance,
  // sum of w L_s and of L_s.
  std::vector<Color> splitWeighted, splitPlain;
  // The subsurface light's plain sums (only when the denoiser filters it apart).
  PartSums subsurface;
};

inline bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }

// Adds one sample's radiance to the plain sums (the filter-weighted ones are the caller's).
inline void addRadiance(PixelSums& sum, const Color& L) {
  sum.radiance += L;
  sum.radianceSquared += L * L;
  ++sum.samples;
  if (isPowerOfTwo(sum.samples)) {  // a new prefix
    sum.previousPrefixRadiance = sum.prefixRadiance;
    sum.prefixRadiance = sum.radiance;
  }
}

// Adds one sample's subsurface light, after addRadiance added the sample's whole radiance.
inline void addSubsurface(PixelSums& sum, const Color& L) {
  PartSums& part = sum.subsurface;
  part.sum += L;
  part.squared += L * L;
  if (isPowerOfTwo(sum.samples)) {
    part.previousPrefix = part.prefix;
    part.prefix = part.sum;
  }
}

// Two independent estimates of the pixel: the mean over its first p samples (p the largest power
// of two below its count) and the mean over the others. Under the progressive sample order
// (sampler.hpp) the first p are one aligned block of Sobol points and the others the start of the
// next: both stratified. A pixel of one sample has one estimate, given twice.
struct PixelHalves {
  Color first = Color::Zero(), rest = Color::Zero();
  int firstSamples = 0;  // p
};

// The halves of n samples whose sum is `total`, with the sums over their first 2^k and 2^(k-1).
inline PixelHalves halvesOf(const Color& total, const Color& prefixSum, const Color& previousPrefixSum, int n) {
  if (n < 2) return {total, total, n};
  int prefix = 1;
  while (prefix * 2 < n) prefix *= 2;
  const Color& first = prefix * 2 == n ? previousPrefixSum : prefixSum;
  return {first / float(prefix), (total - first) / float(n - prefix), prefix};
}

inline PixelHalves pixelHalves(const PixelSums& sum) {
  return halvesOf(sum.radiance, sum.prefixRadiance, sum.previousPrefixRadiance, sum.samples);
}

inline PixelHalves subsurfaceHalves(const PixelSums& sum) {
  const PartSums& part = sum.subsurface;
  return halvesOf(part.sum, part.prefix, part.previousPrefix, sum.samples);
}

// The variance of the mean of half of n samples, per channel, from their sum and sum of squares:
// the samples' variance over n / 2 (0 under 2 samples, where there is nothing to estimate it from).
inline Color halfMeanVarianceOf(const Color& total, const Color& squared, int n) {
  if (n < 2) return Color::Zero();
  const Color mean = total / float(n);
  const Color sampleVariance = ((squared - float(n) * mean * mean) / float(n - 1)).max(0.0f);
  return sampleVariance / (0.5f * float(n));
}

inline Color halfMeanVariance(const PixelSums& sum) {
  return halfMeanVarianceOf(sum.radiance, sum.radianceSquared, sum.samples);
}

inline Color subsurfaceHalfMeanVariance(const PixelSums& sum) {
  return halfMeanVarianceOf(sum.subsurface.sum, sum.subsurface.squared, sum.samples);
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
// A split's value in the pixel (a light group's, a light path's), made as pixelValue makes the
// beauty, so that the splits add up to it.
inline Color splitValue(const PixelSums& sum, size_t split) {
  if (sum.samples == 0 || split >= sum.splitWeighted.size()) return Color::Zero();
  if (sum.weight > 0.0f) return sum.splitWeighted[split] * (1.0f / sum.weight);
  return sum.splitPlain[split] * (1.0f / float(sum.samples));
}

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
