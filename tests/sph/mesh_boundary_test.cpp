// Boundaries from triangle meshes (meshSurfaceSamples, dfsph.hpp): samples cover every triangle
// within the spacing, shared points once; a single layer of them holds water in a closed tank
// (Akinci et al. 2012's volumes make up for the missing layers); the same sites on a moved mesh
// are a moving boundary that carries the water with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lacrima/sph/dfsph.hpp"

namespace lacrima::sph {
namespace mesh_boundary_test {

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

TEST(MeshBoundary, SitesAreTheSamplesAndFollowTheMeshTheyWereFoundOn) {
  const TriangleMesh box = boxMesh(Vec3d::Zero(), Vec3d(0.1, 0.05, 0.1));
  const std::vector<SurfaceSite> sites = meshSurfaceSites(box, 0.01);
  EXPECT_EQ(sitePositions(box, sites), meshSurfaceSamples(box, 0.01));
  TriangleMesh moved = box;
  for (Vec3& p : moved.positions) p += Vec3(0.0f, 0.25f, 0.0f);
  const std::vector<Vec3d> before = sitePositions(box, sites), after = sitePositions(moved, sites);
  for (size_t i = 0; i < sites.size(); ++i) ASSERT_NEAR((after[i] - before[i]).y(), 0.25, 1e-6);
}

TEST(MeshBoundary, SelectedTrianglesAloneAreSampledAndTheCandidatesCountTheCost) {
  const TriangleMesh box = boxMesh(Vec3d::Zero(), Vec3d(0.1, 0.05, 0.1));
  // The two triangles of the face z = 0 (the first two of boxMesh).
  std::vector<bool> floor(box.triangleCount(), false);
  floor[0] = floor[1] = true;
  for (const Vec3d& p : sitePositions(box, meshSurfaceSites(box, 0.01, floor))) ASSERT_EQ(p.z(), 0.0);
  // Each triangle's grid of (n + 1)(n + 2) / 2 candidates, n = ceil(longest edge / spacing): the
  // face's diagonal 0.112 m -> n = 12, 91 each; sampling keeps fewer (the shared diagonal once).
  EXPECT_EQ(meshSurfaceSiteCandidates(box, 0.01, floor), 2 * 91.0);
  EXPECT_LT(double(meshSurfaceSites(box, 0.01, floor).size()), meshSurfaceSiteCandidates(box, 0.01, floor));
  EXPECT_GE(meshSurfaceSiteCandidates(box, 0.01), double(meshSurfaceSites(box, 0.01).size()));
  // The lattice count without the lattice.
  EXPECT_EQ(latticeBlockCount(Vec3d::Zero(), Vec3d(0.1, 0.05, 0.03), 0.01),
            double(latticeBlock(Vec3d::Zero(), Vec3d(0.1, 0.05, 0.03), 0.01).size()));
}

// A floor rising at 0.2 m/s under a resting layer of water: the boundary moves with each step and
// the layer rides on it (a floor that jumped without moveBoundary's velocities would leave the
// water behind, below it).
TEST(MeshBoundary, AMovingFloorLiftsTheWaterOnIt) {
  FluidParams params;
  params.particleRadius = 0.0025;
  const double spacing = 2.0 * params.particleRadius;
  const TriangleMesh floor = boxMesh(Vec3d(-0.05, -0.01, -0.05), Vec3d(0.05, 0.0, 0.05));
  BoundaryParticles boundary = boundaryFromSamples(meshSurfaceSamples(floor, spacing), params.particleRadius);
  DfsphSolver solver(params, latticeBlock(Vec3d(-0.02, spacing, -0.02), Vec3d(0.02, 0.02, 0.02), spacing), boundary);
  const Vec3d rise(0.0, 0.2, 0.0);
  solver.moveBoundary(boundary.positions, std::vector<Vec3d>(boundary.positions.size(), rise));
  solver.advanceTo(0.1);  // the floor's top is now at 0.02
  double lowest = 1.0;  // of the water over the floor (the layer spreads, some of it off the edges)
  for (const Vec3d& x : solver.positions())
    if (std::abs(x.x()) < 0.045 && std::abs(x.z()) < 0.045) lowest = std::min(lowest, x.y());
  EXPECT_GT(lowest, 0.02) << "water below the moved floor's top";
  EXPECT_LT(lowest, 0.02 + 2.0 * spacing);
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

}  // namespace mesh_boundary_test
}  // namespace lacrima::sph
