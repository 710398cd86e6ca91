// Surface anchors resolved; see surface_anchor.hpp.
#include "resolve/surface_anchor.hpp"

#include <fmt/format.h>

#include "asset_parts.hpp"
#include "asset_pose.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "resolve/surface_attachment.hpp"

namespace lacrima::shotfile {

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
