// The welling source's rate over time; see WellingSource in liquid_tear.hpp.
#include <algorithm>

#include "lacrima/liquid/liquid_tear.hpp"

namespace lacrima {

namespace {

// The keyed rate at t, ignoring the welling window.
double keyedRate(const std::vector<std::pair<double, double>>& keys, double t) {
  if (t <= keys.front().first) return keys.front().second;
  if (t >= keys.back().first) return keys.back().second;
  const auto after = std::upper_bound(keys.begin(), keys.end(), t,
                                      [](double value, const std::pair<double, double>& key) { return value < key.first; });
  const auto& [t1, r1] = *after;
  const auto& [t0, r0] = *(after - 1);
  return r0 + (r1 - r0) * (t - t0) / (t1 - t0);
}

}  // namespace

double WellingSource::rateAt(double t) const {
  if (!(t >= start && t < end)) return 0.0;
  return rateKeys.empty() ? rate : keyedRate(rateKeys, t);
}

double WellingSource::volumeBetween(double t0, double t1) const {
  const double a = std::max(t0, start), b = std::min(t1, end);
  if (!(b > a)) return 0.0;
  if (rateKeys.empty()) return rate * (b - a);
  // The rate is straight between consecutive breakpoints (a, the key times inside, b): trapezoids.
  double volume = 0.0, from = a;
  for (const auto& key : rateKeys) {
    if (key.first <= a) continue;
    if (key.first >= b) break;
    volume += 0.5 * (keyedRate(rateKeys, from) + keyedRate(rateKeys, key.first)) * (key.first - from);
    from = key.first;
  }
  return volume + 0.5 * (keyedRate(rateKeys, from) + keyedRate(rateKeys, b)) * (b - from);
}

}  // namespace lacrima
