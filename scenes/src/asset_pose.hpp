#pragma once
// Posing a shot asset at a (fractional) frame: every weight source (static and keyed
// blendshapes, animator controls, a performance track) and the rig joints, then the meshes.
#include <vector>

#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

// The pose of an asset at one (fractional) frame.
struct AssetPose {
  FacePose face;  // b and j
  // Per primitive, the motion of its glTF node relative to the rest pose (ShotAsset::gltfAnimation);
  // empty when no node moves.
  std::vector<Affine3> primitiveMotion;
  // Per glTF skin, its animated joint matrices (GltfAnimationSample::skinJointMatrices); empty
  // when no skin moves. Skinned primitives are posed by these instead of primitiveMotion.
  std::vector<std::vector<Affine3>> skinJointMatrices;
};

// The pose at `frame`: weights from all sources (static and keyed blendshapes, controls,
// performance track, glTF animation) added, then clamped to [0, 1]; joints from the controls
// plus the keyed joint channels; node motion from the glTF animation.
AssetPose assetPoseAt(const ShotAsset& asset, double frame);

// Primitive `index` of the asset in `pose`, in world space: morphed (or rigged), moved by its
// node's animation (a skinned primitive: skinned by its joints' animation), then the asset
// transform. Without animation this is bitwise what the static
// path produced: the neutral mesh, or the morphed one when a static weight is non-zero.
TriangleMesh posedPrimitive(const ShotAsset& asset, const AssetPose& pose, size_t index);

}  // namespace lacrima::shotfile
