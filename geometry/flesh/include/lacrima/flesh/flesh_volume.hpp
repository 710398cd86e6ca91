#pragma once
// The flesh volume under a patch of skin: the region between the skin and an inner surface (the
// skin shrunk by a depth towards the centre of the sphere it fits: the skull's side of the flesh),
// closed by walls along the patch's border, tetrahedralized by TetGen (Si 2015, "TetGen, a Delaunay-based
// quality tetrahedral mesh generator", ACM TOMS 41(2)) with a bound on the radius-edge ratio and
// on the volume (the skin's triangles split where the bounds need it).
//
// Each node is anchored to a skin triangle: its offset from the anchor point, in the triangle's
// own frame, places it on any pose of the skin. So the rig's pose of the skin gives the rig's
// pose of the flesh (the simulation's target), and the skin's vertices are the first nodes.
#include <array>
#include <stdexcept>
#include <cmath>
#include <vector>

#include "lacrima/flesh/tet_mesh.hpp"

namespace lacrima::flesh {

// A connected piece of skin, its vertices numbered from 0, with the skin mesh's numbering kept.
struct SkinPatch {
  std::vector<Vec3d> positions, normals;  // unit outward normals (out of the flesh)
  std::vector<std::array<int, 3>> triangles;
  std::vector<uint32_t> skinVertex;       // patch vertex -> vertex of the skin mesh
  std::vector<uint32_t> skinTriangle;     // patch triangle -> triangle of the skin mesh
};

// The selected triangles of a skin mesh as a patch whose border is a set of simple loops: the
// triangles round a vertex where the border pinches (more than two border edges: two pieces that
// meet at a corner) are left out, again until no such vertex is left.
SkinPatch extractSkinPatch(const std::vector<Vec3d>& positions, const std::vector<Vec3d>& normals,
                           const std::vector<std::array<uint32_t, 3>>& triangles, const std::vector<bool>& selected);

struct FleshVolumeSettings {
  double depth = 0.012;             // m: the flesh's thickness under the skin
  double maxTetVolume = 4e-9;       // m^3 (a regular tetrahedron of 3.3 mm edges)
  double radiusEdgeRatio = 1.5;     // TetGen's -q bound (>= ~1.1; smaller is better shaped)
};

// The volume of a regular tetrahedron of this edge: a shot's "tetSize" as TetGen's volume bound.
inline double regularTetVolume(double edge) { return edge * edge * edge / (6.0 * std::sqrt(2.0)); }

// Where a node sits relative to the skin: a triangle of the patch, a point of it (barycentric)
// and the node's offset from that point in the triangle's frame (edge, in-plane, normal).
struct NodeAnchor {
  int triangle = 0;
  Vec3d barycentric = Vec3d(1, 0, 0);
  Vec3d offset = Vec3d::Zero();
};

struct FleshVolume {
  TetMesh mesh;                     // nodes [0, skinNodes) are the patch's vertices, in order
  int skinNodes = 0;
  std::vector<bool> kinematic;      // the inner surface and the patch's border: moved by the rig
  std::vector<NodeAnchor> anchors;  // one per node
};

class FleshVolumeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How buildFleshVolume makes a volume from these settings, in words (its inner surface's
// construction and TetGen's switches): part of the key volumes are filed on disk under, so a change
// of method is never answered from an old file.
std::string fleshVolumeRecipe(const FleshVolumeSettings& settings);

// Throws FleshVolumeError when the patch is empty, the depth is too deep for the skin's curvature
// or TetGen fails (a region whose skin the rays from the centre cross twice).
FleshVolume buildFleshVolume(const SkinPatch& patch, const FleshVolumeSettings& settings);

// Every node of the volume placed on a pose of the patch (positions in the patch's numbering).
std::vector<Vec3d> anchoredNodePositions(const FleshVolume& volume, const SkinPatch& patch,
                                         const std::vector<Vec3d>& posedPatchPositions);

// A point inside (or on) the mesh as a tetrahedron and its barycentric weights (summing to 1).
struct TetEmbedding {
  int tet = -1;
  Eigen::Vector4d weights = Eigen::Vector4d::Zero();
};

// Each point's tetrahedron: the one whose smallest barycentric weight is largest (so a point on the
// boundary, or a hair outside it, goes to the tetrahedron it is nearest to being in). A point
// outside every tetrahedron by more than `slack` (that weight below -slack) is not embedded
// (tet -1). Slack is meant small (a few hundredths): only the point's own and neighbouring grid
// cells are searched.
std::vector<TetEmbedding> embedPoints(const TetMesh& mesh, const std::vector<Vec3d>& points, double slack = 1e-9);

Vec3d embeddedPosition(const TetMesh& topology, const std::vector<Vec3d>& nodes, const TetEmbedding& embedding);

}  // namespace lacrima::flesh
