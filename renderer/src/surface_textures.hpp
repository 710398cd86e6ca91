#pragma once
// Texture maps of diffuse and skin materials (MaterialTextures in material.hpp), looked up through
// one OpenImageIO TextureSystem per frame. The system is created only when some material has a
// map: frames without textures pay nothing.
//
// Lookups are bilinear in the finest mip level with zero derivatives (no filtering across pixel
// footprints: a map much finer than a pixel aliases, which pixel supersampling averages out).
// Wrap mode periodic, as glTF's default sampler (REPEAT). A lookup is deterministic, so the
// image stays independent of the thread count.
//
// sRGB albedo maps (TextureEncoding, material.hpp) are decoded after the bilinear interpolation,
// per channel with the IEC 61966-2-1 curve; interpolating encoded values first is exact on
// texel centres and differs from interpolating decoded ones only between texels of different
// values.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "lacrima/geometry/math.hpp"
#include "lacrima/materials/material.hpp"
#include "lacrima/materials/texture_values.hpp"


namespace lacrima {

class SurfaceTextures {
 public:
  // Opens every map of `materials` (materialId order); throws InputError naming the material and
  // the file when one cannot be read.
  explicit SurfaceTextures(const std::vector<Material>& materials);
  ~SurfaceTextures();
  SurfaceTextures(const SurfaceTextures&) = delete;
  SurfaceTextures& operator=(const SurfaceTextures&) = delete;

  bool textured(uint32_t materialId) const { return materialId < maps_.size() && maps_[materialId].any; }
  // The values of materialId's maps at uv (thread-safe).
  TextureValues lookup(uint32_t materialId, const Vec2& uv) const;

 private:
  struct OpenMap {
    void* handle = nullptr;  // OIIO::TextureSystem::TextureHandle
    int channels = 0;        // looked up (gray files are expanded to RGB by the system)
    bool srgb = false;
  };
  struct MaterialMaps {
    bool any = false;
    std::optional<OpenMap> albedo, roughness, normal, meanFreePath;
  };
  OpenMap open(const Material& material, const TextureMap& map, const char* role, bool colour);
  void sample(const OpenMap& map, const Vec2& uv, float* result) const;

  struct System;  // the OIIO TextureSystem
  std::unique_ptr<System> system_;
  std::vector<MaterialMaps> maps_;  // per material; empty when no material has maps
};

}  // namespace lacrima
