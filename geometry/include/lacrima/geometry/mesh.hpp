#pragma once
// Triangle meshes stored as a structure of arrays (one std::vector per attribute).
#include <cstdint>
#include <string>
#include <vector>

#include "lacrima/geometry/math.hpp"

namespace lacrima {

struct TriangleMesh {
  std::string name;
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;      // empty, or one unit normal per vertex
  std::vector<Vec2> uvs;          // empty, or one per vertex
  std::vector<uint32_t> indices;  // three per triangle, counter-clockwise seen from outside

  size_t vertexCount() const { return positions.size(); }
  size_t triangleCount() const { return indices.size() / 3; }
};

// Applies an affine transform to positions and (inverse-transpose) normals, in place.
void transformMesh(TriangleMesh& mesh, const Affine3& transform);

// Area-weighted smooth vertex normals. With weldByPosition, vertices at the same position
// (UV seams split vertices in glTF) share one normal so seams do not show.
void computeSmoothNormals(TriangleMesh& mesh, bool weldByPosition = true);

// Problems that make a mesh unrenderable: index out of range, non-finite positions.
// Returns an empty string when the mesh is valid, otherwise a description of the first problem.
std::string findMeshDefect(const TriangleMesh& mesh);

}  // namespace lacrima
