#pragma once
// Material descriptions (plain data, what a shot file or glTF asset says) and the factory that
// turns them into BSDFs. Parameters are constant per material; diffuse and skin materials may add
// texture maps (MaterialTextures), which the renderer looks up per hit (renderer/src/surface_textures.hpp).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "lacrima/base/math.hpp"
#include "lacrima/materials/bsdf.hpp"

namespace lacrima {

inline constexpr float kTearIor = 1.337f;  // refractive index of human tear fluid (about 1.336-1.337, close to water)

struct DiffuseParams {
  Color albedo = Color(0.5f, 0.5f, 0.5f);
};

// Subsurface scattering of skin by a random walk below the surface (subsurface.hpp). The mean
// free path 1/sigma_t per channel, in metres. Defaults: Jensen et al. 2001, "A Practical Model for
// Subsurface Light Transport" (SIGGRAPH), measured coefficients, row Skin1: sigma_s' =
// (0.74, 0.88, 1.01) /mm, sigma_a = (0.032, 0.17, 0.48) /mm, so 1/(sigma_s' + sigma_a) =
// (1.30, 0.95, 0.67) mm; the reduced (transport) coefficients, since the walk scatters
// isotropically (similarity relation). The single-scattering albedo is not given here: it
// follows from the skin's albedo.
// How light below the skin finds where it leaves: a random walk through the medium (Chiang, Kutz
// & Burley 2016; exact for the homogeneous medium, the reference) or the diffusion profile of
// Christensen & Burley 2015 sampled by probe rays (a flat-surface approximation, a few ray
// queries instead of tens); see subsurface.hpp and diffusion_profile.hpp.
enum class SubsurfaceMethod { RandomWalk, Diffusion };

struct SubsurfaceParams {
  Color meanFreePath = Color(1.30e-3f, 0.95e-3f, 0.67e-3f);
  SubsurfaceMethod method = SubsurfaceMethod::RandomWalk;
};

// Skin: Lambertian base under one or two GGX specular lobes whose strength follows dielectric
// Fresnel, optionally with procedural pores and furrows that tilt the shading normal and darken
// the albedo in their hollows (see skin.hpp, skin_relief.hpp). The defaults (lobeMix 0, poreDepth 0,
// furrowDepth 0, cavity 0) give the plainest skin: one lobe, a smooth surface.
struct SkinParams {
  Color albedo = Color(0.62f, 0.43f, 0.35f);
  float roughness = 0.35f;   // sharper lobe, GGX alpha = roughness^2
  float ior = 1.4f;          // skin surface lipids, drives the specular Fresnel
  float roughness2 = 0.6f;   // broader second lobe, GGX alpha = roughness2^2
  float lobeMix = 0.0f;      // weight of the second lobe in [0, 1]; 0 = single lobe
  float poreScale = 3e-4f;   // metres between neighbouring pores (cell size of the pore lattice)
  float poreDepth = 0.0f;    // metres deep; 0 = no pores
  float furrowScale = 6e-4f;  // metres across a plateau of the furrow network (furrows.hpp)
  float furrowDepth = 0.0f;   // metres deep; 0 = no furrows
  float cavity = 0.0f;        // in [0, 1]: how far the pores' and furrows' walls darken the albedo (skin_relief.hpp)
  // Set: the Lambertian base is replaced by a random walk below the surface (subsurface.hpp).
  std::optional<SubsurfaceParams> subsurface;
};

// Smooth dielectric interface (water, tears): Fresnel reflection + refraction, TIR.
struct SmoothDielectricParams {
  float ior = kTearIor;  // the medium's index (relative to air; the renderer divides by the surrounding medium's)
  Color tint = Color(1.0f, 1.0f, 1.0f);  // multiplies transmission (1 = clear)
  int priority = 0;  // nested dielectrics (DielectricMedium below); 0 = the outside is air
};

// Rough dielectric: GGX microfacets, visible-normal sampling (Walter 2007, Heitz 2018).
struct RoughDielectricParams {
  float ior = kTearIor;
  float roughness = 0.1f;  // GGX alpha = roughness^2
  Color tint = Color(1.0f, 1.0f, 1.0f);
  int priority = 0;  // as SmoothDielectricParams::priority
};

using MaterialParams = std::variant<DiffuseParams, SkinParams, SmoothDielectricParams, RoughDielectricParams>;

// How a texture file's values become linear numbers. Auto: for albedo maps, files of integer
// samples (8- or 16-bit PNG, JPEG, TIFF) are sRGB-encoded and float/half files (EXR) are linear;
// every other map is data and always read as stored (linear).
enum class TextureEncoding { Auto, Srgb, Linear };

struct TextureMap {
  std::filesystem::path file;
  TextureEncoding encoding = TextureEncoding::Auto;
};

// The albedo as a procedural iris (iris_pattern.hpp) instead of a map: factors with a mean of 1
// over the iris, so the material's albedo stays the iris's mean colour.
struct IrisPatternParams {
  uint64_t seed = 1;
};

// Texture maps of a diffuse or skin material, looked up at the hit's uv (glTF convention: u to
// the right, v down the image). Each map multiplies the constant it refines (the glTF factor x
// texture rule): albedo and roughness per channel / value, meanFreePath per channel (the map
// holds dimensionless factors). Normal is a tangent-space map in the OpenGL convention (+Y, green,
// points up the image). Meshes without uvs shade with the constants. See docs/shot-format.md.
struct MaterialTextures {
  std::optional<TextureMap> albedo;
  std::optional<IrisPatternParams> irisPattern;  // never together with an albedo map
  std::optional<TextureMap> roughness;     // skin only; scales roughness and roughness2
  std::optional<TextureMap> normal;
  std::optional<TextureMap> meanFreePath;  // skin with subsurface only
  bool anyFile() const { return albedo || roughness || normal || meanFreePath; }
  bool any() const { return anyFile() || irisPattern; }
};

struct Material {
  // Constructors (not an aggregate): brace initialisers that leave out the textures stay free of
  // -Wmissing-field-initializers.
  Material() = default;
  Material(std::string name_, MaterialParams params_, const Color& emission_ = Color(0.0f, 0.0f, 0.0f))
      : name(std::move(name_)), params(std::move(params_)), emission(emission_) {}

