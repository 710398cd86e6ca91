// Closest-point queries accelerated by a uniform grid; see closest_point_grid.hpp.
#include "lacrima/mesh/closest_point_grid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

constexpr int kMaxCellsPerAxis = 256;
constexpr float kCellsPerTriangle = 2.0f;

// The largest cell edge that keeps about `target` cells over the box, whatever its flatness.
float cellEdge(const Vec3& extent, float target) {
  Vec3 e = extent;
  std::sort(e.data(), e.data() + 3);  // ascending
  const float volume = std::cbrt(e[0] * e[1] * e[2] / target);
  const float area = std::sqrt(e[1] * e[2] / target);
  const float length = e[2] / target;
  const float edge = std::max({volume, area, length});
  return edge > 0.0f ? edge : 1.0f;  // a single point: one cell
}

}  // namespace

ClosestPointGrid::ClosestPointGrid(const TriangleMesh& mesh) : mesh_(mesh) {
  if (mesh.triangleCount() == 0) throw InputError("closest point grid: the mesh has no triangles");
  Vec3 lo = Vec3::Constant(std::numeric_limits<float>::infinity());
  Vec3 hi = -lo;
  for (uint32_t index : mesh.indices) {
    lo = lo.cwiseMin(mesh.positions.at(index));
    hi = hi.cwiseMax(mesh.positions.at(index));
  }
  const Vec3 extent = hi - lo;
  // Triangle boxes are widened by this much so that no rounding of cell boundaries loses one.
  const float slack = 1e-5f * std::max(extent.maxCoeff(), 1e-12f);
  const float edge = cellEdge(extent, kCellsPerTriangle * float(mesh.triangleCount()));
  origin_ = lo;
  for (int a = 0; a < 3; ++a) {
    dims_[size_t(a)] = std::clamp(int(std::ceil(extent[a] / edge)), 1, kMaxCellsPerAxis);
    cellSize_[a] = extent[a] > 0.0f ? extent[a] / float(dims_[size_t(a)]) : edge;
  }
  const size_t cells = size_t(dims_[0]) * size_t(dims_[1]) * size_t(dims_[2]);
  auto forEachCellOf = [&](uint32_t t, auto&& visit) {
    Vec3 a, b, c;
    a = mesh.positions[mesh.indices[3 * size_t(t)]];
    b = mesh.positions[mesh.indices[3 * size_t(t) + 1]];
    c = mesh.positions[mesh.indices[3 * size_t(t) + 2]];
    const Cell from = cellOf(a.cwiseMin(b).cwiseMin(c) - Vec3::Constant(slack));
    const Cell to = cellOf(a.cwiseMax(b).cwiseMax(c) + Vec3::Constant(slack));
    for (int z = from[2]; z <= to[2]; ++z)
      for (int y = from[1]; y <= to[1]; ++y)
        for (int x = from[0]; x <= to[0]; ++x) visit(cellIndex({x, y, z}));
  };
  const uint32_t triangles = uint32_t(mesh.triangleCount());
  trianglesByCell_ = makeBucketLists(cells, [&](auto visit) {
    for (uint32_t t = 0; t < triangles; ++t) forEachCellOf(t, [&](size_t cell) { visit(t, cell); });
  });
}

ClosestPointGrid::Cell ClosestPointGrid::cellOf(const Vec3& p) const {
  Cell c;
  for (int a = 0; a < 3; ++a) {
    const float f = std::floor((p[a] - origin_[a]) / cellSize_[a]);
    c[size_t(a)] = int(std::clamp(f, 0.0f, float(dims_[size_t(a)] - 1)));
  }
  return c;
}

float ClosestPointGrid::distanceOutside(const Vec3& p, const Cell& lo, const Cell& hi) const {
  float bound = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    const size_t i = size_t(a);
    if (lo[i] > 0) bound = std::min(bound, p[a] - (origin_[a] + float(lo[i]) * cellSize_[a]));
    if (hi[i] < dims_[i] - 1) bound = std::min(bound, origin_[a] + float(hi[i] + 1) * cellSize_[a] - p[a]);
  }
  return std::max(bound, 0.0f);
}

SurfacePoint ClosestPointGrid::closest(const Vec3& p) const {
  if (!p.allFinite()) return closestSurfacePoint(mesh_, p);
  const Cell centre = cellOf(p);
  SurfacePoint best;
  float bestDistance = std::numeric_limits<float>::infinity();
  uint32_t bestTriangle = std::numeric_limits<uint32_t>::max();
  auto visitCell = [&](const Cell& cell) {
    for (const uint32_t t : trianglesByCell_.in(cellIndex(cell))) {
      Vec3 w;
      const float d = closestPointOnTriangle(mesh_, t, p, w);
      // closestSurfacePoint keeps the first (lowest) triangle of equal distance.
      if (d < bestDistance || (d == bestDistance && t < bestTriangle)) {
        bestDistance = d;
        bestTriangle = t;
        best = SurfacePoint{t, w};
      }
    }
  };
  Cell lo = centre, hi = centre;
  visitCell(centre);
  for (int shell = 1;; ++shell) {
    const float bound = distanceOutside(p, lo, hi);
    if (bound == std::numeric_limits<float>::infinity() || bound * bound > bestDistance) break;
    Cell newLo, newHi;
    for (size_t a = 0; a < 3; ++a) {
      newLo[a] = std::max(centre[a] - shell, 0);
      newHi[a] = std::min(centre[a] + shell, dims_[a] - 1);
    }
    for (int z = newLo[2]; z <= newHi[2]; ++z)
      for (int y = newLo[1]; y <= newHi[1]; ++y)
        for (int x = newLo[0]; x <= newHi[0]; ++x) {
          const bool searched = x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1] && z >= lo[2] && z <= hi[2];
          if (!searched) visitCell({x, y, z});
        }
    lo = newLo;
    hi = newHi;
  }
  if (bestTriangle == std::numeric_limits<uint32_t>::max()) return closestSurfacePoint(mesh_, p);  // all NaN
  return best;
}

}  // namespace lacrima
