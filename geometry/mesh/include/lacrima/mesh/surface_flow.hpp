#pragma once
// The path a drop of water takes down a triangle mesh under gravity: steepest descent on the
// piecewise-linear surface, traced exactly triangle by triangle. It can
// supply the tear path that Lin & Cheng 2013 section 4.2 step 1 takes as given (resampleFlowPath gives
// the polyline of SurfacePoints that buildSheddingTearStrip expects).
//
// Method
// ------
// On a triangle the surface is a plane; the height -g.x is a linear function there, and its
// steepest-descent direction in the plane is gravity projected onto the plane,
//   d = g - (g.n) n,   n = the geometric (flat) triangle normal,
// the discrete gradient of a linear function on a triangle (the gradients of the barycentric
// coordinates are grad(lambda_i) = n x e_i / (2 area), e_i the edge opposite corner i, as in
// Botsch et al., "Polygon Mesh Processing", 2010, chapter 3, discrete differential operators).
// The path walks straight along d inside the triangle. The barycentric coordinates change linearly
// along the walk, at rates grad(lambda_i).d, so the exit edge and point are found exactly (the
// first coordinate to reach zero). Gravity is re-projected in the next triangle and the walk
// continues: a polyline that bends at every edge, i.e. a walk on the surface, not a straight line
// in space.
//
// At an edge or a vertex the path takes the steepest admissible descent among all directions of
// the point's neighbourhood on the surface (its "star"): a triangle's d if d leads into that
// triangle, and the mesh edges leaving the point (rate g.e for a unit edge direction e).
//  * On an edge, where the directions of the two triangles both point into the edge (a valley or
//    crease, e.g. a nasolabial fold), neither triangle admits its d and the path runs along the
//    edge downhill ("edge following") to the edge's lower vertex.
//  * At a vertex, the path continues into whichever triangle (or along whichever edge) descends
//    most steeply from it.
// Faces are tried before edges, so a face wins a tie; a d within 1e-6 rad of the edge it would
// cross counts as running along that edge (float positions tilt coplanar normals by ~1e-7).
//
// Stop conditions (FlowStop): maxLength reached; the path leaves the mesh through a boundary
// edge (or through the gap of an open fan at a boundary vertex); a pit (no direction in the
// star descends, e.g. the lowest point of a closed mesh, or a horizontal crease); flat (|d|
// below flatTolerance |g| in every triangle at the point: a horizontal spot or a surface facing
// straight up or down); maxSteps (a guard: every step strictly descends, so a path cannot cycle,
// but a path can be long); a start on a zero-area triangle.
//
// Robustness: all geometry is computed in double precision from the float positions. A point
// whose barycentric coordinate falls below 1e-7 is snapped onto that edge (two such coordinates:
// onto the vertex), so vertices and edges are hit exactly, never stepped over. Triangles of zero
// area within float precision on the mesh the adjacency is built from take no part in it (an edge
// whose only other triangle is one counts as a boundary); a triangle that becomes degenerate on a
// deformed mesh is never entered (the path follows its edge instead). No NaN is produced.
// Every piece strictly descends, so there is no cycle; maxSteps bounds the work anyway. The same
// input gives bitwise the same output.
//
// Limits: the path is the exact steepest descent of the piecewise-linear mesh, which converges
// to the smooth surface's flow line only at first order in the edge length: on a UV sphere each
// flat facet sends the path along the facet's own mid-meridian, so a path starting at a longitude
// offset a from it (at most half a facet) drifts sideways by about sin(a) x (the horizontal
// distance travelled); a quarter-facet offset gave 1.1e-2 R with 64 segments, 5.3e-3 R with 128.
// Tessellation creases act as valleys (a convex ridge between two facets whose directions both
// point at it also "captures" the path, which is still the exact descent of the polyhedron). The
// path is quasi-static: no inertia, no contact angle, no pinning; it is recomputed per frame on the
// deformed mesh (the adjacency is built once, on the rest mesh).
#include <cstdint>
#include <limits>
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/mesh/surface_point.hpp"

