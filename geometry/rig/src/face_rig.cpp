// Face rig: x(b, j) = T(j)(n + B b) per primitive (Bao et al. 2019, eq. 1).
#include "lacrima/rig/face_rig.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include <Eigen/Dense>

#include "lacrima/base/error.hpp"
#include "lacrima/base/name_suggestion.hpp"
#include "lacrima/rig/region_refinement.hpp"
#include "lacrima/base/vertex_ranges.hpp"

namespace lacrima {

namespace {

std::vector<std::string> partNames(const std::vector<GltfPrimitive>& primitives) {
  std::vector<std::string> names;
  for (const GltfPrimitive& p : primitives) names.push_back(p.part);
  return names;
}

size_t findPart(const std::vector<GltfPrimitive>& primitives, const std::string& part) {
  for (size_t i = 0; i < primitives.size(); ++i)
    if (primitives[i].part == part) return i;
  throw InputError(unknownNameMessage("face part", part, partNames(primitives)));
}

size_t findTargetOrThrow(const std::vector<std::string>& targetNames, const std::string& name) {
  for (size_t i = 0; i < targetNames.size(); ++i)
    if (targetNames[i] == name) return i;
  throw InputError(unknownNameMessage("blendshape", name, targetNames));
}

// The loader guarantees these; the rig indexes positions with them unchecked in the hot loop.
void requireValidTargets(const GltfPrimitive& primitive) {
  for (size_t k = 0; k < primitive.targets.size(); ++k) {
    const SparseDelta& t = primitive.targets[k];
    if (t.vertices.size() != t.deltas.size() ||
        (!t.vertices.empty() && t.vertices.back() >= primitive.mesh.vertexCount()) ||
        std::adjacent_find(t.vertices.begin(), t.vertices.end(), std::greater_equal<>()) != t.vertices.end())
      throw std::invalid_argument(fmt::format("face rig: target {} of {} is malformed", k, primitive.name));
  }
}

// Bao et al. 2019 eq. 1, the pre-skinning shape n + B b; returns whether any vertex moved.
bool addBlendshapes(std::vector<Vec3>& positions, const GltfPrimitive& primitive, const std::vector<float>& weights) {
  std::vector<size_t> active;  // most weights are zero in any frame
  const size_t used = std::min(weights.size(), primitive.targets.size());
  for (size_t k = 0; k < used; ++k)
    if (weights[k] != 0.0f && !primitive.targets[k].vertices.empty()) active.push_back(k);
  if (active.empty()) return false;
  // Each vertex adds its targets' deltas in target order; a range finds each target's vertices in it
  // by their ascending indices.
  forVertexRanges(positions.size(), [&](uint32_t begin, uint32_t end) {
    for (const size_t k : active) {
      const SparseDelta& target = primitive.targets[k];
      const float w = weights[k];
      auto it = std::lower_bound(target.vertices.begin(), target.vertices.end(), begin);
      for (; it != target.vertices.end() && *it < end; ++it)
        positions[*it] += w * target.deltas[size_t(it - target.vertices.begin())];
    }
  });
  return true;
}

void transformPositions(std::vector<Vec3>& positions, const Affine3& t) {
  forVertexRanges(positions.size(), [&](uint32_t begin, uint32_t end) {
    for (uint32_t v = begin; v < end; ++v) positions[v] = t * positions[v];
  });
}

// Jaw weight per vertex: |delta| / (largest |delta| of the target over all primitives).
std::vector<std::vector<float>> jawWeightsFromTarget(const std::vector<GltfPrimitive>& primitives, size_t target) {
  float largest = 0.0f;
  for (const GltfPrimitive& p : primitives)
    if (target < p.targets.size())
      for (const Vec3& d : p.targets[target].deltas) largest = std::max(largest, d.norm());
  std::vector<std::vector<float>> weights(primitives.size());
  if (largest == 0.0f) return weights;
  for (size_t i = 0; i < primitives.size(); ++i) {
    if (target >= primitives[i].targets.size() || primitives[i].targets[target].vertices.empty()) continue;
    const SparseDelta& t = primitives[i].targets[target];
    weights[i].assign(primitives[i].mesh.vertexCount(), 0.0f);
    for (size_t j = 0; j < t.vertices.size(); ++j) weights[i][t.vertices[j]] = t.deltas[j].norm() / largest;
  }
  return weights;
}

}  // namespace

JawHinge estimateJawHinge(const GltfPrimitive& primitive, size_t target) {
  if (target >= primitive.targets.size() || primitive.targets[target].vertices.size() < 3)
    throw InputError(fmt::format("jaw hinge: target {} moves fewer than 3 vertices of {}", target, primitive.name));
  const SparseDelta& t = primitive.targets[target];
  // A rotation about an x-parallel axis through c moves (y, z) by d = (R - I)(p - c), which is
  // linear in (a, s, u, v) = (cos θ - 1, sin θ, -(R - I)c):
  //   d_y = a p_y - s p_z + u,   d_z = s p_y + a p_z + v   (Rodrigues 1840, rotation about the x axis)
  const Eigen::Index n = Eigen::Index(t.vertices.size());
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(2 * n, 4);
  Eigen::VectorXd d(2 * n);
  double meanX = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vec3d p = primitive.mesh.positions[t.vertices[size_t(i)]].cast<double>();
    const Vec3d delta = t.deltas[size_t(i)].cast<double>();
    m.row(2 * i) << p.y(), -p.z(), 1.0, 0.0;
    m.row(2 * i + 1) << p.z(), p.y(), 0.0, 1.0;
    d(2 * i) = delta.y();
    d(2 * i + 1) = delta.z();
    meanX += p.x();
  }
  const Eigen::Vector4d x = m.colPivHouseholderQr().solve(d);
  const double a = x(0), s = x(1);
  Eigen::Matrix2d rotationMinusIdentity;
  rotationMinusIdentity << a, -s, s, a;
  if (std::abs(rotationMinusIdentity.determinant()) < 1e-12)
    throw InputError(fmt::format("jaw hinge: target {} does not rotate {}", target, primitive.name));
  const Eigen::Vector2d centerYz = -rotationMinusIdentity.inverse() * x.tail<2>();
  JawHinge hinge;
  hinge.pivot = Vec3(float(meanX / double(n)), float(centerYz.x()), float(centerYz.y()));
  hinge.openingDegrees = float(std::atan2(s, 1.0 + a) * 180.0 / std::numbers::pi);
  return hinge;
}

