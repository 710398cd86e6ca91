// Blendshapes: the neutral face plus weighted sparse deltas.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"

namespace lacrima {

namespace {

void requireValidTarget(const SparseDelta& target, size_t k, size_t vertexCount) {
  if (target.vertices.size() != target.deltas.size())
    throw std::invalid_argument(fmt::format("applyMorphTargets: target {} has {} vertices but {} deltas", k,
                                            target.vertices.size(), target.deltas.size()));
  // Vertices are ascending (loader invariant), so the last one bounds them all.
  if (!target.vertices.empty() && target.vertices.back() >= vertexCount)
    throw std::invalid_argument(fmt::format("applyMorphTargets: target {} moves vertex {} of a {}-vertex mesh", k,
                                            target.vertices.back(), vertexCount));
}

// Adds w * delta to the vertices one target moves; returns whether anything moved.
bool addWeightedTarget(std::vector<Vec3>& positions, const SparseDelta& target, float w) {
  for (size_t i = 0; i < target.vertices.size(); ++i) positions[target.vertices[i]] += w * target.deltas[i];
  return !target.vertices.empty();
}

}  // namespace

int GltfAsset::findTarget(const std::string& name) const {
  for (size_t i = 0; i < targetNames.size(); ++i)
    if (targetNames[i] == name) return int(i);
  return -1;
}

TriangleMesh applyMorphTargets(const GltfPrimitive& primitive, const std::vector<float>& weights) {
  // Bao et al. 2019, x = n + B b: the neutral shape n plus the blendshape matrix B (one sparse column
  // per target) times the weights b. Skinning (T(j)) is applied by the face rig afterwards.
  TriangleMesh mesh = primitive.mesh;
  bool moved = false;
  const size_t used = std::min(weights.size(), primitive.targets.size());
  for (size_t k = 0; k < used; ++k) {
    const float w = weights[k];
    if (w == 0.0f) continue;  // most of the 57 weights are zero in any frame: skip them early
    if (!std::isfinite(w)) throw InputError(fmt::format("morph target weight {} is not finite ({})", k, w));
    requireValidTarget(primitive.targets[k], k, mesh.vertexCount());
    moved |= addWeightedTarget(mesh.positions, primitive.targets[k], w);
  }
  // A target can have a non-zero weight and still not touch this primitive (the eyeballs move
  // in no target): then the neutral normals are exact and recomputing would only cost time.
  if (moved) {
    if (primitive.weldMap.size() == mesh.vertexCount()) computeSmoothNormals(mesh, primitive.weldMap);
    else computeSmoothNormals(mesh, findCoincidentVertices(primitive.mesh));  // weld as the neutral mesh does
  }
  return mesh;
}

}  // namespace lacrima