  std::string name;
  MaterialParams params;
  Color emission = Color(0.0f, 0.0f, 0.0f);  // radiance emitted from the front side (area lights)
  MaterialTextures textures;                   // none: the constants of params everywhere
};

std::unique_ptr<Bsdf> makeBsdf(const MaterialParams& params);

// The medium a dielectric material encloses, for nested dielectrics with priorities (Schmidt &
// Budge 2002, "Simple Nested Dielectrics in Ray Traced Images", JGT 7(2)): where volumes
// overlap, the one with the higher priority fills the overlap and the surfaces of the others
// there are not interfaces at all. Priority 0 (the default) keeps the plain model: the
// material's `ior` is relative to air. See renderer/src/medium_stack.hpp.
inline constexpr int kMaxDielectricPriority = 1000;  // priorities are integers in [0, 1000]

struct DielectricMedium {
  float ior = 1.0f;  // absolute refractive index of the medium
  int priority = 0;
};

// The BSDF of a dielectric material on an open sheet that bounds no volume (thin_dielectric.hpp:
// its ior and tint; a rough one's roughness is not modelled there); null for opaque materials.
std::unique_ptr<Bsdf> makeThinSheetBsdf(const MaterialParams& params);

// The medium of a dielectric material; nothing for opaque materials.
std::optional<DielectricMedium> dielectricMedium(const MaterialParams& params);

// The same dielectric with its interface seen against a surrounding medium of absolute index
// outsideIor instead of air: ior becomes ior / outsideIor, everything else is kept. An
// index-matched rough interface (relative ior 1) becomes a smooth one: microfacets cannot bend
// light there and the rough model's half vector is undefined (pbrt-v4 DielectricBxDF does the same).
MaterialParams againstMedium(const MaterialParams& params, float outsideIor);

}  // namespace lacrima
