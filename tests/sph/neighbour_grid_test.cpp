// The neighbour grid (neighbour_grid.hpp): the same neighbours as a brute-force search, in
// ascending order, whatever the thread count.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "lacrima/base/hash.hpp"
#include "lacrima/sph/neighbour_grid.hpp"

namespace lacrima::sph {
namespace neighbour_grid_test {

std::vector<Vec3d> randomPoints(size_t count, double extent, uint64_t seed) {
  std::vector<Vec3d> points;
  for (size_t n = 0; n < count; ++n) {
    const uint64_t key = hashCombine(seed, n);
    points.push_back(extent * Vec3d(uint64ToUnitFloat(hashCombine(key, 0)), uint64ToUnitFloat(hashCombine(key, 1)),
                                    uint64ToUnitFloat(hashCombine(key, 2))) -
                     Vec3d(0.3, -1.7, 2.2));  // off the origin, negative coordinates included
  }
  return points;
}

TEST(NeighbourGrid, FindsWhatABruteForceSearchFinds) {
  const double radius = 0.01;
  const std::vector<Vec3d> points = randomPoints(3000, 0.06, 1);
  NeighbourGrid grid(radius);
  grid.build(points);
  const std::vector<Vec3d> queries = randomPoints(500, 0.07, 2);
  size_t found = 0;
  for (const std::vector<Vec3d>* set : {&points, &queries})
    for (const Vec3d& q : *set) {
      std::vector<uint32_t> expected;
      for (uint32_t j = 0; j < points.size(); ++j)
        if ((points[j] - q).squaredNorm() < radius * radius) expected.push_back(j);
      std::vector<uint32_t> near;
      grid.pointsNear(q, near);
      ASSERT_EQ(near, expected);
      found += near.size();
    }
  EXPECT_GT(found, 3500u * 10);  // about 58 neighbours a point: the test sees crowded cells
}

TEST(NeighbourGrid, ListsAreTheSameForAnyThreadCount) {
  const std::vector<Vec3d> points = randomPoints(5000, 0.05, 3);
  NeighbourGrid grid(0.008);
  std::vector<std::vector<uint32_t>> one, all;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    grid.build(points);
    one = neighbourLists(grid, points);
  }
  grid.build(points);
  all = neighbourLists(grid, points);
  EXPECT_EQ(one, all);
}

}  // namespace neighbour_grid_test
}  // namespace lacrima::sph
