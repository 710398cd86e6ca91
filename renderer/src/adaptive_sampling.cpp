#include "lacrima/renderer/adaptive_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lacrima {

float pixelError(const PixelSums& sum) {
  const int n = sum.samples;
  if (n < 2) return std::numeric_limits<float>::infinity();
  // Plain means: with the default filters every filter weight is 1 and they are the pixel's value
  // itself; with Mitchell's signed weights they estimate |f|, close enough to judge convergence.
  const PixelHalves halves = pixelHalves(sum);
  const int p = halves.firstSamples;
  const Color whole = sum.radiance / float(n);
  // |I - A| has the spread of the whole's error times sqrt((n - p) / p) (I - A = (n - p) / n (B - A),
  // A over p samples, B over the n - p others): scaled back to the whole's, 1 at n = 2p.
  const float difference = (whole - halves.first).abs().sum() * std::sqrt(float(p) / float(n - p));
  return difference / (1e-4f + std::sqrt(std::max(whole.sum(), 0.0f)));
}

int nextSampleCount(int taken, const AdaptiveSampling& settings, int maxSamples) {
  if (taken < settings.minSamples) return std::min(settings.minSamples, maxSamples);
  int step = 4;
  while (step * 8 <= taken) step *= 2;  // the largest power of two <= taken / 4, at least 4
  return std::min(taken + step, maxSamples);
}

int selectActivePixels(const std::vector<PixelSums>& sums, int width, int height, const AdaptiveSampling& settings,
                       int maxSamples, std::vector<uint8_t>& active) {
  const size_t n = size_t(width) * size_t(height);
  std::vector<uint8_t> unconverged(n);
  for (size_t p = 0; p < n; ++p)
    unconverged[p] = sums[p].samples < settings.minSamples || !(pixelError(sums[p]) < settings.threshold);
  active.assign(n, 0);
  int count = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const size_t p = size_t(y) * width + x;
      if (sums[p].samples >= maxSamples) continue;
      bool any = false;
      for (int dy = -1; dy <= 1 && !any; ++dy)
        for (int dx = -1; dx <= 1 && !any; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx >= 0 && ny >= 0 && nx < width && ny < height) any = unconverged[size_t(ny) * width + nx] != 0;
        }
      active[p] = any;
      count += any;
    }
  return count;
}

}  // namespace lacrima
