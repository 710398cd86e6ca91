#pragma once
// Fixed-radius neighbour search for SPH: points sorted by the key of their grid cell (cell size =
// the search radius), so each point's neighbours lie in the 27 cells around its own (Ihmsen et al.
// 2011, "A Parallel SPH Implementation on Multi-Core CPUs", Computer Graphics Forum 30(1): a
// compact, sorted uniform grid; the occupied cells found through a hash table). Built and queried in parallel (TBB); every list is in ascending
// index order whatever the thread count, so sums over neighbours, and the simulation, are bitwise
// the same with 1 or N threads.
#include <cstdint>
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima::sph {

class NeighbourGrid {
 public:
  // Indexes `points` (kept by reference until the next build) for queries of radius `radius`.
  NeighbourGrid(double radius) : radius_(radius) {}
  void build(const std::vector<Vec3d>& points);

  // Indices of the indexed points strictly within the radius of p, ascending (p's own index
  // among them when p is one of the points).
  void pointsNear(const Vec3d& p, std::vector<uint32_t>& out) const;

  double radius() const { return radius_; }

 private:
  struct Entry {
    uint64_t cell;
    uint32_t index;
  };
  uint64_t cellKey(int64_t i, int64_t j, int64_t k) const;
  int64_t cellCoordinate(double x) const;

  struct CellRange {
    uint64_t cell;
    uint32_t begin, end;  // into sorted_
  };
  // The range of `cell` in sorted_ (empty when no point lies there): an open-addressing table.
  const CellRange* findCell(uint64_t cell) const;

  double radius_;
  const std::vector<Vec3d>* points_ = nullptr;
  std::vector<Entry> sorted_;      // by (cell, index)
  std::vector<CellRange> ranges_;  // one per occupied cell
  std::vector<int32_t> table_;     // power-of-two slots: index into ranges_, -1 empty
};

// Per point of `queries`, its neighbours among the grid's points (ascending indices), in parallel.
std::vector<std::vector<uint32_t>> neighbourLists(const NeighbourGrid& grid, const std::vector<Vec3d>& queries);

}  // namespace lacrima::sph
