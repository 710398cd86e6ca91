#pragma once
// The distance beyond which a depth correspondence is dropped as an outlier (an occluded model
// point pairing with the surface in front of it: a cheek behind the nose, a lid's rim on the
// eyeball): three times the median pair distance, at least `minimum`. Shared by the rigid and the
// non-rigid stage.
#include <algorithm>
#include <vector>

namespace lacrima::tracking {

inline double robustCut(std::vector<double> distances, double minimum) {
  if (distances.empty()) return minimum;
  std::nth_element(distances.begin(), distances.begin() + long(distances.size() / 2), distances.end());
  return std::max(minimum, 3.0 * distances[distances.size() / 2]);
}

}  // namespace lacrima::tracking
