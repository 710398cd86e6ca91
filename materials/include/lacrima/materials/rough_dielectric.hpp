#pragma once
// Rough dielectric interface: GGX microfacet reflection and refraction (frosted or rippled water).
//
// Parameters (RoughDielectricParams):
//   ior       - relative IOR eta = n_inside / n_outside (normal points outside), 1.337 for tears;
//   roughness - GGX alpha = roughness^2, clamped to alpha >= 1e-3;
//   tint      - multiplies every transmission (as SmoothDielectricBsdf).
//
// Model: Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces":
//   reflection   f_r = D(wm) G2 F / (4 |cos_o| |cos_i|),       wm = normalize(wo + wi)   (eqs. 13, 20)
//   transmission f_t = D(wm) G2 (1 - F) |wi.wm| |wo.wm| / (|cos_i| |cos_o| (wi.wm + wo.wm / etap)^2)
//                      * tint / etap^2,                         wm = normalize(wo + etap wi) (eqs. 16, 21)
// with etap = n_(wi side) / n_(wo side) and wm turned to the upper hemisphere; F = F(wo.wm) exact
// dielectric Fresnel, D GGX, G2 height-correlated Smith (microfacet.hpp). Microfacets seen from
// the back by wo or wi contribute nothing. Works with wo on either side (wo.z < 0: inside).
// The 1/etap^2 factor transports radiance from the camera (pbrt-v4 TransportMode::Radiance,
// see smooth_dielectric.hpp); it is Walter's eq. 21 written for radiance, whose eta_o^2 factor
// over (eta_i (i.h) + eta_o (o.h))^2 is exactly this.
//
// Generalised reciprocity (Veach 1997 ch. 5): with eta_o, eta_i the IORs on the sides of wo
// and wi, f(wo, wi) / eta_o^2 = f(wi, wo) / eta_i^2. Reflection is plainly symmetric.
//
// Sampling (pbrt-v4 DielectricBxDF): a microfacet normal from the distribution of normals
// visible from wo (Heitz 2018), then reflection with probability F(wo.wm), else refraction.
//   pdf_r(wi) = D_wo(wm) / (4 |wo.wm|) * F                                   (Walter eq. 14)
//   pdf_t(wi) = D_wo(wm) |wi.wm| / (wi.wm + wo.wm / etap)^2 * (1 - F)          (Walter eq. 17)
// A sample that leaves on the wrong side of the macro surface is discarded (returned empty);
// pdf() integrates to the probability of success, which the chi-square test accounts for.
#include "lacrima/materials/bsdf.hpp"
#include "lacrima/materials/material.hpp"
#include "lacrima/materials/microfacet.hpp"

namespace lacrima {

class RoughDielectricBsdf final : public Bsdf {
 public:
  explicit RoughDielectricBsdf(const RoughDielectricParams& params);

  Color eval(const Vec3& wo, const Vec3& wi) const override;
  BsdfLobes evalLobes(const Vec3& wo, const Vec3& wi) const override {
    return reflectionOrTransmission(eval(wo, wi), wo, wi);
  }
  float pdf(const Vec3& wo, const Vec3& wi) const override;
  std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const override;
  bool isTransmissive() const override { return true; }
  Color albedo() const override { return tint_; }

  float ior() const { return ior_; }
  const GgxDistribution& distribution() const { return distribution_; }

 private:
  struct HalfVector {
    Vec3 wm;        // microfacet normal, upper hemisphere
    float etap;     // n_(wi side) / n_(wo side), 1 for reflection
    bool reflect;   // wo and wi on the same side
  };
  // Generalised half vector of (wo, wi); nothing for degenerate or back-facing configurations.
  std::optional<HalfVector> halfVector(const Vec3& wo, const Vec3& wi) const;

  float reflectionF(const Vec3& wo, const Vec3& wi, const Vec3& wm, float F) const;
  float transmissionF(const Vec3& wo, const Vec3& wi, const Vec3& wm, float etap, float F) const;
  float reflectionPdf(const Vec3& wo, const Vec3& wm, float F) const;
  float transmissionPdf(const Vec3& wo, const Vec3& wi, const Vec3& wm, float etap, float F) const;

  float ior_;
  GgxDistribution distribution_;
  Color tint_;
};

}  // namespace lacrima
