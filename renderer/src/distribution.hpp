#pragma once
// Piecewise-constant 1D distributions stored as a cumulative distribution function (CDF), the
// building block of pbrt's Distribution1D/Distribution2D (Pharr, Jakob, Humphreys, "Physically
// Based Rendering", 3rd ed., section 13.3.1 and 13.6.7). Private helper of the renderer.
//
// A distribution over n bins is its CDF: n + 1 floats, cdf[0] = 0, cdf[n] = 1. Sampling inverts
// the CDF; the probability of bin i is defined as cdf[i + 1] - cdf[i]. Defining the probability
// from the stored CDF (rather than from the original weights) makes the value reported by
// binProbability() exactly the probability with which sampleCdf() selects the bin, including for
// bins whose weight is too small to survive rounding: those have probability 0 and are never
// selected.
#include <span>

namespace lacrima::detail {

// Fills cdf (weights.size() + 1 entries) from non-negative finite weights and returns their sum.
// When the sum is zero the CDF is made uniform, so the distribution is always valid.
double buildCdf(std::span<const double> weights, std::span<float> cdf);

struct CdfSample {
  int index = 0;             // the selected bin
  float offset = 0.0f;       // position inside the bin, in [0, 1)
  float probability = 0.0f;  // cdf[index + 1] - cdf[index], > 0
};

// Selects the bin containing u (u in [0, 1); values outside are clamped) and the position of u
// inside it. Never returns a bin of probability zero.
CdfSample sampleCdf(std::span<const float> cdf, float u);

// Probability of bin i (0 <= i < cdf.size() - 1).
inline float binProbability(std::span<const float> cdf, int i) { return cdf[i + 1] - cdf[i]; }

}  // namespace lacrima::detail
