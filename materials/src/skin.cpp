// Skin BSDF; see skin.hpp for parameters and sources.
#include "lacrima/materials/skin.hpp"

#include <algorithm>

#include "lacrima/materials/fresnel.hpp"
#include "lacrima/materials/pores.hpp"
#include "lacrima/materials/sampling.hpp"
#include "same_hemisphere.hpp"

namespace lacrima {

namespace {

// Half vector of a reflection, wm = normalize(wo + wi) (Walter 2007 eq. 13). Nothing when degenerate.
std::optional<Vec3> reflectionHalfVector(const Vec3& wo, const Vec3& wi) {
  const Vec3 h = wo + wi;
  const float len2 = h.squaredNorm();
  if (len2 == 0.0f) return std::nullopt;
  return h / std::sqrt(len2);
}

}  // namespace

float fresnelHemisphericalReflectance(float eta) {
  // A few entries per thread: a frame's skin, sclera and lash materials (and a wet film over skin)
  // each ask for their own index on every hit, and skin under a drop for its index relative to the
  // water (integrator.cpp, skinAtHit); one entry would integrate again at each switch, and with
  // more indices than entries the round-robin eviction would integrate on nearly every hit.
  constexpr int kEntries = 8;
  thread_local float cachedEta[kEntries] = {-1.0f, -1.0f, -1.0f, -1.0f, -1.0f, -1.0f, -1.0f, -1.0f};
  thread_local float cachedValue[kEntries] = {};
  thread_local int nextEntry = 0;
  for (int e = 0; e < kEntries; ++e)
    if (eta == cachedEta[e]) return cachedValue[e];
  // Fbar = 2 integral_0^1 F(mu) mu dmu = integral_0^1 F(sqrt(t)) dt with t = mu^2 (substitution);
  // midpoint rule, 4096 cells (error ~1e-6, the integrand is smooth except near t = 0).
  constexpr int kCells = 4096;
  double sum = 0.0;
  for (int i = 0; i < kCells; ++i) {
    const double t = (i + 0.5) / kCells;
    sum += fresnelDielectric(float(std::sqrt(t)), eta);
  }
  const int entry = nextEntry;
  nextEntry = (nextEntry + 1) % kEntries;
  cachedEta[entry] = eta;
  cachedValue[entry] = float(sum / kCells);
  return cachedValue[entry];
}

SkinBsdf::SkinBsdf(const SkinParams& params, std::optional<Vec3> reliefGradientHere)
    : albedo_(params.albedo.max(0.0f).min(kMaxSkinAlbedo)),  // energy margin, see skin.hpp
      ior_(params.ior),
      sharp_(roughnessToAlpha(params.roughness)),
      broad_(roughnessToAlpha(params.roughness2)),
      lobeMix_(std::clamp(params.lobeMix, 0.0f, 1.0f)),
      diffuseNorm_(kInvPi / (1.0f - fresnelHemisphericalReflectance(params.ior))),
      relief_{params.poreScale, params.poreDepth > 0.0f && params.poreScale > 0.0f ? params.poreDepth : 0.0f,
              params.furrowScale, params.furrowDepth > 0.0f && params.furrowScale > 0.0f ? params.furrowDepth : 0.0f},
      reliefGradientHere_(reliefGradientHere),
      hasDiffuseLobe_(!params.subsurface) {}

Vec3 SkinBsdf::perturbShadingNormal(const Vec3& position, const Vec3& ns, const Vec3& ng) const {
  if (relief_.poreDepth == 0.0f && relief_.furrowDepth == 0.0f) return ns;
  const Vec3 gradient = reliefGradientHere_ ? *reliefGradientHere_ : skinReliefAt(relief_, position).gradient;
  return tiltNormalBySlope(gradient, ns, ng);
}

float SkinBsdf::specularF(const Vec3& wo, const Vec3& wi) const {
  const auto wm = reflectionHalfVector(wo, wi);
  if (!wm) return 0.0f;
  // f_r = D G F / (4 cos_o cos_i) per lobe (Walter 2007 eq. 20); the lobes share wm and F.
  const float F = fresnelDielectric(wo.dot(*wm), ior_);
  float dg = sharp_.D(*wm) * sharp_.G(wo, wi);
  if (lobeMix_ > 0.0f) dg = (1.0f - lobeMix_) * dg + lobeMix_ * (broad_.D(*wm) * broad_.G(wo, wi));
  return dg * F / (4.0f * wo.z() * wi.z());
}

float SkinBsdf::specularPdf(const Vec3& wo, const Vec3& wi) const {
  const auto wm = reflectionHalfVector(wo, wi);
  if (!wm) return 0.0f;
  // pdf(wi) = D_wo(wm) / (4 |wo.wm|): visible normals times the reflection Jacobian
  // (Heitz 2018 eq. 1; Walter 2007 eq. 14); the lobe mixture mixes the visible-normal densities.
  float visible = sharp_.visibleD(wo, *wm);
  if (lobeMix_ > 0.0f) visible = (1.0f - lobeMix_) * visible + lobeMix_ * broad_.visibleD(wo, *wm);
  return visible / (4.0f * std::abs(wo.dot(*wm)));
}

// Fresnel-weighted Lambertian base, reciprocal form (Shirley et al. 1997), see skin.hpp.
Color SkinBsdf::diffuseF(const Vec3& wo, const Vec3& wi) const {
  const float transO = 1.0f - fresnelDielectric(wo.z(), ior_);
  const float transI = 1.0f - fresnelDielectric(wi.z(), ior_);
  return albedo_ * (diffuseNorm_ * transO * transI);
}

Color SkinBsdf::eval(const Vec3& wo, const Vec3& wi) const {
  if (!bothAbove(wo, wi)) return Color::Zero();
  if (!hasDiffuseLobe_) return Color::Constant(specularF(wo, wi));
  return diffuseF(wo, wi) + Color::Constant(specularF(wo, wi));
}

BsdfLobes SkinBsdf::evalLobes(const Vec3& wo, const Vec3& wi) const {
  BsdfLobes lobes;
  if (!bothAbove(wo, wi)) return lobes;
  if (hasDiffuseLobe_) lobes.diffuse = diffuseF(wo, wi);
  lobes.glossy = Color::Constant(specularF(wo, wi));
  return lobes;
}

float SkinBsdf::specularProbability(const Vec3& wo) const {
  // Ratio of the lobes' approximate albedos, F(cos_o) vs lum(albedo)(1 - F(cos_o)), clamped so
  // that neither lobe is starved.
  const float fo = fresnelDielectric(wo.z(), ior_);
  const float diffuseEstimate = luminance(albedo_) * (1.0f - fo);
  const float p = fo / std::max(fo + diffuseEstimate, 1e-6f);
  return std::clamp(p, 0.1f, 0.9f);
}

float SkinBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  if (!bothAbove(wo, wi)) return 0.0f;
  if (!hasDiffuseLobe_) return specularPdf(wo, wi);
  const float pSpec = specularProbability(wo);
  // One-sample mixture density (Veach 1997 ch. 9, one-sample model).
  return pSpec * specularPdf(wo, wi) + (1.0f - pSpec) * cosineHemispherePdf(wi.z());
}

std::optional<BsdfSample> SkinBsdf::sample(const Vec3& wo, float uLobe, const Vec2& u) const {
  if (wo.z() <= 0.0f) return std::nullopt;
  // Without the diffuse lobe (subsurface): always specular, uLobe / 1 picks the lobe.
  const float pSpec = hasDiffuseLobe_ ? specularProbability(wo) : 1.0f;
  Vec3 wi;
  const bool glossy = uLobe < pSpec;
  if (glossy) {
    // Specular: pick a lobe (the broad one with probability w, reusing uLobe rescaled to [0, 1)),
    // sample a visible normal and mirror wo about it (Heitz 2018).
    const bool broad = lobeMix_ > 0.0f && uLobe / pSpec < lobeMix_;
    const Vec3 wm = (broad ? broad_ : sharp_).sampleVisibleNormal(wo, u);
    wi = reflect(wo, wm);
  } else {
    wi = sampleCosineHemisphere(u);
  }
  return mixtureReflectionSample(*this, wo, wi, glossy);
}

}  // namespace lacrima
