// Whole-mesh operations: transforms, bounds, volume and the validity checks that guard the
// renderer against meshes it cannot trace.
#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>

#include <fmt/format.h>

#include "lacrima/mesh/mesh.hpp"
#include "lacrima/base/vertex_ranges.hpp"

namespace lacrima {

namespace {

// Reverses the winding of every triangle (swaps its last two corners).
void flipWinding(TriangleMesh& mesh) {
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
}

bool isFiniteVec(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

std::string formatVec(const Vec3& v) { return fmt::format("({}, {}, {})", v.x(), v.y(), v.z()); }

}  // namespace

void transformMesh(TriangleMesh& mesh, const Affine3& transform) {
  // Normals are covectors: they transform by the inverse transpose of the linear part, which
  // keeps them perpendicular to the surface under non-uniform scale.
  const Mat3 linear = transform.linear();
  const Mat3 normalMatrix = linear.inverse().transpose();
  forVertexRanges(mesh.positions.size(), [&](uint32_t begin, uint32_t end) {
    for (uint32_t v = begin; v < end; ++v) mesh.positions[v] = transform * mesh.positions[v];
  });
  forVertexRanges(mesh.normals.size(), [&](uint32_t begin, uint32_t end) {
    for (uint32_t v = begin; v < end; ++v) {
      const Vec3 m = normalMatrix * mesh.normals[v];
      const float length = m.norm();
      if (length > 0.0f && std::isfinite(length)) mesh.normals[v] = m / length;
    }
  });

  // A mirroring transform turns counter-clockwise triangles clockwise; flip them back so the
  // winding keeps agreeing with the (correctly transformed) normals.
  if (linear.determinant() < 0.0f) flipWinding(mesh);
}

Eigen::AlignedBox3f computeBounds(const TriangleMesh& mesh) {
  Eigen::AlignedBox3f box;  // default-constructed box is empty
  for (const Vec3& p : mesh.positions) box.extend(p);
  return box;
}

double signedVolume(const TriangleMesh& mesh) {
  // Divergence theorem: V = 1/6 sum over triangles of a . (b x c). Double precision, because the
  // terms of a small drop far from the origin cancel heavily.
  double volume = 0.0;
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const Vec3d a = mesh.positions[mesh.indices[i]].cast<double>();
    const Vec3d b = mesh.positions[mesh.indices[i + 1]].cast<double>();
    const Vec3d c = mesh.positions[mesh.indices[i + 2]].cast<double>();
    volume += a.dot(b.cross(c));
  }
  return volume / 6.0;
}

std::string findMeshDefect(const TriangleMesh& mesh) {
  const size_t n = mesh.positions.size();
  if (mesh.indices.size() % 3 != 0)
    return fmt::format("{} indices is not a multiple of 3 (triangles only)", mesh.indices.size());
  if (!mesh.normals.empty() && mesh.normals.size() != n)
    return fmt::format("{} normals for {} vertices", mesh.normals.size(), n);
  if (!mesh.uvs.empty() && mesh.uvs.size() != n)
    return fmt::format("{} uvs for {} vertices", mesh.uvs.size(), n);
  for (size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] >= n)
      return fmt::format("index {} (triangle {}) is {}, but there are only {} vertices", i, i / 3,
                         mesh.indices[i], n);
  }
  for (size_t v = 0; v < n; ++v) {
    if (!isFiniteVec(mesh.positions[v]))
      return fmt::format("vertex {} has a non-finite position {}", v, formatVec(mesh.positions[v]));
  }
  for (size_t v = 0; v < mesh.normals.size(); ++v) {
    if (!isFiniteVec(mesh.normals[v]))
      return fmt::format("vertex {} has a non-finite normal {}", v, formatVec(mesh.normals[v]));
  }
  return {};
}

std::string findClosedMeshDefect(const TriangleMesh& mesh) {
  // Count each directed edge. In a closed, consistently oriented mesh every directed edge (a,b)
  // occurs once and its twin (b,a) once: two triangles per edge, traversing it in opposite ways.
  std::unordered_map<uint64_t, int> directed;
  directed.reserve(mesh.indices.size());
  const auto key = [](uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; };
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = mesh.indices[i + k], b = mesh.indices[i + (k + 1) % 3];
      if (a == b) return fmt::format("triangle {} is degenerate (repeats vertex {})", i / 3, a);
      if (++directed[key(a, b)] > 1)
        return fmt::format("edge {}->{} is traversed twice in the same direction (inconsistent "
                           "orientation or more than two triangles on the edge)", a, b);
    }
  }
  for (const auto& [k, count] : directed) {
    const uint32_t a = uint32_t(k >> 32), b = uint32_t(k & 0xffffffffu);
    if (!directed.contains(key(b, a)))
      return fmt::format("edge {}-{} belongs to only one triangle (open boundary)", a, b);
  }
  return {};
}

std::string findWeldedClosedMeshDefect(const TriangleMesh& mesh) {
  TriangleMesh welded;
  welded.positions = mesh.positions;
  welded.indices = mesh.indices;
  const std::vector<uint32_t> representative = findCoincidentVertices(mesh);
  for (uint32_t& index : welded.indices) index = representative[index];
  return findClosedMeshDefect(welded);
}

size_t countBoundaryEdges(const TriangleMesh& mesh) {
  const std::vector<uint32_t> welded = findCoincidentVertices(mesh);
  std::unordered_map<uint64_t, int> triangles;  // per undirected welded edge
  triangles.reserve(mesh.indices.size());
  for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = welded[mesh.indices[i + k]], b = welded[mesh.indices[i + (k + 1) % 3]];
      if (a == b) continue;  // a degenerate edge bounds nothing
      ++triangles[(uint64_t(std::min(a, b)) << 32) | std::max(a, b)];
    }
  size_t boundary = 0;
  for (const auto& [edge, count] : triangles) boundary += count == 1;
  return boundary;
}

}  // namespace lacrima
