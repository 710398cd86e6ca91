// The grid-accelerated closest-point query gives bitwise the brute-force answer.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "height_field_support.hpp"
#include "lacrima/mesh/closest_point_grid.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/mesh/shapes.hpp"

namespace lacrima {
namespace closest_point_grid_test {

void expectSameAsBruteForce(const TriangleMesh& mesh, const std::vector<Vec3>& queries) {
  const ClosestPointGrid grid(mesh);
  for (const Vec3& q : queries) {
    const SurfacePoint expected = closestSurfacePoint(mesh, q);
    const SurfacePoint found = grid.closest(q);
    ASSERT_EQ(found.triangle, expected.triangle) << q.transpose();
    ASSERT_EQ(found.barycentric, expected.barycentric) << q.transpose();
  }
}

std::vector<Vec3> randomPoints(std::mt19937& rng, int n, float lo, float hi) {
  std::uniform_real_distribution<float> u(lo, hi);
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) points.emplace_back(u(rng), u(rng), u(rng));
  return points;
}

TEST(ClosestPointGrid, MatchesBruteForceOnAWavySheetInsideAndFarOutside) {
  const TriangleMesh sheet = test::heightFieldMesh(40, 0.02f, [](float x, float y) {
    return 0.004f * std::sin(300.0f * x) * std::cos(200.0f * y);
  });
  std::mt19937 rng(7);
  expectSameAsBruteForce(sheet, randomPoints(rng, 400, -0.025f, 0.025f));
  expectSameAsBruteForce(sheet, randomPoints(rng, 50, -1.0f, 1.0f));  // mostly far outside the grid
  std::vector<Vec3> vertices(sheet.positions.begin(), sheet.positions.begin() + 200);
  expectSameAsBruteForce(sheet, vertices);  // on vertices: ties between the triangles around them
}

TEST(ClosestPointGrid, MatchesBruteForceOnAClosedEllipsoidAndAFlatSheet) {
  const TriangleMesh ellipsoid = makeEllipsoid(Vec3(0.1f, -0.2f, 0.3f), Mat3(Vec3(0.03f, 0.01f, 0.02f).asDiagonal()));
  std::mt19937 rng(11);
  expectSameAsBruteForce(ellipsoid, randomPoints(rng, 300, -0.1f, 0.4f));
  const TriangleMesh flat = test::heightFieldMesh(30, 0.01f, [](float, float) { return 0.0f; });
  expectSameAsBruteForce(flat, randomPoints(rng, 300, -0.012f, 0.012f));
}

TEST(ClosestPointGrid, DegenerateTrianglesNonFiniteQueriesAndEmptyMeshes) {
  TriangleMesh mesh = test::heightFieldMesh(6, 1.0f, [](float x, float) { return x; });
  mesh.positions.emplace_back(0.5f, 0.5f, 2.0f);
  const uint32_t v = uint32_t(mesh.positions.size() - 1);
  mesh.indices.insert(mesh.indices.end(), {v, v, v});  // a point "triangle"
  std::mt19937 rng(3);
  expectSameAsBruteForce(mesh, randomPoints(rng, 100, -2.0f, 3.0f));
  expectSameAsBruteForce(mesh, {Vec3(std::nanf(""), 0.0f, 0.0f), Vec3(INFINITY, 1.0f, 1.0f)});
  EXPECT_THROW(ClosestPointGrid(TriangleMesh{}), InputError);
}

}  // namespace closest_point_grid_test
}  // namespace lacrima
