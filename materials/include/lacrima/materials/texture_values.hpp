#pragma once
// What texture maps do to a material (MaterialTextures, material.hpp), apart from reading them
// (the renderer's renderer/src/surface_textures.hpp looks them up through OpenImageIO).
#include <optional>

#include "lacrima/base/math.hpp"
#include "lacrima/materials/material.hpp"

namespace lacrima {

// The values of a material's maps at one uv; each set only when the material has that map.
struct TextureValues {
  std::optional<Color> albedo;        // linear
  std::optional<float> roughness;     // the map's first channel
  std::optional<Vec3> normal;         // tangent space, unit, z > 0 (decoded 2 t - 1)
  std::optional<Color> meanFreePath;  // dimensionless factors
};

// `params` with the map values applied (material.hpp: each map multiplies its constant). Diffuse
// albedo is clamped to [0, 1], roughness to [0, 1]; SkinBsdf clamps its own albedo.
MaterialParams applyTextureValues(const MaterialParams& params, const TextureValues& values);

// The shading normal with a tangent-space normal map value applied: the frame is ns, the tangent
// dpdu made orthogonal to ns, and the bitangent ns x tangent pointing up the image (towards
// decreasing v, -dpdv: the OpenGL +Y convention with glTF's v running down). Returns ns when
// dpdu is degenerate or parallel to ns.
Vec3 applyNormalMap(const Vec3& tangentNormal, const Vec3& ns, const Vec3& dpdu, const Vec3& dpdv);

// sRGB transfer function, encoded -> linear (IEC 61966-2-1).
float srgbToLinear(float encoded);

}  // namespace lacrima
