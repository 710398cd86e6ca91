#pragma once
// Many closest-point queries on one mesh: a uniform grid of cells, each listing the triangles
// whose bounding boxes overlap it. A query searches shells of cells around the query point's cell
// until no unsearched cell can hold a nearer triangle, so the answer is exactly
// closestSurfacePoint's (same distance arithmetic, ties to the lowest triangle index) at a cost
// that grows with the triangles near the point instead of all of them.
#include <array>
#include <cstdint>
#include <vector>

#include "lacrima/base/bucket_lists.hpp"
#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/mesh/surface_point.hpp"

namespace lacrima {

class ClosestPointGrid {
 public:
  // Keeps a reference to `mesh`, which must outlive the grid and not change. Throws InputError
  // for a mesh without triangles.
  explicit ClosestPointGrid(const TriangleMesh& mesh);

  // The nearest point of the mesh to p: bitwise closestSurfacePoint(mesh, p).
  SurfacePoint closest(const Vec3& p) const;

 private:
  using Cell = std::array<int, 3>;
  Cell cellOf(const Vec3& p) const;  // clamped into the grid
  size_t cellIndex(const Cell& c) const { return (size_t(c[2]) * size_t(dims_[1]) + size_t(c[1])) * size_t(dims_[0]) + size_t(c[0]); }
  // A lower bound of the distance from p to any cell outside the box [lo, hi] of cells.
  float distanceOutside(const Vec3& p, const Cell& lo, const Cell& hi) const;

  const TriangleMesh& mesh_;
  Vec3 origin_ = Vec3::Zero();
  Vec3 cellSize_ = Vec3::Ones();
  Cell dims_{1, 1, 1};
  BucketLists trianglesByCell_;  // every triangle in each cell its box (grown by a slack) overlaps
};

}  // namespace lacrima
