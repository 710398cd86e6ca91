// Dielectric Fresnel and reflection/refraction directions; see fresnel.hpp for conventions.
#include "lacrima/materials/fresnel.hpp"

namespace lacrima {

float fresnelDielectric(float cosThetaI, float eta) {
  cosThetaI = std::clamp(cosThetaI, -1.0f, 1.0f);
  // Arriving from inside: swap the media (pbrt-v4 FrDielectric).
  if (cosThetaI < 0.0f) {
    eta = 1.0f / eta;
    cosThetaI = -cosThetaI;
  }
  // Snell's law, sin(theta_t) = sin(theta_i) / eta (Hecht §4.4).
  const float sin2ThetaI = 1.0f - cosThetaI * cosThetaI;
  const float sin2ThetaT = sin2ThetaI / (eta * eta);
  if (sin2ThetaT >= 1.0f) return 1.0f;  // total internal reflection
  const float cosThetaT = safeSqrt(1.0f - sin2ThetaT);
  // Fresnel amplitude coefficients for parallel and perpendicular polarisation (Hecht §4.6.2).
  const float rParallel = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
  const float rPerpendicular = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
  // Unpolarised light: the mean of both reflectances (pbrt-v4 FrDielectric).
  return 0.5f * (rParallel * rParallel + rPerpendicular * rPerpendicular);
}

Vec3 reflect(const Vec3& w, const Vec3& n) {
  // w_r = -w + 2 (w.n) n (pbrt-v4 Reflect).
  return -w + 2.0f * w.dot(n) * n;
}

std::optional<Refraction> refract(const Vec3& wi, const Vec3& n, float eta) {
  float cosThetaI = n.dot(wi);
  Vec3 normal = n;
  // Arriving from inside: swap the media and flip the normal to the side of wi (pbrt-v4 Refract).
  if (cosThetaI < 0.0f) {
    eta = 1.0f / eta;
    cosThetaI = -cosThetaI;
    normal = -n;
  }
  // Snell's law (Hecht §4.4).
  const float sin2ThetaI = std::max(0.0f, 1.0f - cosThetaI * cosThetaI);
  const float sin2ThetaT = sin2ThetaI / (eta * eta);
  if (sin2ThetaT >= 1.0f) return std::nullopt;  // total internal reflection
  const float cosThetaT = safeSqrt(1.0f - sin2ThetaT);
  // w_t = -w_i / eta + (cos_i / eta - cos_t) n (pbrt-v4 Refract).
  const Vec3 wt = -wi / eta + (cosThetaI / eta - cosThetaT) * normal;
  return Refraction{wt, eta};
}

}  // namespace lacrima