FaceRigConfig ictFaceRigConfig(const GltfAsset& asset) {
  FaceRigConfig config;
  const GltfPrimitive& face = asset.primitives[findPart(asset.primitives, "M_Face")];
  const Eigen::AlignedBox3f bounds = computeBounds(face.mesh);
  config.headPivot = Vec3(bounds.center().x(), bounds.min().y(), bounds.center().z());
  const GltfPrimitive& teeth = asset.primitives[findPart(asset.primitives, "M_Teeth")];
  config.jawPivot = estimateJawHinge(teeth, findTargetOrThrow(asset.targetNames, config.jawWeightTarget)).pivot;
  config.eyes = {{"left", "M_ScleraLeft", {"M_ScleraLeft", "M_IrisLeft"}},
                 {"right", "M_ScleraRight", {"M_ScleraRight", "M_IrisRight"}}};
  return config;
}

FaceRig::FaceRig(const GltfAsset& asset, FaceRigConfig config)
    : primitives_(asset.primitives), targetNames_(asset.targetNames), config_(std::move(config)) {
  for (const GltfPrimitive& p : primitives_) requireValidTargets(p);
  jawWeights_ = jawWeightsFromTarget(primitives_, findTargetOrThrow(targetNames_, config_.jawWeightTarget));
  eyeOfPrimitive_.assign(primitives_.size(), -1);
  for (size_t e = 0; e < config_.eyes.size(); ++e) {
    const EyeballSpec& eye = config_.eyes[e];
    eyeballs_.push_back(fitSphere(primitives_[findPart(primitives_, eye.spherePart)].mesh.positions));
    for (const std::string& part : eye.parts) {
      const size_t i = findPart(primitives_, part);
      eyeOfPrimitive_[i] = int(e);
      jawWeights_[i].clear();  // an eyeball rotates with the skull and its gaze, never with the jaw
    }
  }
}

