// Surface attachments; see surface_attachment.hpp.
#include "resolve/surface_attachment.hpp"

#include <limits>

#include "asset_pose.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "resolve/surface_anchor.hpp"

namespace lacrima::shotfile {

namespace {

Vec3 pointOnTriangle(const TriangleMesh& mesh, uint32_t triangle, const Vec3& barycentric) {
  return surfacePosition(mesh, SurfacePoint{triangle, barycentric});
}

}  // namespace

ShotShape::Attachment nearestSurfacePoint(const Shot& shot, size_t assetIndex, const std::string& part,
                                          const Vec3& target, double frame) {
  const ShotAsset& asset = shot.assets[assetIndex];
  const AssetPose pose = assetPoseAt(asset, frame);
  ShotShape::Attachment best;
  best.asset = assetIndex;
  float bestDistance2 = std::numeric_limits<float>::infinity();
  for (size_t i = 0; i < asset.gltf->primitives.size(); ++i) {
    if (asset.gltf->primitives[i].part != part) continue;
    const TriangleMesh mesh = posedPrimitive(asset, pose, i);
    if (mesh.triangleCount() == 0) continue;
    const SurfacePoint nearest = closestSurfacePoint(mesh, target);
    const Vec3 point = surfacePosition(mesh, nearest);
    const float d2 = (point - target).squaredNorm();
    if (d2 < bestDistance2) {  // ties keep the earlier primitive
      bestDistance2 = d2;
      best.primitive = i;
      best.triangle = nearest.triangle;
      best.barycentric = nearest.barycentric;
      best.reference = point;
    }
  }
  return best;
}

namespace {

ShotShape::Attachment nearestOnPart(const Shot& shot, size_t assetIndex, const std::string& part, const Vec3& target) {
  return nearestSurfacePoint(shot, assetIndex, part, target, double(shot.frameStart));
}

}  // namespace

void resolveAttachments(Shot& shot) {
  for (ShotShape& shape : shot.shapes) {
    if (shape.attachAsset.empty()) continue;
    for (size_t a = 0; a < shot.assets.size(); ++a) {
      if (shot.assets[a].name != shape.attachAsset || !shot.assets[a].gltf) continue;
      const Vec3 center = shape.centerCurve ? shape.centerCurve->evaluate(float(shot.frameStart)) : shape.center;
      shape.attachment = nearestOnPart(shot, a, shape.attachPart, center);
    }
  }
}

void resolveTearsAndDetails(Shot& shot) {
  for (ShotTear& tear : shot.tears) {
    if (!shot.assets[tear.asset].gltf) continue;
    tear.surfacePoint = resolveSurfaceAnchor(shot, tear.asset, tear.part, tear.start);
    // The skin point follows the face until the drop starts, then the drop leaves from there.
    const ShotAsset& asset = shot.assets[tear.asset];
    const AssetPose pose = assetPoseAt(asset, tear.startFrame);
    const TriangleMesh mesh = posedPrimitive(asset, pose, tear.surfacePoint.primitive);
    tear.origin = pointOnTriangle(mesh, tear.surfacePoint.triangle, tear.surfacePoint.barycentric);
  }
  for (ShotDetail& detail : shot.details)
    if (shot.assets[detail.asset].gltf)
      detail.surfacePoint = resolveSurfaceAnchor(shot, detail.asset, detail.part, detail.center);
}

Vec3 attachedNormal(const std::vector<TriangleMesh>& posedPrimitives, const ShotShape::Attachment& attachment) {
  const TriangleMesh& mesh = posedPrimitives[attachment.primitive];
  const uint32_t* t = &mesh.indices[3 * size_t(attachment.triangle)];
  const Vec3 geometric = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
  if (mesh.normals.size() == mesh.positions.size()) {
    const Vec3 n = attachment.barycentric.x() * mesh.normals[t[0]] + attachment.barycentric.y() * mesh.normals[t[1]] +
                   attachment.barycentric.z() * mesh.normals[t[2]];
    if (n.squaredNorm() > 1e-12f) return n.normalized();
  }
  return geometric.squaredNorm() > 0.0f ? geometric.normalized() : Vec3(Vec3::UnitZ());
}

Vec3 attachedPoint(const std::vector<TriangleMesh>& posedPrimitives, const ShotShape::Attachment& attachment) {
  return pointOnTriangle(posedPrimitives[attachment.primitive], attachment.triangle, attachment.barycentric);
}

}  // namespace lacrima::shotfile
