// Wet skin BSDF; see wet_skin.hpp for the model and sources.
#include "lacrima/materials/wet_skin.hpp"

#include <algorithm>
#include <cmath>

#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/sampling.hpp"
#include "same_hemisphere.hpp"

namespace lacrima {

namespace {

// Fwbar of the film's top seen from air: computed once (the quadrature's per-thread cache holds
// one index only, and the skin's index would evict it on every hit).
float waterHemisphericalReflectance() {
  static const float value = fresnelHemisphericalReflectance(kWaterIor);
  return value;
}

// Lekner & Dorf's multiple-reflection sum (wet_skin.hpp): a base of albedo a under a top that
// sends back the fraction p of the light the base scatters up.
Color trappedAlbedo(const Color& albedo, float p) {
  return (albedo * (1.0f - p)).cwiseQuotient(Color::Ones() - p * albedo);
}

// Its inverse: the albedo a0 the base has without that top, from the albedo a seen through it
// (a = a0 (1 - p) / (1 - p a0) solved for a0).
Color untrappedAlbedo(const Color& albedo, float p) {
  return albedo.cwiseQuotient(Color::Constant(1.0f - p) + p * albedo);
}

}  // namespace

float wetFilmCoverage(float filmThickness) {
  if (!(filmThickness > 0.0f)) return 0.0f;
  return 1.0f - std::exp(-filmThickness / kWetFilmCoverageThickness);
}

float diffuseTrapping(float outerFbar, float n) { return 1.0f - (1.0f - outerFbar) / (n * n); }

Color leknerDorfWetAlbedo(const Color& albedo, float n) {
  return trappedAlbedo(albedo, diffuseTrapping(fresnelHemisphericalReflectance(n), n));
}

Color wetSkinBaseAlbedo(const Color& dryAlbedo, float skinIor, float filmIor, float filmFbar) {
  // The skin's own surface traps with its index; the film's top with the water's Fresnel but the
  // skin's escape cone (Snell's invariant across parallel layers; wet_skin.hpp).
  const float skinFbar = fresnelHemisphericalReflectance(skinIor);
  const float filmTrapping = diffuseTrapping(filmFbar, std::max(skinIor, filmIor));
  return trappedAlbedo(untrappedAlbedo(dryAlbedo, diffuseTrapping(skinFbar, skinIor)), filmTrapping);
}

WetSkinBsdf::WetSkinBsdf(const SkinBsdf& skin, float coverage)
    : skin_(skin),
      coverage_(std::clamp(coverage, 0.0f, 1.0f)),
      coat_(roughnessToAlpha(kWetCoatRoughness)),
      wetAlbedo_(Color::Zero()),
      underNorm_(kInvPi / (1.0f - waterHemisphericalReflectance())),
      hasUnder_(skin.hasDiffuseLobe()) {
  if (coverage_ == 0.0f) return;  // the skin alone: nothing wet to set up
  wetAlbedo_ = wetSkinBaseAlbedo(skin.albedo(), skin.ior(), kWaterIor, waterHemisphericalReflectance())
                   .cwiseMin(kMaxSkinAlbedo);  // the skin's energy margin (wet_skin.hpp, Energy)
}

Vec3 WetSkinBsdf::perturbShadingNormal(const Vec3& position, const Vec3& ns, const Vec3& ng) const {
  const Vec3 pores = skin_.perturbShadingNormal(position, ns, ng);
  if (coverage_ == 0.0f) return pores;
  // The film fills the pores: blend back towards the smooth normal (both unit, on ng's side).
  const Vec3 blended = (1.0f - coverage_) * pores + coverage_ * ns;
  const float length = blended.norm();
  return length > 1e-6f ? Vec3(blended / length) : ns;
}

Color WetSkinBsdf::albedo() const {
  if (coverage_ == 0.0f) return skin_.albedo();
  return (1.0f - coverage_) * skin_.albedo() + coverage_ * wetAlbedo_;
}

float WetSkinBsdf::coatShare(const Vec3& wo) const {
  // Ratio of the wet layer's approximate albedos, coat Fw(cos_o) vs base lum(a_wet)(1 - Fw).
  const float fo = fresnelDielectric(wo.z(), kWaterIor);
  const float underEstimate = luminance(wetAlbedo_) * (1.0f - fo);
  return std::clamp(fo / std::max(fo + underEstimate, 1e-6f), 0.1f, 0.9f);
}

float WetSkinBsdf::coatProbability(const Vec3& wo) const { return hasUnder_ ? coatShare(wo) : 1.0f; }

float WetSkinBsdf::belowTransmission(const Vec3& wo) const {
  const float dry = 1.0f - fresnelDielectric(wo.z(), skin_.ior());
  if (coverage_ == 0.0f) return dry;
  return (1.0f - coverage_) * dry + coverage_ * (1.0f - fresnelDielectric(wo.z(), kWaterIor));
}

float WetSkinBsdf::belowProbability(const Vec3& wo) const {
  const float dry = 1.0f - skin_.specularProbability(wo);
  if (coverage_ == 0.0f) return dry;
  return (1.0f - coverage_) * dry + coverage_ * (1.0f - coatShare(wo));
}

BsdfLobes WetSkinBsdf::wetLobes(const Vec3& wo, const Vec3& wi) const {
  BsdfLobes lobes;
  if (hasUnder_) {  // the film's base, through its top twice (wet_skin.hpp, f_under)
    const float transO = 1.0f - fresnelDielectric(wo.z(), kWaterIor);
    const float transI = 1.0f - fresnelDielectric(wi.z(), kWaterIor);
    lobes.diffuse = wetAlbedo_ * (underNorm_ * transO * transI);
  }
  // The film's top: GGX reflection, f = D G F / (4 cos_o cos_i) (Walter 2007 eq. 20).
  const Vec3 h = wo + wi;
  if (h.squaredNorm() > 0.0f) {
    const Vec3 wm = h.normalized();
    const float F = fresnelDielectric(wo.dot(wm), kWaterIor);
    lobes.glossy = Color::Constant(coat_.D(wm) * coat_.G(wo, wi) * F / (4.0f * wo.z() * wi.z()));
  }
  return lobes;
}

Color WetSkinBsdf::wetEval(const Vec3& wo, const Vec3& wi) const {
  const BsdfLobes wet = wetLobes(wo, wi);
  return wet.diffuse + wet.glossy;
}

float WetSkinBsdf::wetPdf(const Vec3& wo, const Vec3& wi) const {
  const float pCoat = coatProbability(wo);
  float coatPdf = 0.0f;
  const Vec3 h = wo + wi;
  if (h.squaredNorm() > 0.0f) {
    const Vec3 wm = h.normalized();
    // Visible normals times the reflection Jacobian (Heitz 2018 eq. 1; Walter 2007 eq. 14).
    coatPdf = coat_.visibleD(wo, wm) / (4.0f * std::abs(wo.dot(wm)));
  }
  return pCoat * coatPdf + (1.0f - pCoat) * cosineHemispherePdf(wi.z());
}

Color WetSkinBsdf::eval(const Vec3& wo, const Vec3& wi) const {
  if (coverage_ == 0.0f) return skin_.eval(wo, wi);
  if (!bothAbove(wo, wi)) return Color::Zero();
  const Color wet = wetEval(wo, wi);
  if (coverage_ == 1.0f) return wet;
  return (1.0f - coverage_) * skin_.eval(wo, wi) + coverage_ * wet;
}

BsdfLobes WetSkinBsdf::evalLobes(const Vec3& wo, const Vec3& wi) const {
  if (coverage_ == 0.0f) return skin_.evalLobes(wo, wi);
  if (!bothAbove(wo, wi)) return {};
  const BsdfLobes wet = wetLobes(wo, wi);
  if (coverage_ == 1.0f) return wet;
  const BsdfLobes dry = skin_.evalLobes(wo, wi);
  const float c = coverage_;
  return {(1.0f - c) * dry.diffuse + c * wet.diffuse, (1.0f - c) * dry.glossy + c * wet.glossy, Color::Zero()};
}

float WetSkinBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  if (coverage_ == 0.0f) return skin_.pdf(wo, wi);
  if (!bothAbove(wo, wi)) return 0.0f;
  // One-sample mixture density (Veach 1997 ch. 9): the wet layer with probability c.
  const float wet = wetPdf(wo, wi);
  if (coverage_ == 1.0f) return wet;
  return (1.0f - coverage_) * skin_.pdf(wo, wi) + coverage_ * wet;
}

std::optional<BsdfSample> WetSkinBsdf::sample(const Vec3& wo, float uLobe, const Vec2& u) const {
  if (coverage_ == 0.0f) return skin_.sample(wo, uLobe, u);
  if (wo.z() <= 0.0f) return std::nullopt;
  Vec3 wi;
  bool glossy;
  if (uLobe < coverage_) {
    const float uWet = uLobe / coverage_;  // rescaled to [0, 1)
    glossy = uWet < coatProbability(wo);
    wi = glossy ? reflect(wo, coat_.sampleVisibleNormal(wo, u)) : sampleCosineHemisphere(u);
  } else {
    const float uSkin = std::min((uLobe - coverage_) / (1.0f - coverage_), 0.99999994f);
    const auto s = skin_.sample(wo, uSkin, u);
    if (!s) return std::nullopt;
    wi = s->wi;
    glossy = s->glossy;
  }
  return mixtureReflectionSample(*this, wo, wi, glossy);
}

}  // namespace lacrima
