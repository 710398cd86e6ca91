#pragma once
// Low-pass smoothing of a mesh's positions that keeps its topology (same vertices, same
// triangles), e.g. to trace a flow path over the large-scale shape of a face instead of its
// tessellation pits: the path's SurfacePoints are then valid on the original mesh too.
//
// Taubin's lambda/mu smoothing (G. Taubin, "A signal processing approach to fair surface design",
// SIGGRAPH 1995, sections 3-4): each iteration is a shrinking step x += lambda L(x) followed by an
// inflating step x += mu L(x) with mu < -lambda < 0, where L(x)_i is the mean of the neighbours of
// vertex i minus x_i (the umbrella operator with equal weights). The pair is a low-pass filter
// with pass-band frequency k_PB = 1/lambda + 1/mu (0.1 for the defaults): bumps a few edges wide
// are removed, the large-scale shape keeps its size (plain Laplacian smoothing would shrink it).
// A plane is a fixed point (every vertex is the mean of its neighbours up to a linear function),
// except that its rim would move inwards; so vertices on the mesh boundary are held fixed.
#include <cstdint>
#include <vector>

#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

struct TaubinOptions {
  int iterations = 20;  // lambda/mu pairs, >= 0
  float lambda = 0.5f;  // in (0, 1)
  float mu = -0.53f;    // < -lambda
};

// A copy of `mesh` with smoothed positions (normals recomputed when the mesh had normals; uvs and
// indices unchanged). weldMap (findCoincidentVertices) joins UV-seam copies so the seam neither
// opens nor stays fixed as a false boundary; the copies of a vertex move together. A vertex is on
// the boundary when one of its welded edges belongs to a single triangle. Throws InputError for
// invalid options, a weldMap of another size or an index out of range.
TriangleMesh taubinSmoothed(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap,
                            const TaubinOptions& options = {});

// The same filter set up once for a topology and applied to many position sets (e.g. every frame
// of an animation, or a displacement field): building the welded neighbour graph costs far more
// than a few iterations. smoothed(mesh.positions) is bitwise taubinSmoothed(mesh, ...).positions.
class TaubinSmoother {
 public:
  // Throws InputError as taubinSmoothed does.
  TaubinSmoother(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap, const TaubinOptions& options = {});
  // One value per vertex of the topology (InputError for another count); the copies of a welded
  // vertex all get its representative's result.
  std::vector<Vec3> smoothed(const std::vector<Vec3>& positions) const;

 private:
  std::vector<uint32_t> weldMap_;
  TaubinOptions options_;
  // The welded neighbour graph, flat: vertex v's neighbours (sorted, unique) are
  // neighbourList_[neighbourStart_[v]] to neighbourList_[neighbourStart_[v + 1]].
  std::vector<uint32_t> neighbourStart_;
  std::vector<uint32_t> neighbourList_;
  std::vector<char> boundary_;  // an edge of a single triangle (char: read by threads at once)
};

}  // namespace lacrima
