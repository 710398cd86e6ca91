#pragma once
// Skin: a Lambertian base (or subsurface scattering, subsurface.hpp) under one or two GGX specular
// reflection lobes, with optional procedural pores that tilt the shading normal (pores.hpp).
//
// Parameters (SkinParams):
//   albedo     - reflectance of the base before the Fresnel loss, clamped to [0, 0.99] (see Energy);
//   roughness  - sharper lobe, GGX alpha1 = roughness^2, clamped to alpha >= 1e-3;
//   roughness2 - broader lobe, GGX alpha2 = roughness2^2 (used only when lobeMix > 0);
//   lobeMix    - weight w of the broader lobe in [0, 1]; 0 is the single-lobe skin (bitwise);
//   ior        - refractive index of the surface layer; drives the specular Fresnel F;
//   poreScale, poreDepth - the pore field of pores.hpp (poreDepth 0: no pores);
//   furrowScale, furrowDepth - the furrow network of furrows.hpp (furrowDepth 0: none);
//   cavity     - how far the relief's hollows darken the albedo; applied by the renderer per hit,
//                which builds the BSDF with the darkened albedo (skin_relief.hpp).
//
// f(wo, wi) = f_spec + f_diff, both zero unless wo and wi are above the surface:
//   f_spec = [(1 - w) D1(wm) G2_1(wo, wi) + w D2(wm) G2_2(wo, wi)] F(wo.wm) / (4 cos_o cos_i),
//            wm = normalize(wo + wi) (Walter et al. 2007 eq. 20 per lobe, GGX D, height-correlated
//            Smith G2, exact dielectric F). Two lobes, a sharper and a broader one sharing the
//            Fresnel term of the skin's oily layer, are the skin specular advised by d'Eon & Luebke,
//            "Advanced Techniques for Realistic Real-Time Skin Rendering" (GPU Gems 3, ch. 14,
//            2007, §14.3, Kelemen/Szirmay-Kalos specular); measured skin needs more than one lobe
//            (Donner & Jensen 2005, "Light Diffusion in Multi-Layered Translucent Materials").
//            A convex mix of normalised lobes: the specular albedo is the mix of the lobes' albedos.
//   f_diff = albedo / pi * (1 - F(cos_o)) (1 - F(cos_i)) / (1 - Fbar),
//            Fbar = (1/pi) integral F(cos) cos dw, the hemispherical (cosine-weighted) Fresnel
//            reflectance. Light enters and leaves the base through the interface, so both ends
//            pay the Fresnel loss; this keeps f reciprocal (Shirley et al. 1997, "A practitioners'
//            assessment of light reflection models", PG'97; Ashikhmin & Shirley 2000 eq. 5 is the
//            same idea with Schlick's approximation). Dividing by (1 - Fbar) makes the base's
//            directional albedo exactly albedo * (1 - F(cos_o)): light that the coat reflects
//            does not reach the base.
// Energy: total albedo = E_spec(wo) + albedo (1 - F(cos_o)). The single-scattering GGX albedo
// E_spec(wo) can exceed F(cos_o) slightly (facets tilted towards wo see more Fresnel than the
// macro surface): measured max (E_spec - F) / (1 - F) = 7.2e-4, at roughness 0.3, cos_o 0.7, over
// roughness 0.05-1 and ior 1.3-2. The base albedo is therefore clamped to kMaxSkinAlbedo = 0.99,
// which keeps the total <= 1 with a tenfold margin (tested with a white base, one and two lobes:
// the two-lobe E_spec is a convex mix of one-lobe ones, so the same bound holds).
//
// Sampling: a mixture. The specular part is chosen with probability
// pSpec = Fo / (Fo + lum(albedo)(1 - Fo)), Fo = F(cos_o), clamped to [0.1, 0.9]; within it the
// broader lobe with probability w, each lobe by visible-normal sampling (Heitz 2018); else the
// cosine-weighted diffuse lobe. pdf() is the mixture density (Veach 1997 ch. 9, one-sample
// model), and sample() returns the full f and the mixture pdf.
//
// Subsurface (SkinParams::subsurface set): the BSDF is the specular part alone (eval, pdf and
// sample); the renderer replaces the Lambertian base by a random walk below the surface, chosen
// with probability 1 - specularProbability(wo) (subsurface.hpp, renderer/src/subsurface_walk.hpp).
#include "lacrima/materials/bsdf.hpp"
#include "lacrima/materials/material.hpp"
#include "lacrima/materials/microfacet.hpp"
#include "lacrima/materials/skin_relief.hpp"

namespace lacrima {

inline constexpr float kMaxSkinAlbedo = 0.99f;

// Fbar(eta) = 2 integral_0^1 F(mu, eta) mu dmu: the cosine-weighted hemispherical reflectance of
// a dielectric interface lit from outside (twice the first Fresnel moment, pbrt-v4's FresnelMoment1).
// Computed by quadrature and cached per thread for the last eta.
float fresnelHemisphericalReflectance(float eta);

class SkinBsdf final : public Bsdf {
 public:
  // reliefGradientHere: the relief's gradient at the hit this BSDF is built for, when the caller
  // has it already (skin_relief.hpp); perturbShadingNormal then uses it instead of evaluating the
  // relief at the position it is given.
  explicit SkinBsdf(const SkinParams& params, std::optional<Vec3> reliefGradientHere = std::nullopt);

  Color eval(const Vec3& wo, const Vec3& wi) const override;
  BsdfLobes evalLobes(const Vec3& wo, const Vec3& wi) const override;
  float pdf(const Vec3& wo, const Vec3& wi) const override;
  std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const override;
  Color albedo() const override { return albedo_; }  // clamped base albedo
  float ior() const { return ior_; }                  // index of the surface layer
  bool hasDiffuseLobe() const { return hasDiffuseLobe_; }  // false with subsurface (see above)

  // Pores and furrows: ns tilted by the relief at the world position (skin_relief.hpp); ns when
  // poreDepth and furrowDepth are 0.
  Vec3 perturbShadingNormal(const Vec3& position, const Vec3& ns, const Vec3& ng) const override;

  // Probability of sampling the specular lobes (both together) for this wo (exposed for tests).
  float specularProbability(const Vec3& wo) const;

 private:
  Color diffuseF(const Vec3& wo, const Vec3& wi) const;  // the base's f (both above)
  float specularF(const Vec3& wo, const Vec3& wi) const;
  float specularPdf(const Vec3& wo, const Vec3& wi) const;

  Color albedo_;
  float ior_;
  GgxDistribution sharp_;  // alpha = roughness^2
  GgxDistribution broad_;  // alpha = roughness2^2, weight lobeMix_
  float lobeMix_;          // in [0, 1]; 0 skips the broad lobe everywhere (the single-lobe skin, bitwise)
  float diffuseNorm_;      // 1 / (pi (1 - Fbar))
  ReliefFields relief_;  // pores and furrows; depths 0 where their scale or depth is not positive
  std::optional<Vec3> reliefGradientHere_;
  bool hasDiffuseLobe_;    // false with subsurface: the renderer's random walk replaces the base
};

}  // namespace lacrima
