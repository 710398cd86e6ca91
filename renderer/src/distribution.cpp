#include "distribution.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace lacrima::detail {

namespace {
// The largest float below 1: sample values are kept in [0, 1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;
}  // namespace

double buildCdf(std::span<const double> weights, std::span<float> cdf) {
  const std::size_t n = weights.size();
  // Accumulate in double so that long rows keep their small bins.
  double total = 0.0;
  for (double w : weights) total += w;
  cdf[0] = 0.0f;
  if (!(total > 0.0)) {
    for (std::size_t i = 1; i <= n; ++i) cdf[i] = float(double(i) / double(n));
    cdf[n] = 1.0f;
    return 0.0;
  }
  double running = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    running += weights[i];
    cdf[i + 1] = float(std::min(1.0, running / total));
  }
  cdf[n] = 1.0f;
  return total;
}

CdfSample sampleCdf(std::span<const float> cdf, float u) {
  const int n = int(cdf.size()) - 1;
  u = std::clamp(u, 0.0f, kOneMinusEpsilon);
  // The largest i with cdf[i] <= u. Because cdf[i + 1] > u, the bin has non-zero width, so
  // zero-probability bins are skipped (they share their CDF value with the next bin).
  const auto above = std::upper_bound(cdf.begin(), cdf.end(), u);
  const int index = std::clamp(int(above - cdf.begin()) - 1, 0, n - 1);
  CdfSample s;
  s.index = index;
  s.probability = cdf[index + 1] - cdf[index];
  s.offset = s.probability > 0.0f ? std::min((u - cdf[index]) / s.probability, kOneMinusEpsilon) : 0.0f;
  return s;
}

}  // namespace lacrima::detail
