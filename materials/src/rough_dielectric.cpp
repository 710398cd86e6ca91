// Rough dielectric BSDF; see rough_dielectric.hpp for parameters and sources.
#include "lacrima/materials/rough_dielectric.hpp"

#include "lacrima/materials/fresnel.hpp"

namespace lacrima {

RoughDielectricBsdf::RoughDielectricBsdf(const RoughDielectricParams& params)
    : ior_(params.ior), distribution_(roughnessToAlpha(params.roughness)), tint_(params.tint) {}

std::optional<RoughDielectricBsdf::HalfVector> RoughDielectricBsdf::halfVector(const Vec3& wo,
                                                                                const Vec3& wi) const {
  const float cosO = wo.z();
  const float cosI = wi.z();
  if (cosO == 0.0f || cosI == 0.0f) return std::nullopt;
  const bool reflect = cosO * cosI > 0.0f;
  // etap = n_i / n_o; the normal points to the outside, whose IOR is 1 relative to eta.
  const float etap = reflect ? 1.0f : (cosO > 0.0f ? ior_ : 1.0f / ior_);
  // h_r = normalize(wo + wi) (Walter 2007 eq. 13); h_t ~ -(n_i i + n_o o) (Walter 2007 eq. 16).
  Vec3 wm = wi * etap + wo;
  const float len2 = wm.squaredNorm();
  if (len2 == 0.0f) return std::nullopt;
  wm /= std::sqrt(len2);
  if (wm.z() < 0.0f) wm = -wm;
  // Discard microfacets seen from their back side by wo or wi (pbrt-v4 DielectricBxDF).
  if (wm.dot(wi) * cosI <= 0.0f || wm.dot(wo) * cosO <= 0.0f) return std::nullopt;
  return HalfVector{wm, etap, reflect};
}

float RoughDielectricBsdf::reflectionF(const Vec3& wo, const Vec3& wi, const Vec3& wm, float F) const {
  // f_r = D G F / (4 |cos_o cos_i|) (Walter 2007 eq. 20).
  return distribution_.D(wm) * distribution_.G(wo, wi) * F / std::abs(4.0f * wo.z() * wi.z());
}

float RoughDielectricBsdf::transmissionF(const Vec3& wo, const Vec3& wi, const Vec3& wm, float etap,
                                         float F) const {
  // f_t = |i.h||o.h| / (|i.n||o.n|) * n_o^2 (1-F) G D / (n_i (i.h) + n_o (o.h))^2 (Walter 2007 eq. 21),
  // divided through by n_i^2: the n_o^2/n_i^2 = 1/etap^2 factor is the radiance scaling.
  const float wiDotWm = wi.dot(wm);
  const float woDotWm = wo.dot(wm);
  const float sqrtDenom = wiDotWm + woDotWm / etap;
  const float denom = sqrtDenom * sqrtDenom * wi.z() * wo.z();
  if (denom == 0.0f) return 0.0f;
  const float ft = distribution_.D(wm) * distribution_.G(wo, wi) * (1.0f - F) * std::abs(wiDotWm * woDotWm / denom);
  return ft / (etap * etap);
}

float RoughDielectricBsdf::reflectionPdf(const Vec3& wo, const Vec3& wm, float F) const {
  // Visible normal density times the reflection Jacobian 1 / (4 |wo.wm|) (Heitz 2018 eq. 1,
  // Walter 2007 eq. 14), times the probability F of choosing reflection.
  return distribution_.visibleD(wo, wm) / (4.0f * std::abs(wo.dot(wm))) * F;
}

float RoughDielectricBsdf::transmissionPdf(const Vec3& wo, const Vec3& wi, const Vec3& wm, float etap,
                                           float F) const {
  // Refraction Jacobian dwm/dwi = |wi.wm| / (wi.wm + wo.wm / etap)^2 (Walter 2007 eq. 17 divided
  // through by n_i^2), times the probability 1 - F of choosing refraction.
  const float sqrtDenom = wi.dot(wm) + wo.dot(wm) / etap;
  const float denom = sqrtDenom * sqrtDenom;
  if (denom == 0.0f) return 0.0f;
  const float dwmDwi = std::abs(wi.dot(wm)) / denom;
  return distribution_.visibleD(wo, wm) * dwmDwi * (1.0f - F);
}

Color RoughDielectricBsdf::eval(const Vec3& wo, const Vec3& wi) const {
  const auto h = halfVector(wo, wi);
  if (!h) return Color::Zero();
  const float F = fresnelDielectric(wo.dot(h->wm), ior_);
  if (h->reflect) return Color::Constant(reflectionF(wo, wi, h->wm, F));
  return tint_ * transmissionF(wo, wi, h->wm, h->etap, F);
}

float RoughDielectricBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  const auto h = halfVector(wo, wi);
  if (!h) return 0.0f;
  const float F = fresnelDielectric(wo.dot(h->wm), ior_);
  if (h->reflect) return reflectionPdf(wo, h->wm, F);
  return transmissionPdf(wo, wi, h->wm, h->etap, F);
}

std::optional<BsdfSample> RoughDielectricBsdf::sample(const Vec3& wo, float uLobe, const Vec2& u) const {
  if (wo.z() == 0.0f) return std::nullopt;
  // Microfacet normal visible from wo (Heitz 2018), then Fresnel picks the lobe (pbrt-v4 DielectricBxDF).
  const Vec3 wm = distribution_.sampleVisibleNormal(wo, u);
  const float F = fresnelDielectric(wo.dot(wm), ior_);
  BsdfSample s;
  if (uLobe < F) {
    s.wi = reflect(wo, wm);
    if (!sameHemisphere(wo, s.wi)) return std::nullopt;  // reflected through the macro surface
    s.glossy = true;
    s.f = Color::Constant(reflectionF(wo, s.wi, wm, F));
    s.pdf = reflectionPdf(wo, wm, F);
  } else {
    const auto refraction = refract(wo, wm, ior_);
    if (!refraction) return std::nullopt;  // unreachable when F < 1, kept for rounding
    s.wi = refraction->wt;
    if (sameHemisphere(wo, s.wi) || s.wi.z() == 0.0f) return std::nullopt;  // refracted back up
    s.f = tint_ * transmissionF(wo, s.wi, wm, refraction->etap, F);
    s.pdf = transmissionPdf(wo, s.wi, wm, refraction->etap, F);
    s.transmitted = true;
    s.eta = refraction->etap;
  }
  if (!(s.pdf > 0.0f)) return std::nullopt;
  return s;
}

}  // namespace lacrima
