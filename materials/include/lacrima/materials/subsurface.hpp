#pragma once
// Subsurface scattering of skin by a random walk (Chiang, Kutz & Burley 2016, "Practical and
// Controllable Subsurface Scattering for Production Path Tracing", SIGGRAPH Talks): below the
// surface lies a homogeneous medium with isotropic scattering; a path enters it, takes
// exponential free flights until it crosses the surface again, and leaves there. The walk itself
// is in renderer/src/subsurface_walk.cpp; this file holds the medium and the exit lobe.
//
// The boundary: the walk is index-matched (a path that reaches the surface from inside always
// leaves: no internal reflection), and the Fresnel of the skin's surface is paid once at entry,
// 1 - F(cos_o), and once at exit through SubsurfaceExitBsdf, exactly like the Lambertian base it
// replaces (skin.hpp). The path enters in a cosine-distributed direction (Lambertian entry),
// whatever wo is.
//
// Colour: the single-scattering albedo a per channel is chosen so that the medium's diffuse
// reflectance equals the skin's albedo: for an index-matched semi-infinite medium under uniform
// illumination (white-sky albedo) van de Hulst's approximation (van de Hulst 1980, "Multiple Light
// Scattering", vol. 2, via Kokhanovsky 2004, eq. for the spherical albedo)
//   A = (1 - s)(1 - 0.139 s) / (1 + 1.17 s),  s = sqrt(1 - a),
// inverted exactly (a quadratic in s):
//   a = 1 - (4.09712 + 4.20863 A - sqrt(9.59217 + 41.6808 A + 17.7126 A^2))^2.
// A = 1 gives a = 1 (no absorption). The approximation agrees with the exact Chandrasekhar
// H-function value within 0.002 for A in [0.05, 0.95] (tests/materials/subsurface_test.cpp).
#include "lacrima/materials/bsdf.hpp"
#include "lacrima/materials/material.hpp"

namespace lacrima {

// The medium below a skin surface: extinction and single-scattering albedo per channel.
struct SubsurfaceMedium {
  Color sigmaT;                  // 1 / mean free path, per metre
  Color singleScatteringAlbedo;  // sigma_s / sigma_t in [0, 1]
  Color sigmaS() const { return sigmaT * singleScatteringAlbedo; }
};

// van de Hulst's inversion (above): the single-scattering albedo whose semi-infinite white-sky
// albedo is `diffuseAlbedo` (clamped to [0, 1]), per channel.
Color singleScatteringAlbedoFor(const Color& diffuseAlbedo);

// The medium of a skin with subsurface set (albedo and mean free path of `skin`).
SubsurfaceMedium subsurfaceMedium(const SkinParams& skin, const SubsurfaceParams& subsurface);

// The lobe a path leaves the medium through: cosine-distributed, with the Fresnel transmission of
// the skin's surface, f(wi) = (1 - F(cos_i)) / (pi (1 - Fbar)) for wi above the surface (any wo).
// Its cosine-weighted integral is exactly 1: the exit loses no energy beyond what the walk lost.
class SubsurfaceExitBsdf final : public Bsdf {
 public:
  explicit SubsurfaceExitBsdf(float ior);

  Color eval(const Vec3& wo, const Vec3& wi) const override;
  // The light leaving the skin: diffuse (the renderer counts it as subsurface).
  BsdfLobes evalLobes(const Vec3& wo, const Vec3& wi) const override { return {eval(wo, wi)}; }
  float pdf(const Vec3& wo, const Vec3& wi) const override;
  std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const override;
  Color albedo() const override { return Color::Ones(); }

 private:
  float ior_;
  float norm_;  // 1 / (pi (1 - Fbar))
};

}  // namespace lacrima
