#pragma once
// Wet skin: the skin BSDF (skin.hpp) partly covered by a thin water film (a tear's trail). The
// renderer builds one per hit from the film thickness there (MeshInstance::wetness).
//
// Coverage: c = 1 - exp(-d / d0), d = film thickness, d0 = kWetFilmCoverageThickness = 2 um
// (modelling choice: a film thinner than a few micrometres breaks up into patches on the skin's
// micro-relief, so its covered fraction grows with d; a 20 um trail covers > 99.99%).
//
// f(wo, wi) = (1 - c) f_skin + c f_wet, both zero unless wo and wi are above the surface:
//   f_wet = f_coat + f_under
//   f_coat  = D(wm) G2(wo, wi) Fw(wo.wm) / (4 cos_o cos_i): the film's air-water interface, a GGX
//             lobe (Walter et al. 2007 eq. 20) with roughness kWetCoatRoughness = 0.1 (alpha 0.01;
//             modelling choice: a water surface is optically smooth, the film drapes over the
//             skin's relief, so it is sharp but not a mirror, and a finite lobe keeps light
//             sampling and MIS working; alpha 0.04 spread the trail's glints into a dull sheen
//             on the default shot), water index 1.337.
//   f_under = a_wet / pi * (1 - Fw(cos_o)) (1 - Fw(cos_i)) / (1 - Fwbar): the skin's diffuse base
//             seen through the film, the same reciprocal Fresnel-weighted form as the skin's base
//             (skin.hpp) with the water interface's Fresnel Fw and hemispherical reflectance Fwbar.
//   a_wet   = the skin's base albedo under the film, per colour channel, from Lekner & Dorf 1988,
//             "Why some things are darker when wet", Applied Optics 27(7):1278: a base of albedo
//             a0 under a top that sends back the fraction p of the diffuse light it scatters up
//             looks like a (1 - p) / (1 - a0 p) (the sum over repeated reflections of their
//             Fig. 1), p = 1 - (1 - Fbar) / n^2 for a flat top of index n over the base (diffuse
//             light beyond the critical angle is totally reflected; Fbar its reflectance seen
//             from outside). Their base (sand, cloth, paper) meets air directly when dry, so all
//             of p darkens it when wet (p ~ 0.47 under water). Skin does not: its own surface
//             (index n_s = the skin's ior, 1.4) already traps its diffuse light with
//             p_s = 1 - (1 - Fbar(n_s)) / n_s^2 ~ 0.53, and the albedo `a` a shot gives is the
//             dry look, so it already holds that trapping: a = a0 (1 - p_s) / (1 - a0 p_s).
//             Under a flat film the skin-water interface is nearly index-matched (1.4 / 1.337,
//             normal reflectance 5e-4) and n sin(theta) is the same in every parallel layer, so
//             the escape cone into air is still the skin's, 1 / n_s^2, with the water's top
//             Fresnel: p_w = 1 - (1 - Fbar(n_w)) / max(n_s, n_w)^2 (max: a base less dense than
//             water fills the film's whole cone, Lekner & Dorf's case). So
//             a_wet = a0 (1 - p_w) / (1 - a0 p_w) with a0 from the dry a: for skin of index 1.4
//             the diffuse is within 1% of the dry one (p_w ~ p_s), not the ~30% darker a trail
//             looked with p_w applied to `a` (a brownish stain). Wet skin reads wet by its
//             sharp water highlight; off the highlight it is a little darker because the skin's
//             broad specular sheen is gone under the film. Left out: Lekner & Dorf's second
//             extension (the base absorbs more against water than against air; on skin, the
//             stratum corneum swelling with water over minutes) and absorption in the film.
//             The skin's own specular lobes and Fresnel loss are dropped under the film.
// Energy: E_wet(wo) = E_coat(wo) + a_wet (1 - Fw(cos_o)) <= 1 with the same GGX margin as the skin
// (skin.hpp, Energy; a_wet is clamped to kMaxSkinAlbedo = 0.99 like the skin's albedo), and the
// convex mix with the skin keeps it <= 1.
//
// Sampling: the wet layer with probability c (uLobe rescaled), then within it the coat with
// probability Fw(cos_o) / (Fw(cos_o) + lum(a_wet)(1 - Fw(cos_o))) clamped to [0.1, 0.9] (visible
// normals, Heitz 2018), else the cosine lobe; the skin's own sampler otherwise. pdf() is the full
// mixture density (Veach 1997 ch. 9, one-sample model), sample() returns the full f and pdf.
// c = 0 is bitwise the skin BSDF (every call delegates).
//
// Subsurface skin (SkinParams::subsurface set, SkinBsdf::hasDiffuseLobe() false): the film is thin
// (~20 um) next to the skin's mean free paths (~mm), so light that crosses its top scatters in the
// skin as it does where the skin is dry. The wet layer is then the coat alone (f_under dropped,
// the coat sampled with probability 1) and the renderer's walk or probe serves the base of both
// fractions: light enters it with belowTransmission(wo) = (1 - c)(1 - F(cos_o)) + c (1 - Fw(cos_o))
// (F the skin's Fresnel, Fw the water's; the skin-water interface under the film is nearly
// index-matched and left out), and it continues the path below with belowProbability(wo). Without
// this a trail on subsurface skin had a Lambertian base: a smooth, flatter band with an edge
// against the dry skin around it. a_wet ~ a (see above), so the walk keeps the dry albedo.
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

