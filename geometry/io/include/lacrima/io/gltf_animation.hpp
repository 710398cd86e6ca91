#pragma once
// glTF 2.0 animations (spec 3.11 "Animations", interpolation in Appendix C): keyframed morph
// target weights and node translation / rotation / scale, as loaded by loadGltfAsset, and their
// evaluation at a time in seconds.
#include <cstddef>
#include <string>
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima {

// The node property a channel animates (spec 3.11.2 "channel.target.path").
enum class GltfAnimationPath {
  Translation,  // VEC3
  Rotation,     // unit quaternion x, y, z, w
  Scale,        // VEC3
  Weights,      // one weight per morph target of the node's mesh
};

// Spec 3.11.3 / Appendix C.
enum class GltfInterpolation {
  Step,         // the value of the last key at or before t
  Linear,       // lerp; slerp for rotations
  CubicSpline,  // cubic Hermite spline with in- and out-tangents stored per key
};

struct GltfAnimationChannel {
  int node = -1;          // index into GltfAsset::nodeNames
  std::string nodeName;   // "" if the node has no name
  GltfAnimationPath path = GltfAnimationPath::Translation;
  GltfInterpolation interpolation = GltfInterpolation::Linear;
  std::vector<float> times;  // key times in seconds, >= 0 and strictly increasing, at least one
  // Key values, valueSize floats each, key after key. For CubicSpline every key stores three
  // values in the file's order: in-tangent, value, out-tangent. Normalized integer outputs are
  // already decoded to floats.
  std::vector<float> values;
  size_t valueSize = 0;  // 3 (translation, scale), 4 (rotation), morph target count (weights)
};

struct GltfAnimation {
  std::string name;  // "" if unnamed
  std::vector<GltfAnimationChannel> channels;  // at most one per (node, path) pair

  // The last key time of any channel, in seconds (animations start at time 0); 0 without channels.
  float duration() const;
};

// A node's local transform as glTF composes it: T * R * S (spec 3.5.3).
struct NodeTrs {
  Vec3 translation = Vec3::Zero();
  Eigen::Quaternionf rotation = Eigen::Quaternionf::Identity();
  Vec3 scale = Vec3::Ones();

  Affine3 matrix() const;
};

// Spec names for diagnostics: "translation", "rotation", "scale", "weights" and
// "LINEAR", "STEP", "CUBICSPLINE".
const char* gltfAnimationPathName(GltfAnimationPath path);
const char* gltfInterpolationName(GltfInterpolation interpolation);

// The channel of `animation` that animates `path` of `node`, or nullptr.
const GltfAnimationChannel* findChannel(const GltfAnimation& animation, int node, GltfAnimationPath path);

// The channel's value at `seconds` (valueSize floats), held at the first / last key outside the
// keys. Rotations come out normalized. Throws InputError for a non-finite time.
std::vector<float> evaluateChannel(const GltfAnimationChannel& channel, double seconds);

// The morph target weights of `node` at `seconds`, in the order of the targets of the node's mesh.
// Without a weights channel for the node: targetCount zeros (the glTF default when mesh.weights
// is absent). Throws std::invalid_argument when the channel animates another number of targets.
std::vector<float> evaluateMorphWeights(const GltfAnimation& animation, int node, double seconds, size_t targetCount);

// The local TRS of `node` at `seconds`: each of translation, rotation and scale comes from its
// channel when the animation has one, else from `rest` (the node's own TRS).
NodeTrs evaluateNodeTransform(const GltfAnimation& animation, int node, double seconds, const NodeTrs& rest = {});

}  // namespace lacrima
