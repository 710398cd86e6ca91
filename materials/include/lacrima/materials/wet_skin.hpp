#pragma once
// Wet skin: the skin BSDF (skin.hpp) partly covered by a thin water film (a tear's trail; issue 5
// "Wet skin"). The renderer builds one per hit from the film thickness there (MeshInstance::wetness).
//
// Coverage: c = 1 - exp(-d / d0), d = film thickness, d0 = kWetFilmCoverageThickness = 2 um
// (modelling choice: a film thinner than a few micrometres breaks up into patches on the skin's
// micro-relief, so its covered fraction grows with d; a 20 um trail covers > 99.99%).
//
// f(wo, wi) = (1 - c) f_skin + c f_wet, both zero unless wo and wi are above the surface:
//   f_wet = f_coat + f_under
//   f_coat  = D(wm) G2(wo, wi) Fw(wo.wm) / (4 cos_o cos_i): the film's air-water interface, a GGX
//             lobe (Walter et al. 2007 eq. 20) with roughness kWetCoatRoughness = 0.1 (alpha 0.01;
//             modelling choice: the film drapes over the skin's relief, so it is sharp but not a
//             mirror, and a finite lobe keeps light sampling and MIS working), water index 1.337.
//   f_under = a_wet / pi * (1 - Fw(cos_o)) (1 - Fw(cos_i)) / (1 - Fwbar): the skin's diffuse base
//             seen through the film, the same reciprocal Fresnel-weighted form as the skin's base
//             (skin.hpp) with the water interface's Fresnel Fw and hemispherical reflectance Fwbar.
//   a_wet   = a (1 - p) / (1 - a p), p = 1 - (1 - Fwbar) / n^2, per colour channel: Lekner & Dorf
//             1988, "Why some things are darker when wet", Applied Optics 27(7):1278, the sum
//             over repeated reflections between base and film of their Fig. 1 (absorbed fraction
//             1 - a per hit on the base, fraction p of the scattered light sent back by the film's
//             top, 1 - p = (1 - Fwbar) / n^2 escaping: diffuse light inside the film beyond the
//             critical angle is totally reflected). Simplified: their second extension (the base
//             absorbs more against water than against air) is left out, and the film does not
//             absorb. Darker channels darken relatively more: wet skin is darker and more
//             saturated. `a` is the skin's base albedo (its diffuse under the lipid interface):
//             under water that interface is nearly index-matched (1.4 / 1.337, normal reflectance
//             5e-4), so the skin's own specular lobes and Fresnel loss are dropped under the film.
// Energy: E_wet(wo) = E_coat(wo) + a_wet (1 - Fw(cos_o)) <= 1 with the same GGX margin as the skin
// (skin.hpp, Energy; a_wet < a <= 0.99), and the convex mix with the skin keeps it <= 1.
//
// Sampling: the wet layer with probability c (uLobe rescaled), then within it the coat with
// probability Fw(cos_o) / (Fw(cos_o) + lum(a_wet)(1 - Fw(cos_o))) clamped to [0.1, 0.9] (visible
// normals, Heitz 2018), else the cosine lobe; the skin's own sampler otherwise. pdf() is the full
// mixture density (Veach 1997 ch. 9, one-sample model), sample() returns the full f and pdf.
// c = 0 is bitwise the skin BSDF (every call delegates).
//
// Pores (skin.hpp): the film fills them; the shading normal is the skin's pore-tilted one blended
// towards the smooth one by c (modelling choice).
#include "lacrima/materials/skin.hpp"

namespace lacrima {

inline constexpr float kWetFilmCoverageThickness = 2e-6f;  // metres, d0 of the coverage
inline constexpr float kWetCoatRoughness = 0.1f;           // GGX alpha = 0.01
inline constexpr float kWaterIor = 1.337f;                 // the film is tear fluid (kTearIor)

// Covered fraction c in [0, 1) of skin under a film of thickness d metres (0 for d <= 0).
float wetFilmCoverage(float filmThickness);

// Lekner & Dorf 1988 (see above): the albedo of a Lambertian base of albedo `albedo` under a
// non-absorbing film of index n, as seen by light that has entered the film (per channel).
Color leknerDorfWetAlbedo(const Color& albedo, float n);

class WetSkinBsdf final : public Bsdf {
 public:
  // coverage c in [0, 1] (clamped); the skin is copied (it is small, no heap).
  WetSkinBsdf(const SkinBsdf& skin, float coverage);

  Color eval(const Vec3& wo, const Vec3& wi) const override;
  float pdf(const Vec3& wo, const Vec3& wi) const override;
  std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const override;
  Color albedo() const override;
  Vec3 perturbShadingNormal(const Vec3& position, const Vec3& ns, const Vec3& ng) const override;

  float coverage() const { return coverage_; }
  const Color& wetAlbedo() const { return wetAlbedo_; }
  // Probability of sampling the coat within the wet layer (exposed for tests).
  float coatProbability(const Vec3& wo) const;

 private:
  Color wetEval(const Vec3& wo, const Vec3& wi) const;
  float wetPdf(const Vec3& wo, const Vec3& wi) const;

  SkinBsdf skin_;
  float coverage_;
  GgxDistribution coat_;
  Color wetAlbedo_;    // a_wet
  float underNorm_;    // 1 / (pi (1 - Fwbar))
};

}  // namespace lacrima
