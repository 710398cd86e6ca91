// Compact sorted-grid neighbour search; see neighbour_grid.hpp.
#include "lacrima/sph/neighbour_grid.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>

#include "lacrima/geometry/sampler.hpp"

namespace lacrima::sph {

int64_t NeighbourGrid::cellCoordinate(double x) const { return int64_t(std::floor(x / radius_)); }

// A hash of the cell (a 64-bit mix of its coordinates): distinct cells collide with negligible
// probability, and a collision only adds candidates that the distance test then rejects.
uint64_t NeighbourGrid::cellKey(int64_t i, int64_t j, int64_t k) const {
  return mix64(uint64_t(i) * 0x9e3779b97f4a7c15ULL ^ uint64_t(j) * 0xc2b2ae3d27d4eb4fULL ^
               uint64_t(k) * 0x165667b19e3779f9ULL);
}

void NeighbourGrid::build(const std::vector<Vec3d>& points) {
  points_ = &points;
  sorted_.resize(points.size());
  tbb::parallel_for(size_t(0), points.size(), [&](size_t n) {
    const Vec3d& p = points[n];
    sorted_[n] = {cellKey(cellCoordinate(p.x()), cellCoordinate(p.y()), cellCoordinate(p.z())), uint32_t(n)};
  });
  tbb::parallel_sort(sorted_.begin(), sorted_.end(),
                     [](const Entry& a, const Entry& b) { return a.cell != b.cell ? a.cell < b.cell : a.index < b.index; });
}

void NeighbourGrid::pointsNear(const Vec3d& p, std::vector<uint32_t>& out) const {
  out.clear();
  if (!points_) return;
  const int64_t ci = cellCoordinate(p.x()), cj = cellCoordinate(p.y()), ck = cellCoordinate(p.z());
  const double radiusSquared = radius_ * radius_;
  uint64_t visited[27];
  int visitedCount = 0;
  for (int64_t di = -1; di <= 1; ++di)
    for (int64_t dj = -1; dj <= 1; ++dj)
      for (int64_t dk = -1; dk <= 1; ++dk) {
        const uint64_t key = cellKey(ci + di, cj + dj, ck + dk);
        // Two of the 27 cells hashing alike would list their points twice.
        if (std::find(visited, visited + visitedCount, key) != visited + visitedCount) continue;
        visited[visitedCount++] = key;
        auto it = std::lower_bound(sorted_.begin(), sorted_.end(), key,
                                   [](const Entry& e, uint64_t k) { return e.cell < k; });
        for (; it != sorted_.end() && it->cell == key; ++it)
          if (((*points_)[it->index] - p).squaredNorm() < radiusSquared) out.push_back(it->index);
      }
  std::sort(out.begin(), out.end());
}

std::vector<std::vector<uint32_t>> neighbourLists(const NeighbourGrid& grid, const std::vector<Vec3d>& queries) {
  std::vector<std::vector<uint32_t>> lists(queries.size());
  tbb::parallel_for(size_t(0), queries.size(), [&](size_t n) { grid.pointsNear(queries[n], lists[n]); });
  return lists;
}

}  // namespace lacrima::sph
