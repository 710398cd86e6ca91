// Boundaries from triangle meshes (meshSurfaceSamples, dfsph.hpp): samples cover every triangle
// within the spacing, shared points once; a single layer of them holds water in a closed tank
// (Akinci et al. 2012's volumes make up for the missing layers).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "lacrima/sph/dfsph.hpp"

namespace lacrima::sph {
namespace {

// The six faces of the box [lo, hi] as twelve triangles.
TriangleMesh boxMesh(const Vec3d& lo, const Vec3d& hi) {
  TriangleMesh mesh;
  for (int k = 0; k < 8; ++k)
    mesh.positions.emplace_back(float(k & 1 ? hi.x() : lo.x()), float(k & 2 ? hi.y() : lo.y()), float(k & 4 ? hi.z() : lo.z()));
  mesh.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                  2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  return mesh;
}

TEST(MeshBoundary, SamplesCoverEachTriangleWithinTheSpacingAndOnce) {
  const double spacing = 0.01;
  const std::vector<Vec3d> samples = meshSurfaceSamples(boxMesh(Vec3d::Zero(), Vec3d(0.1, 0.1, 0.1)), spacing);
  // Every point of the floor is within the spacing of a sample (a triangle's grid step along its
  // legs is at most the spacing, so the nearest grid point is closer than that).
  for (double x = 0.0; x <= 0.1; x += 0.0037)
    for (double z = 0.0; z <= 0.1; z += 0.0041) {
      double nearest = 1e9;
      for (const Vec3d& s : samples) nearest = std::min(nearest, (s - Vec3d(x, 0.0, z)).norm());
      ASSERT_LE(nearest, spacing);
    }
  // No sample twice (shared corners and edges).
  for (size_t a = 0; a < samples.size(); ++a)
    for (size_t b = a + 1; b < samples.size(); ++b) ASSERT_GT((samples[a] - samples[b]).norm(), 1e-3 * spacing);
  EXPECT_GT(samples.size(), 600u);  // at least the 6 faces' 10 x 10 grids
}

TEST(MeshBoundary, OneLayerOfSamplesHoldsWaterInAClosedTank) {
  FluidParams params;
  params.particleRadius = 0.005;
  params.xsphViscosity = 0.05;
  const double spacing = 2.0 * params.particleRadius;
  const Vec3d tankHi(0.12, 0.2, 0.12);
  // The water starts a spacing away from the walls and floor (see meshSurfaceSamples).
  DfsphSolver solver(params, latticeBlock(Vec3d::Constant(0.5 * spacing), Vec3d(0.115, 0.105, 0.115), spacing),
                     boundaryFromSamples(meshSurfaceSamples(boxMesh(Vec3d::Zero(), tankHi), params.particleRadius),
                                         params.particleRadius));
  const size_t count = solver.positions().size();
  solver.advanceTo(1.5);
  int outside = 0;
  std::vector<double> heights;
  for (const Vec3d& x : solver.positions()) {
    heights.push_back(x.y());
    if ((x.array() < 0.0).any() || (x.array() > tankHi.array()).any()) ++outside;
  }
  // The column's top and bottom: the 99th and 1st percentiles of the heights, plus a radius (a
  // particle or two tossed up by the settling are not the surface).
  std::sort(heights.begin(), heights.end());
  const double top = heights[size_t(0.99 * double(heights.size() - 1))] + params.particleRadius;
  const double lowest = heights[size_t(0.01 * double(heights.size() - 1))] - params.particleRadius;
  std::printf("[ mesh boundary ] %zu particles after 1.5 s: %d outside, column %.4f - %.4f m\n", count, outside, lowest,
              top);
  EXPECT_EQ(outside, 0);
  EXPECT_NEAR(top - lowest, 0.1, 0.005);  // measured 0.1033: the bottom layer rests about 2 r above the single layer
}

}  // namespace
}  // namespace lacrima::sph