namespace lacrima {

// Triangle neighbours across each edge and triangles around each vertex, for one mesh topology
// (valid for any deformation of it). Edge e of triangle t joins its corners e and (e + 1) % 3;
// half-edge 3 t + e. An edge shared by exactly two triangles links them; an edge of one triangle
// is a boundary and an edge of three or more (non-manifold) is treated as a boundary of each.
struct TriangleAdjacency {
  static constexpr uint32_t kNone = 0xffffffffu;

  // Per vertex: the vertex that represents it (itself, or the lowest coincident vertex when
  // built with a weld map, so that edges match across UV seams).
  std::vector<uint32_t> weld;
  // Per half-edge 3 t + e: the half-edge 3 t' + e' of the neighbour across it, or kNone.
  std::vector<uint32_t> twin;
  // Triangles around each representative vertex as corners 3 t + c (triangle t, corner c), in
  // increasing order: those of vertex v are starCorners[starOffsets[v] .. starOffsets[v + 1]).
  std::vector<uint32_t> starOffsets;
  std::vector<uint32_t> starCorners;

  size_t triangleCount() const { return twin.size() / 3; }
  size_t vertexCount() const { return weld.size(); }
};

// Adjacency matching edges by vertex index. Triangles using a vertex twice, or of zero area on
// the mesh it is built from (the rest mesh), take no part (no neighbours, in no star), so a sliver
// lying on an edge does not turn that edge into a non-manifold one. Throws InputError for an index
// count not a multiple of 3 or an index out of range.
TriangleAdjacency buildTriangleAdjacency(const TriangleMesh& mesh);

// As above, matching edges by weldMap[vertex] (e.g. findCoincidentVertices(mesh), so the path
// crosses UV seams). Throws InputError unless weldMap has one valid vertex index per vertex.
TriangleAdjacency buildTriangleAdjacency(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap);

enum class FlowStop {
  MaxLength,   // the path reached FlowPathOptions::maxLength
  Boundary,    // the path leaves the mesh through a boundary
  Pit,         // no direction descends (a local minimum, or a horizontal crease)
  Flat,        // gravity has no component along the surface here
  MaxSteps,    // FlowPathOptions::maxSteps straight pieces were traced
  Degenerate,  // the start lies inside a zero-area triangle
};

// Name of a stop condition ("max length", "boundary", ...), for messages.
const char* flowStopName(FlowStop stop);

struct FlowPathOptions {
  float maxLength = std::numeric_limits<float>::infinity();  // arc length at which to stop (>= 0)
  int maxSteps = 100000;                                     // straight pieces at most (>= 1)
  float flatTolerance = 1e-6f;                               // slopes below flatTolerance |g| do not descend, in [0, 1)
};

// A traced path: a polyline with one point per start, edge crossing, vertex and end. Piece i runs
// straight from point i to point i + 1 inside (or along an edge of) triangle points[i].triangle;
// arrival[i + 1] is point i + 1 in that same triangle, so a piece can be interpolated exactly.
// (points[i + 1] itself is expressed in the triangle of the next piece.)
struct FlowPath {
  std::vector<SurfacePoint> points;
  std::vector<Vec3> arrival;     // arrival[0]: the start as given (no piece ends there)
  std::vector<Vec3> positions;   // world positions of the points on the traced mesh
  std::vector<float> arcLength;  // cumulative, arcLength[0] = 0
  FlowStop stop = FlowStop::Flat;

  float length() const { return arcLength.empty() ? 0.0f : arcLength.back(); }
};

// Traces the flow path from `start` on `mesh` under `gravity` (any non-zero length; its direction
// is what matters). `adjacency` must be built from a mesh of the same topology. Throws
// InputError for an adjacency of another size, an invalid start (see surfacePosition), a
// non-finite gravity or invalid options. A zero gravity gives a one-point path, status Flat.
FlowPath traceFlowPath(const TriangleMesh& mesh, const TriangleAdjacency& adjacency, const SurfacePoint& start,
                       const Vec3& gravity, const FlowPathOptions& options = {});

// Surface points every `spacing` of arc length along the path (0, spacing, 2 spacing, ...) plus
// its end point when that lies more than spacing / 1000 beyond the last sample; each is exact on
// its piece (interpolated in the piece's triangle). An empty path gives none. Throws InputError
// for a spacing that is not finite and positive.
std::vector<SurfacePoint> resampleFlowPath(const FlowPath& path, float spacing);

}  // namespace lacrima
