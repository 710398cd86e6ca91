#include "lacrima/materials/texture_values.hpp"

#include <algorithm>
#include <cmath>

namespace lacrima {

namespace {

Color clampUnit(const Color& c) { return c.cwiseMax(0.0f).cwiseMin(1.0f); }

}  // namespace

float srgbToLinear(float encoded) {
  // IEC 61966-2-1: linear segment below 0.04045, a 2.4 power above.
  if (encoded <= 0.04045f) return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

MaterialParams applyTextureValues(const MaterialParams& params, const TextureValues& values) {
  if (const auto* diffuse = std::get_if<DiffuseParams>(&params)) {
    DiffuseParams p = *diffuse;
    if (values.albedo) p.albedo = clampUnit(p.albedo * *values.albedo);
    return p;
  }
  if (const auto* skin = std::get_if<SkinParams>(&params)) {
    SkinParams p = *skin;
    if (values.albedo) p.albedo = p.albedo * *values.albedo;  // SkinBsdf clamps to [0, kMaxSkinAlbedo]
    if (values.roughness) {
      const float scale = std::max(0.0f, *values.roughness);
      p.roughness = std::min(1.0f, p.roughness * scale);
      p.roughness2 = std::min(1.0f, p.roughness2 * scale);
    }
    if (values.meanFreePath && p.subsurface)
      p.subsurface->meanFreePath = p.subsurface->meanFreePath * values.meanFreePath->cwiseMax(1e-4f);
    return p;
  }
  return params;  // dielectrics take no maps (the shot loader refuses them)
}

Vec3 applyNormalMap(const Vec3& tangentNormal, const Vec3& ns, const Vec3& dpdu, const Vec3& dpdv) {
  const Vec3 along = dpdu - ns * ns.dot(dpdu);  // Gram-Schmidt against the shading normal
  const float length = along.norm();
  if (!(length > 1e-12f)) return ns;
  const Vec3 tangent = along / length;
  Vec3 bitangent = ns.cross(tangent);
  if (bitangent.dot(dpdv) > 0.0f) bitangent = -bitangent;  // +Y is up the image: decreasing v
  const Vec3 n = tangentNormal.x() * tangent + tangentNormal.y() * bitangent + tangentNormal.z() * ns;
  const float nLength = n.norm();
  return nLength > 1e-12f ? Vec3(n / nLength) : ns;
}

}  // namespace lacrima
