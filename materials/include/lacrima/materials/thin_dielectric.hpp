#pragma once
// A thin dielectric sheet: an open dielectric surface (a tear-line card, an eye-wetness strip)
// that bounds no volume. Light is reflected by both faces of a slab too thin to bend or offset
// what passes through, so transmission goes straight on and the path never enters a medium
// (pbrt-v4, Pharr, Jakob & Humphreys 2023, section 9.5.1, ThinDielectricBxDF):
//   R0 = F(|cos_o|, eta)                       one face's unpolarised Fresnel reflectance
//   R  = R0 + T0^2 R0 / (1 - R0^2), T0 = 1-R0  every inter-reflection inside the slab summed
//   T  = 1 - R
// Sampling picks reflection with probability R, else transmission:
//   reflection:   wi = mirror of wo, f = R / |cos_i|,        pdf = R  -> weight 1
//   transmission: wi = -wo,          f = T tint / |cos_i|,   pdf = T  -> weight tint
// No 1/eta^2 radiance factor: the path leaves the slab on the side of air again. Both faces are
// alike (wo.z of either sign). The tint multiplies each crossing of the sheet once. Roughness of
// a rough dielectric material is not modelled on a thin sheet.
#include "lacrima/materials/bsdf.hpp"

namespace lacrima {

class ThinDielectricBsdf final : public Bsdf {
 public:
  ThinDielectricBsdf(float ior, const Color& tint);

  // The slab's reflectance R for a direction with cosine cosTheta to the normal (either side).
  float reflectance(float cosTheta) const;

  Color eval(const Vec3& wo, const Vec3& wi) const override;
  BsdfLobes evalLobes(const Vec3& wo, const Vec3& wi) const override {
    return reflectionOrTransmission(eval(wo, wi), wo, wi);
  }
  float pdf(const Vec3& wo, const Vec3& wi) const override;
  std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const override;
  bool isPureSpecular() const override { return true; }
  bool isTransmissive() const override { return true; }
  // The straight transmission is exact here: T tint.
  Color straightTransmittance(const Vec3& wo) const override;
  Color albedo() const override { return tint_; }

 private:
  float ior_;
  Color tint_;
};

}  // namespace lacrima
