#pragma once
// The median of a set of timings, as the bench reports quote them (the machine is noisy, so a
// median rather than a mean). NaN for no values.
#include <algorithm>
#include <cmath>
#include <vector>

namespace lacrima::cli {

inline double median(std::vector<double> values) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace lacrima::cli
