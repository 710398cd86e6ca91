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

namespace {

// The sample of bin `above - 1`, where `above` is the first CDF entry > u (u already clamped).
CdfSample sampleOfUpperBound(std::span<const float> cdf, std::span<const float>::iterator above, float u) {
  const int n = int(cdf.size()) - 1;
  // The largest i with cdf[i] <= u. Because cdf[i + 1] > u, the bin has non-zero width, so
  // zero-probability bins are skipped (they share their CDF value with the next bin).
  const int index = std::clamp(int(above - cdf.begin()) - 1, 0, n - 1);
  CdfSample s;
  s.index = index;
  s.probability = cdf[index + 1] - cdf[index];
  s.offset = s.probability > 0.0f ? std::min((u - cdf[index]) / s.probability, kOneMinusEpsilon) : 0.0f;
  return s;
}

// The guide's cell boundary k / G, as the float that u is compared with.
float guideBoundary(int k, int cells) { return float(double(k) / double(cells)); }

}  // namespace

CdfSample sampleCdf(std::span<const float> cdf, float u) {
  u = std::clamp(u, 0.0f, kOneMinusEpsilon);
  return sampleOfUpperBound(cdf, std::upper_bound(cdf.begin(), cdf.end(), u), u);
}

void buildGuide(std::span<const float> cdf, std::span<int> guide) {
  const int cells = int(guide.size()) - 1;
  for (int k = 0; k <= cells; ++k)
    guide[k] = int(std::upper_bound(cdf.begin(), cdf.end(), guideBoundary(k, cells)) - cdf.begin());
}

CdfSample sampleCdf(std::span<const float> cdf, std::span<const int> guide, float u) {
  u = std::clamp(u, 0.0f, kOneMinusEpsilon);
  const int cells = int(guide.size()) - 1;
  if (cells < 1) return sampleCdf(cdf, u);
  // The guide cell of u, checked against the stored boundaries (u * G may round across one).
  int k = std::min(int(u * float(cells)), cells - 1);
  while (k > 0 && u < guideBoundary(k, cells)) --k;
  while (k + 1 < cells && u >= guideBoundary(k + 1, cells)) ++k;
  // boundary_k <= u < boundary_k+1, so the first entry > u lies in [guide[k], guide[k + 1]].
  const auto first = cdf.begin() + guide[k];
  const auto last = cdf.begin() + std::min(guide[k + 1] + 1, int(cdf.size()));
  return sampleOfUpperBound(cdf, std::upper_bound(first, last, u), u);
}

}  // namespace lacrima::detail
