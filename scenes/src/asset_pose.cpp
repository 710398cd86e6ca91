// Asset posing; see asset_pose.hpp.
#include "asset_pose.hpp"

#include <algorithm>
#include <map>

#include "lacrima/scenes/shot.hpp"

namespace lacrima::shotfile {

namespace {

// FaceControls::jointChannelNames order: head rx ry rz tx ty tz, jaw the same, then rx ry rz of
// each eye.
void addJointChannel(FacePose& pose, size_t channel, float value) {
  const auto addToJoint = [&](RigidJoint& joint, size_t component) {
    if (component < 3) joint.eulerDegrees[int(component)] += value;
    else joint.translation[int(component - 3)] += value;
  };
  if (channel < 6) return addToJoint(pose.head, channel);
  if (channel < 12) return addToJoint(pose.jaw, channel - 6);
  const size_t eye = (channel - 12) / 3;
  if (pose.eyeEulerDegrees.size() <= eye) pose.eyeEulerDegrees.resize(eye + 1, Vec3::Zero());
  pose.eyeEulerDegrees[eye][int((channel - 12) % 3)] += value;
}

void addDrivenPose(const ShotAsset& asset, double frame, FacePose& pose) {
  std::map<std::string, float> values;
  for (const AssetChannel& c : asset.controlValues) values[c.name] = c.value.at(frame);
  const FacePose driven = asset.controls->evaluate(values);
  for (size_t i = 0; i < driven.blendshapeWeights.size() && i < pose.blendshapeWeights.size(); ++i)
    pose.blendshapeWeights[i] += driven.blendshapeWeights[i];
  pose.head = driven.head;
  pose.jaw = driven.jaw;
  pose.eyeEulerDegrees = driven.eyeEulerDegrees;
}

}  // namespace

AssetPose assetPoseAt(const ShotAsset& asset, double frame) {
  AssetPose out;
  FacePose& pose = out.face;
  pose.blendshapeWeights = asset.weights;
  for (const AssetChannel& c : asset.animatedBlendshapes) pose.blendshapeWeights[c.index] = c.value.at(frame);
  if (asset.controls) addDrivenPose(asset, frame, pose);
  if (asset.performance) asset.performance->addWeightsAt(frame, pose.blendshapeWeights);
  if (asset.gltfAnimation) {
    const ShotGltfAnimation& playback = *asset.gltfAnimation;
    const GltfAnimationSample sample =
        sampleGltfAnimation(*asset.gltf, asset.gltf->animations.at(playback.index), playback.secondsAt(frame));
    for (size_t i = 0; i < sample.weights.size() && i < pose.blendshapeWeights.size(); ++i)
      pose.blendshapeWeights[i] += sample.weights[i];
    if (sample.anyPrimitiveMoves) out.primitiveMotion = sample.primitiveMotion;
    if (sample.anySkinMoves) out.skinJointMatrices = sample.skinJointMatrices;
  }
  for (float& w : pose.blendshapeWeights) w = std::clamp(w, 0.0f, 1.0f);
  for (const AssetChannel& c : asset.joints) addJointChannel(pose, c.index, c.value.at(frame));
  if (asset.performance)
    for (const auto& [channel, value] : asset.performance->jointsAt(frame)) addJointChannel(pose, channel, value);
  if (asset.rig) pose.eyeEulerDegrees.resize(asset.rig->config().eyes.size(), Vec3::Zero());
  return out;
}

TriangleMesh posedPrimitive(const ShotAsset& asset, const AssetPose& assetPose, size_t index) {
  const FacePose& pose = assetPose.face;
  const GltfPrimitive& primitive = asset.gltf->primitives[index];
  TriangleMesh mesh;
  if (asset.rig) {
    mesh = asset.rig->evaluatePrimitive(index, pose);
  } else {
    const auto& w = pose.blendshapeWeights;
    const bool morphed = std::any_of(w.begin(), w.end(), [](float x) { return x != 0.0f; });
    mesh = morphed ? applyMorphTargets(primitive, w) : primitive.mesh;
  }
  if (primitive.skin >= 0 && size_t(primitive.skin) < assetPose.skinJointMatrices.size() &&
      !assetPose.skinJointMatrices[size_t(primitive.skin)].empty())
    applyGltfSkin(*asset.gltf, primitive, assetPose.skinJointMatrices[size_t(primitive.skin)], mesh);
  if (index < assetPose.primitiveMotion.size() &&
      assetPose.primitiveMotion[index].matrix() != Affine3::Identity().matrix())
    transformMesh(mesh, assetPose.primitiveMotion[index]);
  transformMesh(mesh, asset.transform.matrix());
  mesh.name = asset.name + "/" + primitive.name;
  return mesh;
}

}  // namespace lacrima::shotfile

namespace lacrima {

FacePose assetFacePoseAt(const Shot& shot, size_t assetIndex, double frame) {
  return shotfile::assetPoseAt(shot.assets.at(assetIndex), frame).face;
}

}  // namespace lacrima
