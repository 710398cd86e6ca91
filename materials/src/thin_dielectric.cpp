// Thin dielectric sheet; see thin_dielectric.hpp for the model and its source.
#include "lacrima/materials/thin_dielectric.hpp"

#include <cmath>

#include "lacrima/materials/fresnel.hpp"

namespace lacrima {

ThinDielectricBsdf::ThinDielectricBsdf(float ior, const Color& tint) : ior_(ior), tint_(tint) {}

float ThinDielectricBsdf::reflectance(float cosTheta) const {
  const float r0 = fresnelDielectric(std::abs(cosTheta), ior_);
  if (r0 >= 1.0f) return 1.0f;  // only at grazing rounding limits: a slab in air has no TIR
  const float t0 = 1.0f - r0;
  return r0 + t0 * t0 * r0 / (1.0f - r0 * r0);
}

Color ThinDielectricBsdf::eval(const Vec3&, const Vec3&) const { return Color::Zero(); }

float ThinDielectricBsdf::pdf(const Vec3&, const Vec3&) const { return 0.0f; }

Color ThinDielectricBsdf::straightTransmittance(const Vec3& wo) const { return tint_ * (1.0f - reflectance(wo.z())); }

std::optional<BsdfSample> ThinDielectricBsdf::sample(const Vec3& wo, float uLobe, const Vec2&) const {
  if (wo.z() == 0.0f) return std::nullopt;
  const float R = reflectance(wo.z()), T = 1.0f - R;
  if (uLobe < R || T <= 0.0f) return specularReflectionSample(wo, R);
  BsdfSample s;
  s.specular = true;
  s.wi = -wo;
  s.f = tint_ * (T / std::abs(s.wi.z()));
  s.pdf = T;
  s.transmitted = true;
  s.eta = 1.0f;
  return s;
}

}  // namespace lacrima
