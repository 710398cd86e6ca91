#pragma once
// Posing a shot asset at a (fractional) frame: every weight source (static and keyed
// blendshapes, animator controls, a performance track) and the rig joints, then the meshes.
#include <vector>

#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

// b and j at `frame`: weights from all sources added, then clamped to [0, 1]; joints from the
// controls plus the keyed joint channels.
FacePose assetPoseAt(const ShotAsset& asset, double frame);

// Primitive `index` of the asset in `pose`, in world space (the asset transform applied).
// Without animation this is bitwise what the static path produced: the neutral mesh, or the
// morphed one when a static weight is non-zero.
TriangleMesh posedPrimitive(const ShotAsset& asset, const FacePose& pose, size_t index);

}  // namespace lacrima::shotfile
