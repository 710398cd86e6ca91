#pragma once
// A small synthetic face asset for rig tests: a head ellipsoid with a jaw-open and a smile
// blendshape, and one eyeball (sclera sphere + iris cap) that no blendshape moves.
#include <string>
#include <vector>

#include "lacrima/rig/face_rig.hpp"
#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/mesh/shapes.hpp"
#include "lacrima/rig/skinning.hpp"

namespace lacrima::test {

inline const Vec3 kSyntheticJawPivot(0.0f, 0.0f, -0.02f);
inline const Vec3 kSyntheticEyeCenter(0.03f, 0.03f, 0.06f);
inline constexpr float kSyntheticEyeRadius = 0.012f;
inline constexpr float kSyntheticJawOpenDegrees = 12.0f;

inline GltfPrimitive makeSyntheticPrimitive(const std::string& part, TriangleMesh mesh, size_t targetCount) {
  GltfPrimitive p;
  p.part = part;
  p.name = "Synthetic/" + part;
  p.mesh = std::move(mesh);
  p.mesh.name = p.name;
  p.weldMap = findCoincidentVertices(p.mesh);
  computeSmoothNormals(p.mesh, p.weldMap);
  p.targets.resize(targetCount);
  return p;
}

// Targets: 0 "jawOpen" (lower half rotated about kSyntheticJawPivot, linearised as a delta),
// 1 "mouthSmile" (front vertices pushed out and up).
inline GltfAsset makeSyntheticFace() {
  GltfAsset asset;
  asset.targetNames = {"jawOpen", "mouthSmile"};
  GltfPrimitive face = makeSyntheticPrimitive("M_Face", makeEllipsoid(Vec3::Zero(), Mat3(Vec3(0.08f, 0.11f, 0.1f).asDiagonal()), 12, 24), 2);
  const Affine3 open = jointTransform(RigidJoint{Vec3(kSyntheticJawOpenDegrees, 0, 0), Vec3::Zero()}, kSyntheticJawPivot);
  for (uint32_t v = 0; v < face.mesh.vertexCount(); ++v) {
    const Vec3& p = face.mesh.positions[v];
    if (p.y() < -0.02f) {
      face.targets[0].vertices.push_back(v);
      face.targets[0].deltas.push_back(open * p - p);
    }
    if (p.z() > 0.05f) {
      face.targets[1].vertices.push_back(v);
      face.targets[1].deltas.push_back(Vec3(0.0f, 0.004f, 0.002f) * (1.0f + p.x()));
    }
  }
  asset.primitives.push_back(std::move(face));
  asset.primitives.push_back(makeSyntheticPrimitive(
      "M_ScleraLeft", makeEllipsoid(kSyntheticEyeCenter, Mat3(Mat3::Identity() * kSyntheticEyeRadius), 10, 20), 2));
  const Vec3 irisCenter = kSyntheticEyeCenter + Vec3(0, 0, kSyntheticEyeRadius * 0.9f);
  asset.primitives.push_back(makeSyntheticPrimitive(
      "M_IrisLeft", makeEllipsoid(irisCenter, Mat3(Vec3(0.005f, 0.005f, 0.001f).asDiagonal()), 6, 12), 2));
  return asset;
}

inline FaceRigConfig syntheticRigConfig() {
  FaceRigConfig config;
  config.headPivot = Vec3(0.0f, -0.11f, 0.0f);
  config.jawPivot = kSyntheticJawPivot;
  config.eyes = {{"left", "M_ScleraLeft", {"M_ScleraLeft", "M_IrisLeft"}}};
  return config;
}

}  // namespace lacrima::test
