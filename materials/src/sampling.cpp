// Sample warps; see sampling.hpp.
#include "lacrima/materials/sampling.hpp"

namespace lacrima {

Vec2 sampleUniformDiskConcentric(const Vec2& u) {
  // Map u to [-1,1]^2, then squares to concentric rings (Shirley & Chiu 1997).
  const Vec2 uo = 2.0f * u - Vec2(1.0f, 1.0f);
  if (uo.x() == 0.0f && uo.y() == 0.0f) return Vec2(0.0f, 0.0f);
  float r;
  float theta;
  if (std::abs(uo.x()) > std::abs(uo.y())) {
    r = uo.x();
    theta = (kPi / 4.0f) * (uo.y() / uo.x());
  } else {
    r = uo.y();
    theta = kPi / 2.0f - (kPi / 4.0f) * (uo.x() / uo.y());
  }
  return r * Vec2(std::cos(theta), std::sin(theta));
}

Vec3 sampleCosineHemisphere(const Vec2& u) {
  // Malley's method: z = sqrt(1 - x^2 - y^2) above a uniform disk point (pbrt-v4 SampleCosineHemisphere).
  const Vec2 d = sampleUniformDiskConcentric(u);
  return Vec3(d.x(), d.y(), safeSqrt(1.0f - d.x() * d.x() - d.y() * d.y()));
}

Vec3 sampleUniformSphere(const Vec2& u) {
  // z uniform in [-1, 1] (Archimedes' hat-box theorem), phi uniform (pbrt-v4 SampleUniformSphere).
  const float z = 1.0f - 2.0f * u.x();
  const float r = safeSqrt(1.0f - z * z);
  const float phi = 2.0f * kPi * u.y();
  return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

}  // namespace lacrima
