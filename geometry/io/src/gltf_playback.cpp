// Playing a glTF animation on a flattened asset: the weights channels mapped to asset-wide
// morph target indices, and per primitive the motion of its node relative to the rest pose that
// the loader already applied. See sampleGltfAnimation in gltf_asset.hpp.
#include <cmath>
#include <functional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"

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
    if (asset.primitives[p].skin >= 0) continue;  // spec 3.7.3: the skin alone places it
    if (resolve(node, 0) != State::Moving) continue;
    const Affine3d motion = animatedWorld[size_t(node)] * restWorld[size_t(node)].inverse();
    out.primitiveMotion[p] = motion.cast<float>();
    out.anyPrimitiveMoves = true;
  }

  out.skinJointMatrices.resize(asset.skins.size());
  for (size_t s = 0; s < asset.skins.size(); ++s) {
    const GltfSkin& skin = asset.skins[s];
    bool moves = false;
    for (int joint : skin.joints) moves |= resolve(joint, 0) == State::Moving;
    if (!moves) continue;
    std::vector<Affine3>& matrices = out.skinJointMatrices[s];
    for (size_t j = 0; j < skin.joints.size(); ++j)
      matrices.push_back((animatedWorld[size_t(skin.joints[j])] * skin.inverseBindMatrices[j].cast<double>()).cast<float>());
    out.anySkinMoves = true;
  }
  return out;
}

void applyGltfSkin(const GltfAsset& asset, const GltfPrimitive& primitive, const std::vector<Affine3>& jointMatrices,
                   TriangleMesh& mesh) {
  if (primitive.skin < 0 || size_t(primitive.skin) >= asset.skins.size())
    throw std::invalid_argument(fmt::format("applyGltfSkin: primitive '{}' has no skin", primitive.name));
  const GltfSkin& skin = asset.skins[size_t(primitive.skin)];
  const size_t vertexCount = mesh.vertexCount();
  if (jointMatrices.size() != skin.joints.size() || skin.restJointMatrices.size() != skin.joints.size() ||
      primitive.skinJoints.size() != vertexCount || primitive.skinWeights.size() != vertexCount)
    throw std::invalid_argument(fmt::format("applyGltfSkin: primitive '{}': {} joint matrices for {} joints, {} / {} "
                                            "skinned vertices for {}", primitive.name, jointMatrices.size(),
                                            skin.joints.size(), primitive.skinJoints.size(),
                                            primitive.skinWeights.size(), vertexCount));
  using Mat34d = Eigen::Matrix<double, 3, 4>;
  for (size_t v = 0; v < vertexCount; ++v) {
    Mat34d posed = Mat34d::Zero(), rest = Mat34d::Zero();
    for (int c = 0; c < 4; ++c) {
      const float w = primitive.skinWeights[v][c];
      if (w == 0.0f) continue;
      const size_t k = primitive.skinJoints[v][size_t(c)];
      if (k >= skin.joints.size())
        throw std::invalid_argument(fmt::format("applyGltfSkin: primitive '{}' vertex {} names joint {}", primitive.name, v, k));
      posed += double(w) * jointMatrices[k].matrix().topRows<3>().cast<double>();
      rest += double(w) * skin.restJointMatrices[k].matrix().topRows<3>().cast<double>();
    }
    // x = S(v) S_rest(v)^-1 x_rest, with x_rest the (morphed) rest-pose position.
    const Vec3d local = rest.leftCols<3>().inverse() * (mesh.positions[v].cast<double>() - rest.col(3));
    mesh.positions[v] = (posed.leftCols<3>() * local + posed.col(3)).cast<float>();
  }
  if (primitive.weldMap.size() == vertexCount) computeSmoothNormals(mesh, primitive.weldMap);
  else computeSmoothNormals(mesh, findCoincidentVertices(primitive.mesh));
}

}  // namespace lacrima
