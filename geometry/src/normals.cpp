// Smooth vertex normals, optionally welded across vertices that share a position.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "lacrima/geometry/mesh.hpp"

namespace lacrima {

namespace {

// Bit pattern of a coordinate with -0 folded onto +0, so that the two zeros weld.
uint32_t coordinateBits(float x) { return std::bit_cast<uint32_t>(x == 0.0f ? 0.0f : x); }

struct PositionKey {
  uint32_t x, y, z;
  bool operator==(const PositionKey&) const = default;
};

struct PositionKeyHash {
  size_t operator()(const PositionKey& k) const {
    // Any decent mix works; the keys are few (one per vertex).
    uint64_t h = (uint64_t(k.x) * 0x9e3779b97f4a7c15ULL) ^ (uint64_t(k.y) * 0xc2b2ae3d27d4eb4fULL) ^
                 (uint64_t(k.z) * 0x165667b19e3779f9ULL);
    return size_t(h ^ (h >> 29));
  }
};

// Fallback for vertices that touch no triangle of non-zero area: any unit vector keeps the
// renderer's shading frame valid; such vertices are never hit, so the choice does not show.
const Vec3 kFallbackNormal(0.0f, 0.0f, 1.0f);

// Sum of the (unnormalised) face normals around each weld group, written to the group's
// representative vertex. The cross product's length is twice the triangle area, so summing it
// weights each face by its area, which is robust to the thin slivers of triangulated quads.
std::vector<Vec3> accumulateFaceNormals(const TriangleMesh& mesh, const std::vector<uint32_t>* weldMap) {
  std::vector<Vec3> sums(mesh.positions.size(), Vec3::Zero());
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    if (std::max({a, b, c}) >= sums.size())
      throw std::invalid_argument("computeSmoothNormals: triangle index out of range (check findMeshDefect first)");
    const Vec3 faceNormal = (mesh.positions[b] - mesh.positions[a]).cross(mesh.positions[c] - mesh.positions[a]);
    for (uint32_t v : {a, b, c}) sums[weldMap ? (*weldMap)[v] : v] += faceNormal;
  }
  return sums;
}

void writeNormals(TriangleMesh& mesh, const std::vector<Vec3>& sums, const std::vector<uint32_t>* weldMap) {
  mesh.normals.resize(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& sum = sums[weldMap ? (*weldMap)[v] : v];
    const float length = sum.norm();
    mesh.normals[v] = (length > 0.0f && std::isfinite(length)) ? Vec3(sum / length) : kFallbackNormal;
  }
}

}  // namespace

std::vector<uint32_t> findCoincidentVertices(const TriangleMesh& mesh) {
  std::unordered_map<PositionKey, uint32_t, PositionKeyHash> firstAt;
  firstAt.reserve(mesh.positions.size());
  std::vector<uint32_t> representative(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    const PositionKey key{coordinateBits(p.x()), coordinateBits(p.y()), coordinateBits(p.z())};
    // try_emplace keeps the first (lowest) index seen at this position.
    representative[v] = firstAt.try_emplace(key, uint32_t(v)).first->second;
  }
  return representative;
}

void computeSmoothNormals(TriangleMesh& mesh, const std::vector<uint32_t>& weldMap) {
  if (weldMap.size() != mesh.positions.size())
    throw std::invalid_argument("computeSmoothNormals: weld map size differs from the vertex count");
  for (uint32_t r : weldMap) {
    if (r >= mesh.positions.size()) throw std::invalid_argument("computeSmoothNormals: weld map entry out of range");
  }
  writeNormals(mesh, accumulateFaceNormals(mesh, &weldMap), &weldMap);
}

void computeSmoothNormals(TriangleMesh& mesh, bool weldByPosition) {
  if (weldByPosition) {
    computeSmoothNormals(mesh, findCoincidentVertices(mesh));
    return;
  }
  writeNormals(mesh, accumulateFaceNormals(mesh, nullptr), nullptr);
}

}  // namespace lacrima
