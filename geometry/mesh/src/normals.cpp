// Smooth vertex normals, optionally welded across vertices that share a position.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "lacrima/mesh/mesh.hpp"

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

// The unnormalised face normal of triangle (a, b, c); one expression for every caller, so that
// sums built in the same order agree bitwise.
Vec3 faceNormalOf(const TriangleMesh& mesh, uint32_t a, uint32_t b, uint32_t c) {
  return (mesh.positions[b] - mesh.positions[a]).cross(mesh.positions[c] - mesh.positions[a]);
}

// The unit normal of a summed face normal; kFallbackNormal for a zero or non-finite sum.
Vec3 normalOfSum(const Vec3& sum) {
  const float length = sum.norm();
  return (length > 0.0f && std::isfinite(length)) ? Vec3(sum / length) : kFallbackNormal;
}

PositionKey positionKey(const Vec3& p) { return {coordinateBits(p.x()), coordinateBits(p.y()), coordinateBits(p.z())}; }

// Sum of the (unnormalised) face normals around each weld group, written to the group's
// representative vertex. The cross product's length is twice the triangle area, so summing it
// weights each face by its area, which is robust to the thin slivers of triangulated quads.
std::vector<Vec3> accumulateFaceNormals(const TriangleMesh& mesh, const std::vector<uint32_t>* weldMap) {
  std::vector<Vec3> sums(mesh.positions.size(), Vec3::Zero());
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    if (std::max({a, b, c}) >= sums.size())
      throw std::invalid_argument("computeSmoothNormals: triangle index out of range (check findMeshDefect first)");
    const Vec3 faceNormal = faceNormalOf(mesh, a, b, c);
    for (uint32_t v : {a, b, c}) sums[weldMap ? (*weldMap)[v] : v] += faceNormal;
  }
  return sums;
}

void writeNormals(TriangleMesh& mesh, const std::vector<Vec3>& sums, const std::vector<uint32_t>* weldMap) {
  mesh.normals.resize(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    mesh.normals[v] = normalOfSum(sums[weldMap ? (*weldMap)[v] : v]);
  }
}

constexpr int32_t kNoGroup = -1;

// The vertices whose normal changes when `moved` vertices moved: the corners of every triangle
// with a moved corner.
std::vector<uint32_t> verticesAroundMoved(const TriangleMesh& mesh, const std::vector<bool>& moved) {
  std::vector<bool> around(mesh.positions.size(), false);
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t* t = &mesh.indices[i];
    if (std::max({t[0], t[1], t[2]}) >= around.size())
      throw std::invalid_argument("renewSmoothNormalsAround: triangle index out of range (check findMeshDefect first)");
    if (moved[t[0]] || moved[t[1]] || moved[t[2]]) around[t[0]] = around[t[1]] = around[t[2]] = true;
  }
  std::vector<uint32_t> vertices;
  for (uint32_t v = 0; v < around.size(); ++v)
    if (around[v]) vertices.push_back(v);
  return vertices;
}

// Each vertex's weld group (vertices at bitwise the same position, as findCoincidentVertices
// welds them) among the groups of `vertices`; kNoGroup for a vertex in none of them. Only
// vertices inside the bounds of `vertices` can share a position with one: the rest is skipped.
std::vector<int32_t> weldGroupsOf(const TriangleMesh& mesh, const std::vector<uint32_t>& vertices, size_t& groupCount) {
  std::unordered_map<PositionKey, int32_t, PositionKeyHash> groupAt;
  Eigen::AlignedBox3f bounds;
  for (uint32_t v : vertices) {
    groupAt.try_emplace(positionKey(mesh.positions[v]), int32_t(groupAt.size()));
    bounds.extend(mesh.positions[v]);
  }
  groupCount = groupAt.size();
  std::vector<int32_t> group(mesh.positions.size(), kNoGroup);
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    // A NaN coordinate fails contains(): such a vertex welds only by its bits, so look it up.
    if (bounds.contains(mesh.positions[v]) || !mesh.positions[v].allFinite()) {
      const auto it = groupAt.find(positionKey(mesh.positions[v]));
      if (it != groupAt.end()) group[v] = it->second;
    }
  }
  return group;
}

}  // namespace

void renewSmoothNormalsAround(TriangleMesh& mesh, const std::vector<bool>& moved) {
  if (moved.size() != mesh.positions.size() || mesh.normals.size() != mesh.positions.size())
    throw std::invalid_argument("renewSmoothNormalsAround: one moved flag and one normal per vertex are needed");
  const std::vector<uint32_t> vertices = verticesAroundMoved(mesh, moved);
  if (vertices.empty()) return;
  size_t groupCount = 0;
  const std::vector<int32_t> group = weldGroupsOf(mesh, vertices, groupCount);
  // The same additions, in the same (triangle) order, as accumulateFaceNormals makes for these groups.
  std::vector<Vec3> sums(groupCount, Vec3::Zero());
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    if (group[a] == kNoGroup && group[b] == kNoGroup && group[c] == kNoGroup) continue;
    const Vec3 faceNormal = faceNormalOf(mesh, a, b, c);
    for (uint32_t v : {a, b, c})
      if (group[v] != kNoGroup) sums[size_t(group[v])] += faceNormal;
  }
  for (uint32_t v : vertices) mesh.normals[v] = normalOfSum(sums[size_t(group[v])]);
}

std::vector<uint32_t> findCoincidentVertices(const TriangleMesh& mesh) {
  std::unordered_map<PositionKey, uint32_t, PositionKeyHash> firstAt;
  firstAt.reserve(mesh.positions.size());
  std::vector<uint32_t> representative(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const PositionKey key = positionKey(mesh.positions[v]);
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
