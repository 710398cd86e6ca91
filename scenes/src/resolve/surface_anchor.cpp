// Surface anchors; see surface_anchor.hpp.
#include "resolve/surface_anchor.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

#include "asset_pose.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "resolve/surface_attachment.hpp"

namespace lacrima::shotfile {

namespace {

constexpr const char* kAnchorForms = "[x, y, z], {\"landmark\": i}, {\"vertex\": i} or {\"uv\": [u, v]}";

std::vector<size_t> primitivesOfPart(const GltfAsset& gltf, const std::string& part) {
  std::vector<size_t> found;
  for (size_t i = 0; i < gltf.primitives.size(); ++i)
    if (gltf.primitives[i].part == part) found.push_back(i);
  return found;
}

// The single primitive of a part, for vertex and uv anchors; reports a part of several.
std::optional<size_t> singlePrimitive(ObjectReader& o, const std::string& key, const GltfAsset& gltf,
                                      const std::string& part) {
  const std::vector<size_t> primitives = primitivesOfPart(gltf, part);
  if (primitives.size() == 1) return primitives[0];
  o.error(key, fmt::format("part '{}' is made of {} primitives, so a {} index is ambiguous; use a point or a landmark",
                           part, primitives.size(), key));
  return std::nullopt;
}

std::optional<ShotSurfaceAnchor> readLandmark(ObjectReader& o, const GltfAsset& gltf, const std::string& part) {
  if (gltf.landmarks.empty()) {
    o.error("landmark", fmt::format("'{}' has no landmarks (glTF nodes[0].extras.landmarks68)",
                                    gltf.path.filename().string()));
    return std::nullopt;
  }
  const auto index = o.integer("landmark", Range::closed(0, double(gltf.landmarks.size() - 1)));
  if (!index) return std::nullopt;
  const Landmark& landmark = gltf.landmarks[size_t(*index)];
  const std::string& landmarkPart = gltf.primitives[size_t(landmark.primitive)].part;
  if (landmarkPart != part) {
    o.error("landmark", fmt::format("landmark {} is a vertex of part '{}', not of '{}'", *index, landmarkPart, part));
    return std::nullopt;
  }
  ShotSurfaceAnchor anchor;
  anchor.kind = ShotSurfaceAnchor::Kind::Landmark;
  anchor.index = uint32_t(*index);
  return anchor;
}

std::optional<ShotSurfaceAnchor> readVertex(ObjectReader& o, const GltfAsset& gltf, const std::string& part) {
  const auto primitive = singlePrimitive(o, "vertex", gltf, part);
  if (!primitive) return std::nullopt;
  const TriangleMesh& mesh = gltf.primitives[*primitive].mesh;
  const auto index = o.integer("vertex", Range::closed(0, double(mesh.vertexCount()) - 1));
  if (!index) return std::nullopt;
  if (!vertexSurfacePoint(mesh, uint32_t(*index))) {
    o.error("vertex", fmt::format("vertex {} of part '{}' belongs to no triangle", *index, part));
    return std::nullopt;
  }
  ShotSurfaceAnchor anchor;
  anchor.kind = ShotSurfaceAnchor::Kind::Vertex;
  anchor.index = uint32_t(*index);
  return anchor;
}

std::optional<ShotSurfaceAnchor> readUv(ObjectReader& o, const GltfAsset& gltf, const std::string& part) {
  const auto primitive = singlePrimitive(o, "uv", gltf, part);
  if (!primitive) return std::nullopt;
  const auto uv = readVec2(o.checker(), *o.find("uv"), o.at("uv"), Range::any(), "[u, v]");
  if (!uv) return std::nullopt;
  const TriangleMesh& mesh = gltf.primitives[*primitive].mesh;
  if (mesh.uvs.empty()) {
    o.error("uv", fmt::format("part '{}' has no texture coordinates (TEXCOORD_0)", part));
    return std::nullopt;
  }
  if (!surfacePointAtUv(mesh, *uv)) {
    o.error("uv", fmt::format("no triangle of part '{}' covers uv [{}, {}]", part, uv->x(), uv->y()));
    return std::nullopt;
  }
  ShotSurfaceAnchor anchor;
  anchor.kind = ShotSurfaceAnchor::Kind::Uv;
  anchor.uv = *uv;
  return anchor;
}

}  // namespace

namespace {

// A landmark or vertex index as readInteger would take it (5 or 5.0); 0 for anything else, which
// checkSurfaceAnchor reports.
uint32_t indexAsWritten(const Json& x) {
  if (!x.is_number()) return 0;
  const double d = x.get<double>();
  return d >= 0.0 && d <= double(UINT32_MAX) && d == std::floor(d) ? uint32_t(d) : 0;
}

}  // namespace

std::optional<ShotSurfaceAnchor> readSurfaceAnchor(Checker& c, const Json& value, const std::string& pointer) {
  if (value.is_array()) {
    const auto point = readVec3(c, value, pointer);
    if (!point) return std::nullopt;
    ShotSurfaceAnchor anchor;
    anchor.point = *point;
    return anchor;
  }
  if (!value.is_object() || value.size() != 1) {
    c.error(pointer, Anchor::Value,
            fmt::format("expected a surface anchor, {}; found {}", kAnchorForms, describeValue(value)));
    return std::nullopt;
  }
  ObjectReader o(c, value, pointer, {"landmark", "vertex", "uv"});
  if (!o.ok()) return std::nullopt;
  ShotSurfaceAnchor anchor;
  // The value as written, taken without a report: checkSurfaceAnchor reports a bad one with the
  // bounds the asset gives it.
  if (const Json* x = o.find("landmark")) {
    anchor.kind = ShotSurfaceAnchor::Kind::Landmark;
    anchor.index = indexAsWritten(*x);
  } else if (const Json* x = o.find("vertex")) {
    anchor.kind = ShotSurfaceAnchor::Kind::Vertex;
    anchor.index = indexAsWritten(*x);
  } else if (const Json* x = o.find("uv")) {
    anchor.kind = ShotSurfaceAnchor::Kind::Uv;
    if (x->is_array() && x->size() == 2 && (*x)[0].is_number() && (*x)[1].is_number())
      anchor.uv = Vec2((*x)[0].get<float>(), (*x)[1].get<float>());
  } else {
    return std::nullopt;  // its one key is unknown, and reported
  }
  return anchor;
}

bool checkSurfaceAnchor(Checker& c, const Json& value, const std::string& pointer, const GltfAsset& gltf,
                        const std::string& part) {
  // The reading phase has checked that the object's one key is known: this reports nothing new.
  ObjectReader o(c, value, pointer, {"landmark", "vertex", "uv"});
  if (o.has("landmark")) return readLandmark(o, gltf, part).has_value();
  if (o.has("vertex")) return readVertex(o, gltf, part).has_value();
  return readUv(o, gltf, part).has_value();
}

ShotSurfacePoint resolveSurfaceAnchor(const Shot& shot, size_t assetIndex, const std::string& part,
                                      const ShotSurfaceAnchor& anchor) {
  const double firstFrame = double(shot.frameStart);
  if (anchor.kind == ShotSurfaceAnchor::Kind::Point)
    return nearestSurfacePoint(shot, assetIndex, part, anchor.point, firstFrame);
  const ShotAsset& asset = shot.assets[assetIndex];
  const GltfAsset& gltf = *asset.gltf;
  size_t primitive = 0;
  std::optional<SurfacePoint> point;
  if (anchor.kind == ShotSurfaceAnchor::Kind::Landmark) {
    const Landmark& landmark = gltf.landmarks.at(anchor.index);
    primitive = size_t(landmark.primitive);
    point = vertexSurfacePoint(gltf.primitives[primitive].mesh, landmark.vertex);
  } else {
    primitive = primitivesOfPart(gltf, part).at(0);
    const TriangleMesh& mesh = gltf.primitives[primitive].mesh;
    point = anchor.kind == ShotSurfaceAnchor::Kind::Vertex ? vertexSurfacePoint(mesh, anchor.index)
                                                            : surfacePointAtUv(mesh, anchor.uv);
  }
  // Checked when read; a refinement of the mesh keeps vertices and uv coverage.
  if (!point) throw InputError(fmt::format("{}: a surface anchor on part '{}' no longer resolves", shot.path.string(), part));
  ShotSurfacePoint resolved;
  resolved.asset = assetIndex;
  resolved.primitive = primitive;
  resolved.triangle = point->triangle;
  resolved.barycentric = point->barycentric;
  const TriangleMesh posed = posedPrimitive(asset, assetPoseAt(asset, firstFrame), primitive);
  resolved.reference = surfacePosition(posed, *point);
  return resolved;
}

std::vector<bool> trianglesWithinRegions(const TriangleMesh& mesh, const std::vector<ShotSkinRegion>& regions) {
  std::vector<bool> inside(mesh.triangleCount(), false);
  for (size_t t = 0; t < inside.size(); ++t)
    for (const ShotSkinRegion& region : regions) {
      bool all = true;
      for (int c = 0; c < 3; ++c)
        all = all && (mesh.positions[mesh.indices[3 * t + size_t(c)]] - region.centerPoint.reference).norm() <= region.radius;
      if (all) {
        inside[t] = true;
        break;
      }
    }
  return inside;
}

}  // namespace lacrima::shotfile
