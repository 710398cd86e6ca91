// Compact sorted-grid neighbour search; see neighbour_grid.hpp.
#include "lacrima/sph/neighbour_grid.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>

#include "lacrima/base/hash.hpp"

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
  ranges_.clear();
  for (uint32_t n = 0; n < sorted_.size(); ++n) {
    if (ranges_.empty() || ranges_.back().cell != sorted_[n].cell) ranges_.push_back({sorted_[n].cell, n, n});
    ranges_.back().end = n + 1;
  }
  size_t slots = 16;
  while (slots < 2 * ranges_.size()) slots *= 2;  // at most half full: short probes
  table_.assign(slots, -1);
  for (size_t r = 0; r < ranges_.size(); ++r) {
    size_t slot = ranges_[r].cell & (slots - 1);
    while (table_[slot] >= 0) slot = (slot + 1) & (slots - 1);
    table_[slot] = int32_t(r);
  }
}

const NeighbourGrid::CellRange* NeighbourGrid::findCell(uint64_t cell) const {
  if (table_.empty()) return nullptr;
  const size_t mask = table_.size() - 1;
  for (size_t slot = cell & mask;; slot = (slot + 1) & mask) {
    if (table_[slot] < 0) return nullptr;
    if (ranges_[size_t(table_[slot])].cell == cell) return &ranges_[size_t(table_[slot])];
  }
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
        const CellRange* range = findCell(key);
        if (!range) continue;
        for (uint32_t n = range->begin; n < range->end; ++n)
          if (((*points_)[sorted_[n].index] - p).squaredNorm() < radiusSquared) out.push_back(sorted_[n].index);
      }
  std::sort(out.begin(), out.end());
}

std::vector<std::vector<uint32_t>> neighbourLists(const NeighbourGrid& grid, const std::vector<Vec3d>& queries) {
  std::vector<std::vector<uint32_t>> lists(queries.size());
  tbb::parallel_for(size_t(0), queries.size(), [&](size_t n) { grid.pointsNear(queries[n], lists[n]); });
  return lists;
}

}  // namespace lacrima::sph
