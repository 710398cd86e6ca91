#pragma once
#include <algorithm>

#include "lacrima/base/math.hpp"

namespace lacrima {

// Ray origins are pushed off the surface along the geometric normal, on the side the new ray
// leaves towards; the offset scales with the coordinates' magnitude (float spacing).
inline Vec3 offsetOrigin(const Vec3& position, const Vec3& geometricNormal, const Vec3& direction) {
  const float scale = 1e-4f * std::max(0.05f, position.cwiseAbs().maxCoeff());
  return position + (direction.dot(geometricNormal) > 0.0f ? scale : -scale) * geometricNormal;
}

}  // namespace lacrima
