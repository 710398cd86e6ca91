// Surface attachments; see surface_attachment.hpp.
#include "surface_attachment.hpp"

#include <limits>

#include "asset_pose.hpp"

namespace lacrima::shotfile {

namespace {

// Barycentric coordinates of the point of triangle abc closest to p (Ericson, "Real-Time
// Collision Detection", 2005, section 5.1.5, ClosestPtPointTriangle).
Vec3 closestBarycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return Vec3(1, 0, 0);
  const Vec3 bp = p - b;
  const float d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0f && d4 <= d3) return Vec3(0, 1, 0);
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) {
    const float v = d1 / (d1 - d3);
    return Vec3(1 - v, v, 0);
  }
  const Vec3 cp = p - c;
  const float d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0f && d5 <= d6) return Vec3(0, 0, 1);
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) {
    const float w = d2 / (d2 - d6);
    return Vec3(1 - w, 0, w);
  }
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
    const float w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return Vec3(0, 1 - w, w);
  }
  const float denom = 1.0f / (va + vb + vc);
  const float v = vb * denom, w = vc * denom;
  return Vec3(1 - v - w, v, w);
}

Vec3 pointOnTriangle(const TriangleMesh& mesh, uint32_t triangle, const Vec3& barycentric) {
  const uint32_t* t = &mesh.indices[3 * size_t(triangle)];
  return barycentric.x() * mesh.positions[t[0]] + barycentric.y() * mesh.positions[t[1]] +
         barycentric.z() * mesh.positions[t[2]];
}

// The nearest surface point of the part's primitives to `target`.
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
    for (uint32_t t = 0; t < mesh.triangleCount(); ++t) {
      const uint32_t* v = &mesh.indices[3 * size_t(t)];
      const Vec3 bary = closestBarycentric(target, mesh.positions[v[0]], mesh.positions[v[1]], mesh.positions[v[2]]);
      const Vec3 point = pointOnTriangle(mesh, t, bary);
      const float d2 = (point - target).squaredNorm();
      if (d2 < bestDistance2) {
        bestDistance2 = d2;
        best.primitive = i;
        best.triangle = t;
        best.barycentric = bary;
        best.reference = point;
      }
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
    tear.surfacePoint = nearestSurfacePoint(shot, tear.asset, tear.part, tear.start, double(shot.frameStart));
    // The skin point follows the face until the drop starts, then the drop leaves from there.
    const ShotAsset& asset = shot.assets[tear.asset];
    const AssetPose pose = assetPoseAt(asset, tear.startFrame);
    const TriangleMesh mesh = posedPrimitive(asset, pose, tear.surfacePoint.primitive);
    tear.origin = pointOnTriangle(mesh, tear.surfacePoint.triangle, tear.surfacePoint.barycentric);
  }
  for (ShotDetail& detail : shot.details)
    if (shot.assets[detail.asset].gltf)
      detail.surfacePoint = nearestSurfacePoint(shot, detail.asset, detail.part, detail.center, double(shot.frameStart));
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