// p = 1 - (1 - Fbar) / n^2: the fraction of diffuse light inside a medium of index n that a flat
// top sends back, Fbar the top's hemispherical reflectance seen from outside (Lekner & Dorf 1988).
float diffuseTrapping(float outerFbar, float n);

// Lekner & Dorf 1988 (see above): the albedo of a Lambertian base of albedo `albedo` in contact
// with air when dry, under a non-absorbing film of index n (per channel).
Color leknerDorfWetAlbedo(const Color& albedo, float n);

// a_wet of skin (see above): its dry base albedo seen through its own surface of index skinIor,
// that surface's trapping undone and the film's (top reflectance filmFbar) applied (per channel).
Color wetSkinBaseAlbedo(const Color& dryAlbedo, float skinIor, float filmIor, float filmFbar);

class WetSkinBsdf final : public Bsdf {
 public:
  // coverage c in [0, 1] (clamped); the skin is copied (it is small, no heap).
  WetSkinBsdf(const SkinBsdf& skin, float coverage);

  Color eval(const Vec3& wo, const Vec3& wi) const override;
  BsdfLobes evalLobes(const Vec3& wo, const Vec3& wi) const override;
  float pdf(const Vec3& wo, const Vec3& wi) const override;
  std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const override;
  Color albedo() const override;
  Vec3 perturbShadingNormal(const Vec3& position, const Vec3& ns, const Vec3& ng) const override;

  float coverage() const { return coverage_; }
  const Color& wetAlbedo() const { return wetAlbedo_; }
  // Probability of sampling the coat within the wet layer (exposed for tests); 1 on subsurface skin.
  float coatProbability(const Vec3& wo) const;

  // Subsurface skin (see above): the fraction of the light arriving along wo that crosses into the
  // skin, and the probability with which the renderer continues the path below the surface (the
  // dry share's 1 - SkinBsdf::specularProbability, the wet share's 1 - the coat's share of the
  // wet layer's albedo).
  float belowTransmission(const Vec3& wo) const;
  float belowProbability(const Vec3& wo) const;

 private:
  BsdfLobes wetLobes(const Vec3& wo, const Vec3& wi) const;  // the wet layer's base and coat
  float coatShare(const Vec3& wo) const;  // the coat's share of the wet layer's albedo, clamped
  Color wetEval(const Vec3& wo, const Vec3& wi) const;
  float wetPdf(const Vec3& wo, const Vec3& wi) const;

  SkinBsdf skin_;
  float coverage_;
  GgxDistribution coat_;
  Color wetAlbedo_;    // a_wet
  float underNorm_;    // 1 / (pi (1 - Fwbar))
  bool hasUnder_;      // the wet layer's Lambertian base: false on subsurface skin
};

}  // namespace lacrima
