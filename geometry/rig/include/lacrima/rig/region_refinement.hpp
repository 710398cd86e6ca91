#pragma once
// Local subdivision of a triangle mesh: a selected set of triangles is refined (1-to-4 split,
// linear or Loop), the triangles around it are split so that no T-junction appears, and the rest
// stays as it was. Fine skin details (Lin & Cheng 2013, section 3) need more vertices than a face mesh
// has, but only where the detail is.
//
// The refinement is returned as stencils: every vertex of the refined mesh is a sparse weighted
// combination of the vertices of the mesh it came from, so that any per-vertex attribute
// (positions, uvs, morph target deltas, skin weights) is refined the same way. The original
// vertices keep their indices 0..n-1 (landmarks stay valid); new vertices are appended.
#include <cstdint>
#include <vector>

#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

enum class RefinementScheme {
  Linear,  // new vertices at edge midpoints, old vertices stay: the surface does not change
  Loop,    // Loop (1987) masks inside the region; linear on its border and on mesh boundaries
};

// One level of refinement of a mesh.
struct RegionRefinement {
  std::vector<uint32_t> indices;  // the refined triangles (same winding as their parents)
  VertexStencils stencils;        // one row per refined vertex; rows 0..n-1 are the old vertices
  // Per refined triangle: a child of a refined (1-to-4) triangle. The selection for the next level.
  std::vector<bool> refined;
  size_t refinedParents = 0;  // triangles split 1-to-4 (the selection after closure)
};

// One level. `selected` has one entry per triangle. Closure: the selection first grows until
// every unselected triangle shares at most one edge with it; an unselected triangle on one split
// edge is then split in two from its opposite corner. Edges are matched by vertex position
// (findCoincidentVertices), so a UV seam (vertices duplicated at one position) splits on both
// sides and does not crack. Loop masks (odd: 3/8 (a + b) + 1/8 (c + d); even: (1 - n beta) v +
// beta sum of the n neighbours, beta = 3/(8n) for n > 3 and 3/16 for n = 3, Warren's weights)
// apply only to edges whose two triangles are refined and to vertices whose whole one-ring is
// refined and that are on no mesh boundary (a seam counts as one); everything else is linear, so
// the region meets the untouched mesh without a crack. Throws std::invalid_argument when
// `selected` has the wrong size.
RegionRefinement refineRegionOnce(const TriangleMesh& mesh, const std::vector<bool>& selected,
                                  RefinementScheme scheme);

// Attributes of the refined vertices from the old ones. A row that is a single source of weight
// 1 copies it bitwise. Throws std::invalid_argument when a source is out of range.
std::vector<Vec3> applyStencils(const VertexStencils& stencils, const std::vector<Vec3>& values);
std::vector<Vec2> applyStencils(const VertexStencils& stencils, const std::vector<Vec2>& values);
// A sparse morph target: refined delta = stencil combination of the old deltas; only non-zero
// deltas are kept (ascending vertices).
SparseDelta applyStencils(const VertexStencils& stencils, const SparseDelta& delta, size_t oldVertexCount);
// Skin influences: weights combined per joint, the 4 largest kept (ties: lower joint first),
// renormalised to sum 1; unused slots are joint 0 with weight 0.
void applyStencils(const VertexStencils& stencils, std::vector<std::array<uint16_t, 4>>& joints,
                   std::vector<Vec4>& weights);

// `levels` levels of refinement: level k + 1 refines the children of the triangles refined at
// level k (each level closes its own border, so the mesh stays conforming). Positions and uvs
// are refined; normals, when the mesh has them, are recomputed smooth and welded by position.
TriangleMesh refineMesh(const TriangleMesh& mesh, std::vector<bool> selected, RefinementScheme scheme, int levels);

// A glTF primitive refined as refineMesh does, with its morph targets and skin influences, and
// its weldMap recomputed as the loader computes it. `carried`, when given, holds one more
// per-vertex attribute (e.g. a smoothed copy of the positions) refined with the same stencils (it
// must have one value per vertex: std::invalid_argument otherwise). Normals: a Loop refinement's
// are recomputed smooth from its triangles (its surface is smooth) and it clears normalTriangles
// and normalSources; a linear refinement keeps shading the surface it split, not its flat facets:
// it records the triangles from before its first linear refinement (normalTriangles) and, per
// added vertex, the original vertices it interpolates (normalSources, composed over levels and
// over earlier linear refinements), and its normals are computePrimitiveNormals'.
GltfPrimitive refinePrimitive(const GltfPrimitive& primitive, std::vector<bool> selected, RefinementScheme scheme,
                              int levels, std::vector<Vec3>* carried = nullptr);

// Smooth normals of a primitive's (posed) mesh, welded by its weldMap. Without normalTriangles,
// computeSmoothNormals of the mesh's own triangles. With them (a linear refinement), the mesh is
// shaded as the unrefined mesh would be: original vertices get the smooth normals of
// normalTriangles, added vertices the normalised blend of their normalSources' normals (Phong's
// interpolation). Normals computed from the split triangles instead would shade the split flat:
// a band of facets where the smooth mesh had none, and biased normals on its border where small
// split triangles meet large unsplit ones (the pale band along a liquid tear's path).
void computePrimitiveNormals(TriangleMesh& mesh, const GltfPrimitive& primitive);

}  // namespace lacrima
