// Lambertian BSDF; see diffuse.hpp for parameters and sources.
#include "lacrima/materials/diffuse.hpp"

#include "lacrima/materials/sampling.hpp"
#include "same_hemisphere.hpp"

namespace lacrima {

DiffuseBsdf::DiffuseBsdf(const DiffuseParams& params) : albedo_(params.albedo) {}

Color DiffuseBsdf::eval(const Vec3& wo, const Vec3& wi) const {
  if (!bothAbove(wo, wi)) return Color::Zero();
  // f = albedo / pi (pbrt-v4 DiffuseBxDF).
  return albedo_ * kInvPi;
}

float DiffuseBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  if (!bothAbove(wo, wi)) return 0.0f;
  return cosineHemispherePdf(wi.z());
}

std::optional<BsdfSample> DiffuseBsdf::sample(const Vec3& wo, float /*uLobe*/, const Vec2& u) const {
  if (wo.z() <= 0.0f) return std::nullopt;
  const Vec3 wi = sampleCosineHemisphere(u);
  const float pdf = cosineHemispherePdf(wi.z());
  if (pdf == 0.0f) return std::nullopt;  // exactly on the horizon
  BsdfSample s;
  s.wi = wi;
  s.f = albedo_ * kInvPi;
  s.pdf = pdf;
  return s;
}

}  // namespace lacrima
