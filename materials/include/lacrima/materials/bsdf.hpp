#pragma once
// The BSDF interface. All directions are unit vectors in the local shading frame (z = shading
// normal) and point away from the surface: wo towards the viewer, wi towards the light.
// Conventions follow pbrt-v4: f() excludes the cosine factor; the path throughput update is
// f * |cos(wi)| / pdf. Delta (specular) lobes return f and pdf such that f*|cos|/pdf is the
// lobe weight (pdf = probability of choosing the lobe), and eval()/pdf() return zero for them.
#include <cmath>
#include <memory>
#include <optional>

#include "lacrima/base/math.hpp"

namespace lacrima {

struct BsdfSample {
  Vec3 wi;
  Color f;
  float pdf = 0.0f;
  bool specular = false;    // sampled from a delta lobe (no MIS with lights)
  bool transmitted = false; // wi is on the other side of the surface from wo
  // Reflected by a specular or glossy (microfacet) lobe rather than a diffuse one: a glossy
  // bounce for the per-type bounce limits (RenderSettings::bounces).
  bool glossy = false;
  float eta = 1.0f;         // relative IOR crossed (eta_wi_side / eta_wo_side) for transmission, else 1
};

// eval(wo, wi) split by the kind of scattering, for the renderer's light-path AOVs
// (renderer/light_paths.hpp): diffuse (a Lambertian base, the light leaving the skin), glossy
// (specular and microfacet reflection) and transmission (through a dielectric); the three add up
// to eval(wo, wi).
struct BsdfLobes {
  Color diffuse = Color::Zero();
  Color glossy = Color::Zero();
  Color transmission = Color::Zero();
  Color sum() const { return diffuse + glossy + transmission; }
};

class Bsdf {
 public:
  virtual ~Bsdf() = default;

  virtual Color eval(const Vec3& wo, const Vec3& wi) const = 0;
  // eval(wo, wi) by kind of scattering (BsdfLobes); zero where eval is (delta lobes).
  virtual BsdfLobes evalLobes(const Vec3& wo, const Vec3& wi) const = 0;
  virtual float pdf(const Vec3& wo, const Vec3& wi) const = 0;
  // uLobe picks a lobe (reflect/refract, diffuse/specular); u picks the direction.
  virtual std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const = 0;

  // True when every lobe is a delta distribution (light sampling is useless there).
  virtual bool isPureSpecular() const { return false; }
  // True when light can pass through (the surface bounds a medium such as water).
  virtual bool isTransmissive() const { return false; }
  // What a shadow ray keeps when it goes straight through this surface, ignoring refraction:
  // zero for opaque surfaces. wo is the local direction towards the shading point the shadow ray
  // started from. Used by the renderer's transparent shadows (see integrator.cpp).
  virtual Color straightTransmittance(const Vec3& /*wo*/) const { return Color::Zero(); }
  // The shading normal to use at world `position`, given the interpolated one ns and the
  // geometric one ng (unit, same side). Materials with fine-scale relief (skin pores) tilt it;
  // the result must be unit and on ng's side. Default: ns unchanged.
  virtual Vec3 perturbShadingNormal(const Vec3& /*position*/, const Vec3& ns, const Vec3& /*ng*/) const {
    return ns;
  }
  // Reflectance-like colour for the albedo AOV.
  virtual Color albedo() const = 0;
};

// A dielectric's lobes: f reflected is glossy, f transmitted (wi across the surface) transmission.
inline BsdfLobes reflectionOrTransmission(const Color& f, const Vec3& wo, const Vec3& wi) {
  BsdfLobes lobes;
  (wo.z() * wi.z() > 0.0f ? lobes.glossy : lobes.transmission) = f;
  return lobes;
}

// The mirror lobe of a smooth interface picked with probability R (its Fresnel reflectance):
// wi = mirror of wo, f = R / |cos_i|, pdf = R, so the weight f |cos_i| / pdf is 1 (pbrt-v4
// DielectricBxDF). Shared by the smooth and thin dielectrics.
inline BsdfSample specularReflectionSample(const Vec3& wo, float R) {
  BsdfSample s;
  s.specular = true;
  s.glossy = true;
  s.wi = Vec3(-wo.x(), -wo.y(), wo.z());
  s.f = Color::Constant(R / std::abs(s.wi.z()));
  s.pdf = R;
  return s;
}

// The sample of a one-sample mixture of reflection lobes: wi was drawn by one lobe, but the
// value and density are the whole mixture's (eval, pdf), so that MIS sees the mixture. Nothing
// when wi is below the horizon (lost to masking) or the mixture's density there is 0. glossy:
// the lobe that drew wi was a glossy one (BsdfSample::glossy).
inline std::optional<BsdfSample> mixtureReflectionSample(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi,
                                                         bool glossy) {
  if (wi.z() <= 0.0f) return std::nullopt;
  BsdfSample s;
  s.wi = wi;
  s.glossy = glossy;
  s.f = bsdf.eval(wo, wi);
  s.pdf = bsdf.pdf(wo, wi);
  if (s.pdf == 0.0f) return std::nullopt;
  return s;
}

}  // namespace lacrima
