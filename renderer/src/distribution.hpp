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

// A guide table over a CDF (the cutpoint method: Chen & Asau 1974; Devroye 1986, "Non-Uniform
// Random Variate Generation", sec. III.2.4): guide[k] = the number of CDF entries <= k / G, for
// k = 0 .. G (G = guide.size() - 1). A u in [k / G, (k + 1) / G) has its bin between guide[k] - 1
// and guide[k + 1] - 1, so sampling searches that short range instead of the whole CDF (one or
// two cache lines of a 2k-wide environment row instead of eleven), and returns exactly the bin
// that the plain search would.
void buildGuide(std::span<const float> cdf, std::span<int> guide);

// sampleCdf(cdf, u), bitwise, with the guide table that buildGuide made for cdf.
CdfSample sampleCdf(std::span<const float> cdf, std::span<const int> guide, float u);

// Probability of bin i (0 <= i < cdf.size() - 1).
inline float binProbability(std::span<const float> cdf, int i) { return cdf[i + 1] - cdf[i]; }

}  // namespace lacrima::detail