void FaceRig::validatePose(const FacePose& pose) const {
  if (pose.blendshapeWeights.size() > targetNames_.size())
    throw InputError(fmt::format("face pose has {} blendshape weights but the rig has {} blendshapes",
                                 pose.blendshapeWeights.size(), targetNames_.size()));
  for (size_t k = 0; k < pose.blendshapeWeights.size(); ++k)
    if (!std::isfinite(pose.blendshapeWeights[k]))
      throw InputError(fmt::format("blendshape weight '{}' is not finite ({})", targetNames_[k], pose.blendshapeWeights[k]));
  if (pose.eyeEulerDegrees.size() > config_.eyes.size())
    throw InputError(fmt::format("face pose has {} eye rotations but the rig has {} eyes", pose.eyeEulerDegrees.size(),
                                 config_.eyes.size()));
  const auto finite = [](const RigidJoint& j) { return j.eulerDegrees.allFinite() && j.translation.allFinite(); };
  if (!finite(pose.head) || !finite(pose.jaw)) throw InputError("face pose: head or jaw joint is not finite");
  for (const Vec3& e : pose.eyeEulerDegrees)
    if (!e.allFinite()) throw InputError("face pose: an eye rotation is not finite");
}

// Applies T(j) to one primitive's pre-skinning shape; returns whether anything moved.
bool FaceRig::skin(size_t i, const FacePose& pose, std::vector<Vec3>& positions) const {
  const Affine3 head = jointTransform(pose.head, config_.headPivot);
  const int eye = eyeOfPrimitive_[i];
  if (eye >= 0) {
    // Gaze turns the eyeball about its fitted centre, inside the head.
    const RigidJoint gaze{size_t(eye) < pose.eyeEulerDegrees.size() ? pose.eyeEulerDegrees[size_t(eye)] : Vec3::Zero(),
                          Vec3::Zero()};
    if (gaze.isIdentity() && pose.head.isIdentity()) return false;
    transformPositions(positions, head * jointTransform(gaze, eyeballs_[size_t(eye)].center));
    return true;
  }
  if (!jawWeights_[i].empty() && !pose.jaw.isIdentity()) {
    // LBS (Bao et al. 2019): T = sum_k w_k T_k with two bones: the skull (head) and the jaw (head * jaw).
    SkinWeights w{2, std::vector<float>(2 * positions.size())};
    for (size_t v = 0; v < positions.size(); ++v) {
      w.weights[2 * v] = 1.0f - jawWeights_[i][v];
      w.weights[2 * v + 1] = jawWeights_[i][v];
    }
    applyLinearBlendSkinning(positions, {head, head * jointTransform(pose.jaw, config_.jawPivot)}, w);
    return true;
  }
  if (pose.head.isIdentity()) return false;
  transformPositions(positions, head);
  return true;
}

TriangleMesh FaceRig::evaluatePrimitive(size_t i, const FacePose& pose) const {
  validatePose(pose);
  const GltfPrimitive& primitive = primitives_.at(i);
  TriangleMesh mesh = primitive.mesh;
  bool moved = addBlendshapes(mesh.positions, primitive, pose.blendshapeWeights);
  moved |= skin(i, pose, mesh.positions);
  // Unmoved primitives keep the neutral normals bitwise; recomputing would only cost time.
  if (moved) {
    // Welded by the neutral mesh's map; a linearly refined primitive shaded as the surface it split.
    computePrimitiveNormals(mesh, primitive);
  }
  return mesh;
}

std::vector<TriangleMesh> FaceRig::evaluate(const FacePose& pose) const {
  std::vector<TriangleMesh> meshes;
  meshes.reserve(primitives_.size());
  for (size_t i = 0; i < primitives_.size(); ++i) meshes.push_back(evaluatePrimitive(i, pose));
  return meshes;
}

}  // namespace lacrima
