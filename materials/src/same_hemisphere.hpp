#pragma once
// Directions in a BSDF's local shading frame (z along the normal).
#include "lacrima/base/math.hpp"

namespace lacrima {

// Both directions above the surface: the only case a reflection-only lobe is non-zero.
inline bool bothAbove(const Vec3& wo, const Vec3& wi) { return wo.z() > 0.0f && wi.z() > 0.0f; }

}  // namespace lacrima
