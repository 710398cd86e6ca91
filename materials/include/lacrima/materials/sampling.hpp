#pragma once
// Small sample warps shared by the BSDFs. u is a point of [0,1)^2.
//
// Sources: Shirley & Chiu 1997, "A Low Distortion Map Between Disk and Square" (concentric map);
// Malley's method (pbrt-v4 SampleCosineHemisphere): project a uniform disk point up to the hemisphere to get a
// cosine-weighted direction, pdf = cos(theta) / pi.
#include "lacrima/base/math.hpp"

namespace lacrima {

// Uniform point on the unit disk (Shirley & Chiu 1997 concentric map).
Vec2 sampleUniformDiskConcentric(const Vec2& u);

// Cosine-weighted direction on the upper hemisphere z > 0 (Malley's method).
Vec3 sampleCosineHemisphere(const Vec2& u);

// Uniform direction on the unit sphere, density 1 / (4 pi) (pbrt-v4 SampleUniformSphere).
Vec3 sampleUniformSphere(const Vec2& u);

// Density of sampleCosineHemisphere: cos(theta) / pi (pbrt-v4 SampleCosineHemisphere).
inline float cosineHemispherePdf(float cosTheta) { return std::max(0.0f, cosTheta) * kInvPi; }

}  // namespace lacrima
