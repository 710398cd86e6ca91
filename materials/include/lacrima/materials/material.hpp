#pragma once
// Material descriptions (plain data, what a shot file or glTF asset says) and the factory that
// turns them into BSDFs. Parameters are constant per material in this version (no textures).
#include <memory>
#include <string>
#include <variant>

#include "lacrima/geometry/math.hpp"
#include "lacrima/materials/bsdf.hpp"

namespace lacrima {

inline constexpr float kTearIor = 1.337f;  // refractive index of human tear fluid (about 1.336-1.337, close to water)

struct DiffuseParams {
  Color albedo = Color(0.5f, 0.5f, 0.5f);
};

// Skin: Lambertian base under one or two GGX specular lobes whose strength follows dielectric
// Fresnel, optionally with procedural pores that tilt the shading normal (see skin.hpp, pores.hpp).
// The defaults (lobeMix 0, poreDepth 0) are skin v1: one lobe, no pores.
struct SkinParams {
  Color albedo = Color(0.62f, 0.43f, 0.35f);
  float roughness = 0.35f;   // sharper lobe, GGX alpha = roughness^2
  float ior = 1.4f;          // skin surface lipids, drives the specular Fresnel
  float roughness2 = 0.6f;   // broader second lobe, GGX alpha = roughness2^2
  float lobeMix = 0.0f;      // weight of the second lobe in [0, 1]; 0 = single lobe (skin v1)
  float poreScale = 3e-4f;   // metres between neighbouring pores (cell size of the pore lattice)
  float poreDepth = 0.0f;    // metres deep; 0 = no pores
};

// Smooth dielectric interface (water, tears): Fresnel reflection + refraction, TIR.
struct SmoothDielectricParams {
  float ior = kTearIor;  // inside / outside
  Color tint = Color(1.0f, 1.0f, 1.0f);  // multiplies transmission (1 = clear)
};

// Rough dielectric: GGX microfacets, visible-normal sampling (Walter 2007, Heitz 2018).
struct RoughDielectricParams {
  float ior = kTearIor;
  float roughness = 0.1f;  // GGX alpha = roughness^2
  Color tint = Color(1.0f, 1.0f, 1.0f);
};

using MaterialParams = std::variant<DiffuseParams, SkinParams, SmoothDielectricParams, RoughDielectricParams>;

struct Material {
  std::string name;
  MaterialParams params;
  Color emission = Color(0.0f, 0.0f, 0.0f);  // radiance emitted from the front side (area lights)
};

std::unique_ptr<Bsdf> makeBsdf(const MaterialParams& params);

}  // namespace lacrima
