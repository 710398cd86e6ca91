#pragma once
// Lambertian reflection, one-sided.
//
// Parameters (DiffuseParams): `albedo` is the directional-hemispherical reflectance, constant for
// every direction; f = albedo / pi (Lambert 1760; pbrt-v4 DiffuseBxDF).
// Sampling: cosine-weighted hemisphere by Malley's method, pdf = cos(theta_i) / pi, so each sample
// has weight f cos / pdf = albedo.
// One-sided: light is reflected only when wo and wi are both above the surface (z > 0). For
// wo.z <= 0 eval/pdf are zero and sample() returns nothing; the renderer flips the shading frame
// of single-sided opaque surfaces, this is only for robustness.
#include "lacrima/materials/bsdf.hpp"
#include "lacrima/materials/material.hpp"

namespace lacrima {

class DiffuseBsdf final : public Bsdf {
 public:
  explicit DiffuseBsdf(const DiffuseParams& params);

  Color eval(const Vec3& wo, const Vec3& wi) const override;
  BsdfLobes evalLobes(const Vec3& wo, const Vec3& wi) const override { return {eval(wo, wi)}; }
  float pdf(const Vec3& wo, const Vec3& wi) const override;
  std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const override;
  Color albedo() const override { return albedo_; }

 private:
  Color albedo_;
};

}  // namespace lacrima
