// Smooth dielectric BSDF; see smooth_dielectric.hpp for parameters and sources.
#include "lacrima/materials/smooth_dielectric.hpp"

#include "lacrima/materials/fresnel.hpp"

namespace lacrima {

SmoothDielectricBsdf::SmoothDielectricBsdf(const SmoothDielectricParams& params)
    : ior_(params.ior), tint_(params.tint) {}

Color SmoothDielectricBsdf::eval(const Vec3&, const Vec3&) const { return Color::Zero(); }

float SmoothDielectricBsdf::pdf(const Vec3&, const Vec3&) const { return 0.0f; }

Color SmoothDielectricBsdf::straightTransmittance(const Vec3& wo) const {
  // Fresnel transmission with the n^2 radiance scaling of the refraction lobe (pbrt-v4
  // DielectricBxDF, TransportMode::Radiance), evaluated as if the ray were not bent.
  const float T = 1.0f - fresnelDielectric(wo.z(), ior_);
  const float etap = wo.z() > 0.0f ? ior_ : 1.0f / ior_;
  return tint_ * (T / (etap * etap));
}

std::optional<BsdfSample> SmoothDielectricBsdf::sample(const Vec3& wo, float uLobe, const Vec2&) const {
  if (wo.z() == 0.0f) return std::nullopt;
  const Vec3 n(0.0f, 0.0f, 1.0f);
  const float R = fresnelDielectric(wo.z(), ior_);  // 1 under total internal reflection
  const float T = 1.0f - R;

  if (uLobe < R || T <= 0.0f) return specularReflectionSample(wo, R);  // the perfect mirror
  BsdfSample s;
  s.specular = true;
  const auto refraction = refract(wo, n, ior_);
  if (!refraction || refraction->wt.z() == 0.0f) return std::nullopt;  // only at rounding limits
  // Refraction, f = T / |cos_i|, radiance scaled by 1/etap^2 (pbrt-v4 DielectricBxDF, TransportMode::Radiance).
  const float etap = refraction->etap;
  s.wi = refraction->wt;
  s.f = tint_ * (T / (std::abs(s.wi.z()) * etap * etap));
  s.pdf = T;
  s.transmitted = true;
  s.eta = etap;
  return s;
}

}  // namespace lacrima
