// Playing a glTF animation on a flattened asset: the weights channels mapped to asset-wide
// morph target indices, and per primitive the motion of its node relative to the rest pose that
// the loader already applied. See sampleGltfAnimation in gltf_asset.hpp.
#include <cmath>
#include <functional>
#include <vector>

#include <fmt/format.h>

#include "lacrima/geometry/error.hpp"
#include "lacrima/geometry/gltf_asset.hpp"

namespace lacrima {

namespace {

using Affine3d = Eigen::Transform<double, 3, Eigen::Affine>;

bool movesNode(const GltfAnimationChannel& c) { return c.path != GltfAnimationPath::Weights; }

}  // namespace

GltfAnimationSample sampleGltfAnimation(const GltfAsset& asset, const GltfAnimation& animation, double seconds) {
  if (!std::isfinite(seconds)) throw InputError(fmt::format("animation time {} is not finite", seconds));
  GltfAnimationSample out;
  out.weights.assign(asset.targetNames.size(), 0.0f);
  out.primitiveMotion.assign(asset.primitives.size(), Affine3::Identity());

  const size_t nodeCount = asset.nodes.size();
  std::vector<bool> animated(nodeCount, false);  // a TRS channel targets the node
  for (const GltfAnimationChannel& c : animation.channels) {
    if (c.node < 0 || size_t(c.node) >= nodeCount) continue;
    if (movesNode(c)) {
      animated[size_t(c.node)] = true;
      continue;
    }
    // Weights: in channel order, so a later channel overwrites a shared asset-wide target.
    const std::vector<int>& slots = asset.nodes[size_t(c.node)].targetSlots;
    if (slots.empty() || slots.size() != c.valueSize) continue;  // node outside the default scene
    const std::vector<float> w = evaluateChannel(c, seconds);
    for (size_t k = 0; k < slots.size(); ++k)
      if (slots[k] >= 0 && size_t(slots[k]) < out.weights.size()) out.weights[size_t(slots[k])] = w[k];
  }

  // Per node (memoized): is anything on its path to the root animated, and its rest and
  // animated world transforms. Parent links come from one walk of a tree, so they end at -1;
  // the depth guard only protects against a hand-made asset with a cycle.
  enum class State : unsigned char { Unknown, Still, Moving };
  std::vector<State> state(nodeCount, State::Unknown);
  std::vector<Affine3d> restWorld(nodeCount, Affine3d::Identity()), animatedWorld(nodeCount, Affine3d::Identity());
  std::function<State(int, size_t)> resolve = [&](int n, size_t depth) -> State {
    if (n < 0 || size_t(n) >= nodeCount || depth > nodeCount) return State::Still;
    State& s = state[size_t(n)];
    if (s != State::Unknown) return s;
    const GltfNode& node = asset.nodes[size_t(n)];
    const State parentState = resolve(node.parent, depth + 1);
    const bool hasParent = node.parent >= 0 && size_t(node.parent) < nodeCount;
    const Affine3d parentRest = hasParent ? restWorld[size_t(node.parent)] : Affine3d::Identity();
    const Affine3d parentAnimated = hasParent ? animatedWorld[size_t(node.parent)] : Affine3d::Identity();
    const Affine3d restLocal = node.matrix.cast<double>();
    restWorld[size_t(n)] = parentRest * restLocal;
    if (animated[size_t(n)]) {
      const NodeTrs pose = evaluateNodeTransform(animation, n, seconds, node.trs);
      animatedWorld[size_t(n)] = parentAnimated * pose.matrix().cast<double>();
      s = State::Moving;
    } else {
      animatedWorld[size_t(n)] = parentAnimated * restLocal;
      s = parentState;
    }
    return s;
  };

  for (size_t p = 0; p < asset.primitives.size(); ++p) {
    const int node = asset.primitives[p].node;
    if (resolve(node, 0) != State::Moving) continue;
    const Affine3d motion = animatedWorld[size_t(node)] * restWorld[size_t(node)].inverse();
    out.primitiveMotion[p] = motion.cast<float>();
    out.anyPrimitiveMoves = true;
  }
  return out;
}

}  // namespace lacrima
