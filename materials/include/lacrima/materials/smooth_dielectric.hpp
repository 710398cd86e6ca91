#pragma once
// Smooth dielectric interface (water, tears): Fresnel reflection plus refraction, both delta lobes.
//
// Parameters (SmoothDielectricParams):
//   ior  - relative IOR eta = n_inside / n_outside (the normal points outside); 1.337 for tears;
//   tint - multiplies every transmission (applied at each crossing, so a ray that enters and
//          leaves a drop is tinted twice; 1 = clear).
//
// Both sides work: wo.z > 0 is outside, wo.z < 0 is inside (then the relative IOR is 1/eta and
// total internal reflection happens beyond the critical angle asin(1/eta) = 48.4 deg for 1.337).
// Sampling chooses reflection with probability R = F(cos_o) (exact unpolarised Fresnel), else
// refraction with probability T = 1 - R:
//   reflection:   wi = mirror of wo,  f = R / |cos_i|,                  pdf = R  -> weight 1
//   transmission: wi by Snell's law,  f = T tint / |cos_i| / etap^2,    pdf = T  -> weight tint/etap^2
// (pbrt-v4 DielectricBxDF). etap = n_(wi side) / n_(wo side), returned in BsdfSample::eta.
//
// The 1/etap^2 factor: lacrima traces paths from the camera, so the BSDF transports radiance, and
// radiance divided by n^2 is what is conserved across an interface (Veach 1997 ch. 5,
// pbrt-v4 "Non-Symmetric Scattering and Refraction", TransportMode::Radiance). A camera
// ray entering water (etap = 1.337) gets 1/1.337^2; leaving it again gets 1.337^2, so the
// factors cancel for a path that enters and leaves the drop. Consequence: R + T weights sum to 1
// only once the transmitted weight is multiplied back by etap^2, and the radiance "albedo" seen
// from inside water can exceed 1 (radiance concentrates in the denser medium) without creating
// energy.
// eval() and pdf() are zero: the lobes are delta distributions (bsdf.hpp).
#include "lacrima/materials/bsdf.hpp"
#include "lacrima/materials/material.hpp"

namespace lacrima {

class SmoothDielectricBsdf final : public Bsdf {
 public:
  explicit SmoothDielectricBsdf(const SmoothDielectricParams& params);

  Color eval(const Vec3& wo, const Vec3& wi) const override;
  BsdfLobes evalLobes(const Vec3& wo, const Vec3& wi) const override {
    return reflectionOrTransmission(eval(wo, wi), wo, wi);
  }
  float pdf(const Vec3& wo, const Vec3& wi) const override;
  std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const override;
  bool isPureSpecular() const override { return true; }
  Color straightTransmittance(const Vec3& wo) const override;
  bool isTransmissive() const override { return true; }
  Color albedo() const override { return tint_; }

  float ior() const { return ior_; }

 private:
  float ior_;
  Color tint_;
};

}  // namespace lacrima
