// Checking a surface anchor against the loaded asset; see surface_anchor_check.hpp.
#include "load/surface_anchor_check.hpp"

#include <fmt/format.h>

#include "asset_parts.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

namespace {

// The single primitive of a part, for vertex and uv anchors; reports a part of several.
std::optional<size_t> singlePrimitive(ObjectReader& o, const std::string& key, const GltfAsset& gltf,
                                      const std::string& part) {
  const std::vector<size_t> primitives = primitivesOfPart(gltf, part);
  if (primitives.size() == 1) return primitives[0];
  o.error(key, fmt::format("part '{}' is made of {} primitives, so a {} index is ambiguous; use a point or a landmark",
                           part, primitives.size(), key));
  return std::nullopt;
}

bool checkLandmark(ObjectReader& o, const GltfAsset& gltf, const std::string& part) {
  if (gltf.landmarks.empty()) {
    o.error("landmark", fmt::format("'{}' has no landmarks (glTF nodes[0].extras.landmarks68)",
                                    gltf.path.filename().string()));
    return false;
  }
  const auto index = o.integer("landmark", Range::closed(0, double(gltf.landmarks.size() - 1)));
  if (!index) return false;
  const Landmark& landmark = gltf.landmarks[size_t(*index)];
  const std::string& landmarkPart = gltf.primitives[size_t(landmark.primitive)].part;
  if (landmarkPart != part) {
    o.error("landmark", fmt::format("landmark {} is a vertex of part '{}', not of '{}'", *index, landmarkPart, part));
    return false;
  }
  return true;
}

bool checkVertex(ObjectReader& o, const GltfAsset& gltf, const std::string& part) {
  const auto primitive = singlePrimitive(o, "vertex", gltf, part);
  if (!primitive) return false;
  const TriangleMesh& mesh = gltf.primitives[*primitive].mesh;
  const auto index = o.integer("vertex", Range::closed(0, double(mesh.vertexCount()) - 1));
  if (!index) return false;
  if (!vertexSurfacePoint(mesh, uint32_t(*index))) {
    o.error("vertex", fmt::format("vertex {} of part '{}' belongs to no triangle", *index, part));
    return false;
  }
  return true;
}

bool checkUv(ObjectReader& o, const GltfAsset& gltf, const std::string& part) {
  const auto primitive = singlePrimitive(o, "uv", gltf, part);
  if (!primitive) return false;
  const auto uv = readVec2(o.checker(), *o.find("uv"), o.at("uv"), Range::any(), "[u, v]");
  if (!uv) return false;
  const TriangleMesh& mesh = gltf.primitives[*primitive].mesh;
  if (mesh.uvs.empty()) {
    o.error("uv", fmt::format("part '{}' has no texture coordinates (TEXCOORD_0)", part));
    return false;
  }
  if (!surfacePointAtUv(mesh, *uv)) {
    o.error("uv", fmt::format("no triangle of part '{}' covers uv [{}, {}]", part, uv->x(), uv->y()));
    return false;
  }
  return true;
}

}  // namespace

bool checkSurfaceAnchor(Checker& c, const Json& value, const std::string& pointer, const GltfAsset& gltf,
                        const std::string& part) {
  // The reading phase has checked that the object's one key is known: this reports nothing new.
  ObjectReader o(c, value, pointer, {"landmark", "vertex", "uv"});
  if (o.has("landmark")) return checkLandmark(o, gltf, part);
  if (o.has("vertex")) return checkVertex(o, gltf, part);
  return checkUv(o, gltf, part);
}

}  // namespace lacrima::shotfile
