#include "surface_textures.hpp"

#include <OpenImageIO/texture.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

constexpr int kColourChannels = 3;

// One TextureSystem for the process, made when a first frame has maps and never destroyed: its
// cache of tiles and of the MIP levels built on the fly outlives a frame, so a sequence reads and
// filters each map once instead of once per frame (about 15 % of a frame's time with a 1024^2
// albedo map). The cache is bounded by OIIO's max_memory_MB.
OIIO::TextureSystem& processTextureSystem() {
  static OIIO::TextureSystem* const textures = [] {
    OIIO::TextureSystem* made = OIIO::TextureSystem::create(false);  // lacrima's own, not OIIO's shared one
    // One-channel (grey) maps read as RGB where three channels are asked for.
    made->attribute("gray_to_rgb", 1);
    // Plain images (PNG, flat EXR) get MIP levels built when first needed; maketx files have theirs.
    made->attribute("automip", 1);
    return made;
  }();
  return *textures;
}

}  // namespace

UvFootprint uvFootprint(float width, const Vec3& dpdu, const Vec3& dpdv) {
  const float lengthU = dpdu.norm(), lengthV = dpdv.norm();
  if (!(width > 0.0f) || !(lengthU > 0.0f) || !(lengthV > 0.0f)) return {};
  return {width / lengthU, width / lengthV};
}

SurfaceTextures::SurfaceTextures(const std::vector<Material>& materials) {
  const bool anyMaps = std::any_of(materials.begin(), materials.end(), [](const Material& m) { return m.textures.any(); });
  if (!anyMaps) return;
  const bool anyFiles =
      std::any_of(materials.begin(), materials.end(), [](const Material& m) { return m.textures.anyFile(); });
  if (anyFiles) textures_ = &processTextureSystem();
  maps_.resize(materials.size());
  for (size_t id = 0; id < materials.size(); ++id) {
    const Material& m = materials[id];
    MaterialMaps& maps = maps_[id];
    maps.any = m.textures.any();
    if (m.textures.albedo) maps.albedo = open(m, *m.textures.albedo, "albedo", true);
    if (m.textures.irisPattern) maps.iris.emplace(m.textures.irisPattern->seed);
    if (m.textures.roughness) maps.roughness = open(m, *m.textures.roughness, "roughness", false);
    if (m.textures.normal) maps.normal = open(m, *m.textures.normal, "normal", false);
    if (m.textures.meanFreePath) maps.meanFreePath = open(m, *m.textures.meanFreePath, "meanFreePath", false);
  }
}

SurfaceTextures::~SurfaceTextures() = default;

// colour: an albedo map, the only kind whose Auto encoding can be sRGB (material.hpp).
SurfaceTextures::OpenMap SurfaceTextures::open(const Material& material, const TextureMap& map, const char* role,
                                               bool colour) {
  OIIO::TextureSystem& ts = *textures_;
  const OIIO::ustring name(map.file.string());
  // A map rewritten since an earlier frame opened it is read again (its modification time).
  ts.invalidate(name, false);
  OIIO::TextureSystem::TextureHandle* handle = ts.get_texture_handle(name);
  OIIO::ImageSpec spec;
  if (!handle || !ts.get_imagespec(handle, nullptr, 0, spec))
    throw InputError(fmt::format("material '{}': cannot read the {} texture '{}': {}", material.name, role,
                                 map.file.string(), ts.geterror()));
  OpenMap open;
  open.handle = handle;
  open.channels = std::string_view(role) == "roughness" ? 1 : kColourChannels;
  const bool integerSamples = !spec.format.is_floating_point();
  open.srgb = colour && (map.encoding == TextureEncoding::Srgb ||
                         (map.encoding == TextureEncoding::Auto && integerSamples));
  return open;
}

void SurfaceTextures::sample(const OpenMap& map, const Vec2& uv, const UvFootprint& footprint, float* result) const {
  OIIO::TextureSystem& ts = *textures_;
  OIIO::TextureOpt options;
  options.swrap = options.twrap = OIIO::TextureOpt::WrapPeriodic;
  options.mipmode = OIIO::TextureOpt::MipModeTrilinear;
  options.interpmode = OIIO::TextureOpt::InterpBilinear;
  // OIIO's t runs down the image like glTF's v: uv is passed as it is. The footprint is given as
  // the derivatives of an axis-aligned pixel (ds/dx = du, dt/dy = dv).
  if (!ts.texture(static_cast<OIIO::TextureSystem::TextureHandle*>(map.handle), ts.get_perthread_info(), options,
                  uv.x(), uv.y(), footprint.du, 0.0f, 0.0f, footprint.dv, map.channels, result))
    std::fill(result, result + map.channels, 1.0f);  // unreadable tile: the constants alone (checked at open)
  if (map.srgb)
    for (int c = 0; c < map.channels; ++c) result[c] = srgbToLinear(result[c]);
}

TextureValues SurfaceTextures::lookup(uint32_t materialId, const Vec2& uv, const UvFootprint& footprint) const {
  const MaterialMaps& maps = maps_[materialId];
  TextureValues values;
  float rgb[kColourChannels];
  if (maps.albedo) {
    sample(*maps.albedo, uv, footprint, rgb);
    values.albedo = Color(rgb[0], rgb[1], rgb[2]);
  }
  // Point-sampled: the pixel's samples average the pattern (its finest fibres are ~0.1 mm apart).
  if (maps.iris) values.albedo = maps.iris->factorAt(uv);
  if (maps.roughness) {
    sample(*maps.roughness, uv, footprint, rgb);
    values.roughness = rgb[0];
  }
  if (maps.normal) {
    sample(*maps.normal, uv, footprint, rgb);
    const Vec3 n(2.0f * rgb[0] - 1.0f, 2.0f * rgb[1] - 1.0f, 2.0f * rgb[2] - 1.0f);
    // A texel that points below the surface (or nowhere) leaves the normal as it is.
    values.normal = n.z() > 1e-4f ? Vec3(n.normalized()) : Vec3(0.0f, 0.0f, 1.0f);
  }
  if (maps.meanFreePath) {
    sample(*maps.meanFreePath, uv, footprint, rgb);
    values.meanFreePath = Color(rgb[0], rgb[1], rgb[2]);
  }
  return values;
}

}  // namespace lacrima
