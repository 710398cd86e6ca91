// Subsurface medium and exit lobe; see subsurface.hpp for the model and sources.
#include "lacrima/materials/subsurface.hpp"

#include <algorithm>

#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/sampling.hpp"
#include "lacrima/materials/skin.hpp"

namespace lacrima {

Color singleScatteringAlbedoFor(const Color& diffuseAlbedo) {
  Color result;
  for (int c = 0; c < 3; ++c) {
    const double A = std::clamp(double(diffuseAlbedo[c]), 0.0, 1.0);
    // The root s = sqrt(1 - a) of 0.139 s^2 - (1.139 + 1.17 A) s + (1 - A) = 0 (van de Hulst 1980).
    const double s = 4.09712 + 4.20863 * A - std::sqrt(9.59217 + 41.6808 * A + 17.7126 * A * A);
    result[c] = float(std::clamp(1.0 - s * s, 0.0, 1.0));
  }
  return result;
}

SubsurfaceMedium subsurfaceMedium(const SkinParams& skin, const SubsurfaceParams& subsurface) {
  return SubsurfaceMedium{subsurface.meanFreePath.inverse(), singleScatteringAlbedoFor(skin.albedo)};
}

SubsurfaceExitBsdf::SubsurfaceExitBsdf(float ior)
    : ior_(ior), norm_(kInvPi / (1.0f - fresnelHemisphericalReflectance(ior))) {}

Color SubsurfaceExitBsdf::eval(const Vec3& wo, const Vec3& wi) const {
  if (wo.z() <= 0.0f || wi.z() <= 0.0f) return Color::Zero();
  return Color::Constant(norm_ * (1.0f - fresnelDielectric(wi.z(), ior_)));
}

float SubsurfaceExitBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  return wo.z() > 0.0f ? cosineHemispherePdf(wi.z()) : 0.0f;
}

std::optional<BsdfSample> SubsurfaceExitBsdf::sample(const Vec3& wo, float /*uLobe*/, const Vec2& u) const {
  if (wo.z() <= 0.0f) return std::nullopt;
  BsdfSample s;
  s.wi = sampleCosineHemisphere(u);
  s.f = eval(wo, s.wi);
  s.pdf = cosineHemispherePdf(s.wi.z());
  if (s.pdf <= 0.0f) return std::nullopt;
  return s;
}

}  // namespace lacrima
