// Subdivision under details; see detail_refinement.hpp.
#include "resolve/detail_refinement.hpp"

#include <limits>
#include <optional>

#include "lacrima/rig/region_refinement.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "resolve/surface_attachment.hpp"

namespace lacrima::shotfile {

namespace {

// How far beyond the detail's ellipse, in the tangent plane, the mesh is refined: the snapped
// centre moves a little once the face is posed at the shot's first frame.
constexpr float kTangentMargin = 1.25f;

// The asset's primitives of `part` in world space, neutral (others left empty).
std::vector<TriangleMesh> neutralPartInWorld(const ShotAsset& asset, const GltfAsset& gltf, const std::string& part) {
  std::vector<TriangleMesh> world(gltf.primitives.size());
  for (size_t i = 0; i < gltf.primitives.size(); ++i) {
    if (gltf.primitives[i].part != part) continue;
    world[i] = gltf.primitives[i].mesh;
    transformMesh(world[i], asset.transform.matrix());
  }
  return world;
}

struct SkinPoint {
  Vec3 position, normal;
};

// The point of the part nearest to `target` and the skin normal there (ties: earlier primitive).
std::optional<SkinPoint> snapToPart(const std::vector<TriangleMesh>& world, const Vec3& target) {
  std::optional<SkinPoint> best;
  float bestDistance2 = std::numeric_limits<float>::infinity();
  for (size_t i = 0; i < world.size(); ++i) {
    if (world[i].triangleCount() == 0) continue;
    const SurfacePoint nearest = closestSurfacePoint(world[i], target);
    const Vec3 point = surfacePosition(world[i], nearest);
    const float d2 = (point - target).squaredNorm();
    if (!(d2 < bestDistance2)) continue;
    bestDistance2 = d2;
    ShotSurfacePoint attachment;
    attachment.primitive = i;
    attachment.triangle = nearest.triangle;
    attachment.barycentric = nearest.barycentric;
    best = SkinPoint{point, attachedNormal(world, attachment)};
  }
  return best;
}

// The detail's centre on the neutral part: a written point snapped to it, or the landmark, vertex
// or uv point of the anchor (checked when read).
std::optional<SkinPoint> anchorOnNeutralPart(const std::vector<TriangleMesh>& world, const GltfAsset& gltf,
                                             const std::string& part, const ShotSurfaceAnchor& anchor) {
  if (anchor.kind == ShotSurfaceAnchor::Kind::Point) return snapToPart(world, anchor.point);
  std::optional<size_t> primitive;
  for (size_t i = 0; i < gltf.primitives.size() && !primitive; ++i)
    if (gltf.primitives[i].part == part) primitive = i;
  std::optional<SurfacePoint> point;
  if (anchor.kind == ShotSurfaceAnchor::Kind::Landmark) {
    const Landmark& landmark = gltf.landmarks.at(anchor.index);
    primitive = size_t(landmark.primitive);
    point = vertexSurfacePoint(world[*primitive], landmark.vertex);
  } else if (primitive) {
    point = anchor.kind == ShotSurfaceAnchor::Kind::Vertex ? vertexSurfacePoint(world[*primitive], anchor.index)
                                                            : surfacePointAtUv(world[*primitive], anchor.uv);
  }
  if (!point) return std::nullopt;
  ShotSurfacePoint attachment;
  attachment.primitive = *primitive;
  attachment.triangle = point->triangle;
  attachment.barycentric = point->barycentric;
  return SkinPoint{surfacePosition(world[*primitive], *point), attachedNormal(world, attachment)};
}

void refineAroundDetail(const ShotAsset& asset, const ShotDetail& detail, GltfAsset& gltf) {
  const std::vector<TriangleMesh> world = neutralPartInWorld(asset, gltf, detail.part);
  const std::optional<SkinPoint> skin = anchorOnNeutralPart(world, gltf, detail.part, detail.center);
  if (!skin) return;
  const float maxExtent = std::max(detail.semiAxisA, detail.semiAxisB);
  for (size_t i = 0; i < gltf.primitives.size(); ++i) {
    if (world[i].triangleCount() == 0) continue;
    GltfPrimitive& primitive = gltf.primitives[i];
    const std::vector<bool> region =
        detailRegionTriangles(world[i], primitive.weldMap, skin->position, skin->normal, maxExtent);
    primitive = refinePrimitive(primitive, region, detail.subdivisionScheme, detail.subdivisionLevels);
  }
}

}  // namespace

std::vector<bool> detailRegionTriangles(const TriangleMesh& world, const std::vector<uint32_t>& weldMap,
                                        const Vec3& center, const Vec3& normal, float maxExtent) {
  std::vector<bool> inside(world.vertexCount(), false);
  for (size_t v = 0; v < world.vertexCount(); ++v) {
    const Vec3 d = world.positions[v] - center;
    const float along = d.dot(normal);
    inside[v] = (d - along * normal).norm() <= kTangentMargin * maxExtent && std::abs(along) <= maxExtent;
  }
  std::vector<bool> selected(world.triangleCount(), false);
  for (size_t t = 0; t < selected.size(); ++t)
    for (int k = 0; k < 3; ++k) selected[t] = selected[t] || inside[world.indices[3 * t + k]];
  // One more ring, across seams too: every triangle touching a selected corner's position.
  std::vector<bool> touched(world.vertexCount(), false);
  for (size_t t = 0; t < selected.size(); ++t)
    if (selected[t])
      for (int k = 0; k < 3; ++k) touched[weldMap.at(world.indices[3 * t + k])] = true;
  for (size_t t = 0; t < selected.size(); ++t)
    for (int k = 0; k < 3; ++k) selected[t] = selected[t] || touched[weldMap[world.indices[3 * t + k]]];
  return selected;
}

void refineDetailRegions(Shot& shot) {
  for (size_t a = 0; a < shot.assets.size(); ++a) {
    ShotAsset& asset = shot.assets[a];
    if (!asset.gltf) continue;
    std::shared_ptr<GltfAsset> refined;
    for (const ShotDetail& detail : shot.details) {
      if (detail.asset != a || detail.subdivisionLevels <= 0) continue;
      if (!refined) refined = std::make_shared<GltfAsset>(*asset.gltf);
      refineAroundDetail(asset, detail, *refined);
    }
    if (!refined) continue;
    asset.gltf = refined;
    // The rig copies the primitives and derives per-vertex jaw weights: rebuild it on the new ones.
    if (asset.rig) asset.rig = std::make_shared<const FaceRig>(*refined, asset.rig->config());
  }
}

}  // namespace lacrima::shotfile
