#pragma once
// Texture maps of diffuse and skin materials (MaterialTextures in material.hpp), and the procedural
// iris in place of an albedo map (iris_pattern.hpp). Maps are looked up through
// one OpenImageIO TextureSystem for the whole process (its tile and MIP cache serves every frame
// of a sequence). The system is created only when some material has a map file: frames without
// them pay nothing.
//
// Lookups are trilinear MIP-map lookups (bilinear in the two levels around the footprint) with an
// isotropic footprint: the width of the pixel's cone where the path meets the surface, in uv
// units along u and v (UvFootprint). Maps without MIP levels get them built on the fly by the
// system (automip). The footprint ignores the 1/cos stretch at grazing angles and the widening
// after bounces, so lookups err on the sharp side there (pixel supersampling averages the rest).
// Wrap mode periodic, as glTF's default sampler (REPEAT). A lookup is deterministic, so the
// image stays independent of the thread count.
//
// sRGB albedo maps (TextureEncoding, material.hpp) are decoded after the filtered lookup, per
// channel with the IEC 61966-2-1 curve: interpolation and MIP averaging act on encoded values,
// which is exact where the texels under the filter agree and slightly dark where they differ.
#include <OpenImageIO/oiioversion.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/materials/iris_pattern.hpp"
#include "lacrima/materials/material.hpp"
#include "lacrima/materials/texture_values.hpp"


OIIO_NAMESPACE_BEGIN
class TextureSystem;
OIIO_NAMESPACE_END

namespace lacrima {

// A lookup's filter width in texture coordinates: how far u and v change over the footprint.
struct UvFootprint {
  float du = 0.0f;
  float dv = 0.0f;
};

// The footprint `width` metres wide on a surface whose uv tangents are dpdu, dpdv (SurfaceHit);
// zero (the finest level) where a tangent is degenerate.
UvFootprint uvFootprint(float width, const Vec3& dpdu, const Vec3& dpdv);

class SurfaceTextures {
 public:
  // Opens every map of `materials` (materialId order); throws InputError naming the material and
  // the file when one cannot be read.
  explicit SurfaceTextures(const std::vector<Material>& materials);
  ~SurfaceTextures();
  SurfaceTextures(const SurfaceTextures&) = delete;
  SurfaceTextures& operator=(const SurfaceTextures&) = delete;

  bool textured(uint32_t materialId) const { return materialId < maps_.size() && maps_[materialId].any; }
  // The values of materialId's maps at uv, filtered over footprint (thread-safe).
  TextureValues lookup(uint32_t materialId, const Vec2& uv, const UvFootprint& footprint = {}) const;

 private:
  struct OpenMap {
    void* handle = nullptr;  // OIIO::TextureSystem::TextureHandle
    int channels = 0;        // looked up (gray files are expanded to RGB by the system)
    bool srgb = false;
  };
  struct MaterialMaps {
    bool any = false;
    std::optional<OpenMap> albedo, roughness, normal, meanFreePath;
    std::optional<IrisPattern> iris;  // the albedo as a procedural iris (no albedo map then)
  };
  OpenMap open(const Material& material, const TextureMap& map, const char* role, bool colour);
  void sample(const OpenMap& map, const Vec2& uv, const UvFootprint& footprint, float* result) const;

  OIIO::TextureSystem* textures_ = nullptr;  // the process's (surface_textures.cpp); null without map files
  std::vector<MaterialMaps> maps_;  // per material; empty when no material has maps
};

}  // namespace lacrima
