#pragma once
// Adaptive sampling: which pixels take more camera samples, and how many.
//
// Dammertz, Hanika, Keller & Lensch 2010, "A hierarchical automatic stopping condition for Monte
// Carlo global illumination" (WSCG), sec. 2.1: a pixel's error is estimated from the difference
// between its estimate I over all its samples and an estimate A over part of them, relative to
// the square root of its value,
//   e = (|I_r - A_r| + |I_g - A_g| + |I_b - A_b|) / sqrt(I_r + I_g + I_b),
// with Cycles' 1e-4 in the denominator against division by zero (Cycles, kernel/film/
// adaptive_sampling.h, where A is over the odd-numbered samples). Here A is over the first p
// samples, p the largest power of two below n: under the progressive sample order (sampler.hpp)
// those are one aligned block of Sobol points, stratified on their own. The odd-numbered samples
// of a Sobol sequence are not: sample 2j and 2j+1 differ in the first bit of the pixel position
// (before scrambling, in the first dimension), so the odd half is nearly one half of the pixel,
// and |I - A| would measure the image's detail inside the pixel rather than noise, and never
// fall (measured: on the default shot's close-up, no pixel converged before 256 samples even
// at a threshold of 0.1). The difference is scaled by sqrt(p / (n - p)), so that it estimates
// the error of I whatever n (1 at n = 2p, as in the paper). A pixel whose error is under the
// threshold has converged. Like Cycles,
// a pixel keeps sampling while any of its 8 neighbours has not converged: the estimate itself is
// noisy, and a lone stopped pixel in a noisy region would stay visibly noisier than its
// neighbours. Every decision is made between rounds, over the whole image, from sums that do not
// depend on the thread count, so adaptive renders stay deterministic.
#include <cstdint>
#include <vector>

#include "lacrima/renderer/frame.hpp"
#include "lacrima/renderer/pixel_sums.hpp"

namespace lacrima {

// The error estimate above; 0 for a pixel whose samples agree exactly (a black or constant pixel),
// infinite under 2 samples.
float pixelError(const PixelSums& sum);

// The sample count a pixel that has taken `taken` samples goes on to in its next round: the
// minimum first, then steps of a power of two at least 4 and about a quarter of what it has (so
// the error is checked about four times per doubling), never past `maxSamples`.
int nextSampleCount(int taken, const AdaptiveSampling& settings, int maxSamples);

// Marks in `active` (one per pixel, row-major) the pixels that take another round: under
// `maxSamples`, and themselves or one of their 8 neighbours not converged. Returns how many.
int selectActivePixels(const std::vector<PixelSums>& sums, int width, int height, const AdaptiveSampling& settings,
                       int maxSamples, std::vector<uint8_t>& active);

}  // namespace lacrima
