#pragma once
// Triangle meshes stored as a structure of arrays (one std::vector per attribute).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "lacrima/base/math.hpp"

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

// One sparse row per vertex of a mesh derived from another (a refinement): vertex v =
// sum_k weights[k] * old[sources[k]], k in [offsets[v], offsets[v + 1]). Weights of a row sum to 1.
struct VertexStencils {
  std::vector<uint32_t> offsets{0};
  std::vector<uint32_t> sources;
  std::vector<float> weights;

  size_t size() const { return offsets.size() - 1; }
  void add(const std::vector<std::pair<uint32_t, float>>& row);
};

// Applies an affine transform to positions and (inverse-transpose) normals, in place.
void transformMesh(TriangleMesh& mesh, const Affine3& transform);

// Area-weighted smooth vertex normals. With weldByPosition, vertices at the same position
// (UV seams split vertices in glTF) share one normal so seams do not show. Vertices on no
// triangle of non-zero area get +Z. Throws std::invalid_argument for out-of-range indices.
void computeSmoothNormals(TriangleMesh& mesh, bool weldByPosition = true);

// For each vertex, the lowest index of a vertex at bitwise the same position (+0 and -0 equal).
// Computed once on a neutral mesh, it keeps seams welded after a deformation moves the copies
// of a seam vertex by slightly different amounts.
std::vector<uint32_t> findCoincidentVertices(const TriangleMesh& mesh);

// As above, but vertices are welded by a precomputed map (findCoincidentVertices); the map must
// have one entry per vertex, each entry a valid vertex index.
void computeSmoothNormals(TriangleMesh& mesh, const std::vector<uint32_t>& weldMap);

// After some vertices moved (`moved`, one flag per vertex): the normals of every vertex of a
// triangle with a moved corner, exactly (bitwise) as computeSmoothNormals(mesh, true) would give
// them, the other normals kept. Costs the moved region plus one pass over the triangles, not the
// whole mesh's weld. `mesh` must have one normal per vertex.
void renewSmoothNormalsAround(TriangleMesh& mesh, const std::vector<bool>& moved);

// Axis-aligned bounds of the positions (empty box for an empty mesh).
Eigen::AlignedBox3f computeBounds(const TriangleMesh& mesh);

// Enclosed volume by the divergence theorem (sum of signed tetrahedra against the origin, in
// double precision). Positive for a closed mesh whose triangles are counter-clockwise from outside.
double signedVolume(const TriangleMesh& mesh);

// Problems that make a mesh unrenderable: index count not a multiple of 3, index out of range,
// normals/uvs not one per vertex, non-finite positions or normals.
// Returns an empty string when the mesh is valid, otherwise a description of the first problem.
std::string findMeshDefect(const TriangleMesh& mesh);

// Closed and consistently oriented: every directed edge appears exactly once and its reverse
// exactly once (so every edge is shared by exactly two triangles that agree on orientation).
// Returns "" when that holds, otherwise a description of the first offending edge.
// Expects a mesh without findMeshDefect problems.
std::string findClosedMeshDefect(const TriangleMesh& mesh);
// The same check on the mesh with coincident vertices merged (findCoincidentVertices): for meshes
// that keep separate vertices on either side of a sharp edge for their normals (liquid beads and
// rivulets along their contact lines), closed as the renderer's openness check sees them.
std::string findWeldedClosedMeshDefect(const TriangleMesh& mesh);

// The edges that belong to exactly one triangle, orientation ignored, with vertices welded by
// position (findCoincidentVertices) so that a closed surface split at UV seams counts as closed.
// 0 for a closed surface; an open sheet (a tear-line card) counts its outline.
size_t countBoundaryEdges(const TriangleMesh& mesh);

}  // namespace lacrima
