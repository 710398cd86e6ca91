#pragma once
// Shading normals (interpolated, normal-mapped, perturbed by pores) disagree with the geometric
// surface near silhouettes and on coarse tessellation. Two rules keep that from leaking light
// through surfaces or darkening them (Veach 1997, section 5.3): a shading normal is taken on its
// geometric normal's side, and a direction counts only where the geometric surface and the
// shading frame agree on whether it reflects or goes through.
#include "lacrima/base/math.hpp"

namespace lacrima {

// The shading normal flipped, when needed, onto the geometric normal's side.
template <typename Vector>
Vector onGeometricSide(const Vector& shadingNormal, const Vector& geometricNormal) {
  return shadingNormal.dot(geometricNormal) < 0 ? Vector(-shadingNormal) : shadingNormal;
}

// Whether wi leaves on wo's side of the geometric surface (reflects) rather than through it.
inline bool reflectsGeometrically(const Vec3& wo, const Vec3& wi, const Vec3& geometricNormal) {
  return wi.dot(geometricNormal) * wo.dot(geometricNormal) > 0.0f;
}

// The same in the shading frame, from the local directions' z (the shading normal's axis).
inline bool reflectsInShadingFrame(const Vec3& woLocal, const Vec3& wiLocal) { return wiLocal.z() * woLocal.z() > 0.0f; }

}  // namespace lacrima
