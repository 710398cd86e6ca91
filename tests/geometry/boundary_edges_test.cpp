// countBoundaryEdges (mesh/mesh.hpp): what decides whether a dielectric mesh bounds a volume
// or is an open sheet rendered as a thin interface.
#include <gtest/gtest.h>

#include "lacrima/mesh/mesh.hpp"
#include "lacrima/mesh/shapes.hpp"

namespace lacrima {
namespace boundary_edges_test {

TEST(BoundaryEdges, AClosedEllipsoidHasNone) {
  EXPECT_EQ(countBoundaryEdges(makeEllipsoid(Vec3::Zero(), Mat3::Identity() * 0.01f, 8, 16)), 0u);
}

TEST(BoundaryEdges, ARectangleHasItsFourSides) {
  EXPECT_EQ(countBoundaryEdges(makeRectangle(Vec3::Zero(), Vec3(1, 0, 0), Vec3(0, 1, 0))), 4u);
}

TEST(BoundaryEdges, ASphereCutAlongASeamIsStillClosed) {
  // Every vertex of the first triangle fan duplicated, as a UV seam splits vertices in glTF:
  // by index the fan's edges are open, welded by position they are not.
  TriangleMesh mesh = makeEllipsoid(Vec3::Zero(), Mat3::Identity(), 6, 12);
  for (size_t i = 0; i < 9; ++i) {
    mesh.positions.push_back(mesh.positions[mesh.indices[i]]);
    mesh.indices[i] = uint32_t(mesh.positions.size() - 1);
  }
  EXPECT_EQ(countBoundaryEdges(mesh), 0u);
  EXPECT_NE(findClosedMeshDefect(mesh), "");  // the index-based check does see the cut
}

TEST(BoundaryEdges, RemovingATriangleOpensThreeEdges) {
  TriangleMesh mesh = makeEllipsoid(Vec3::Zero(), Mat3::Identity(), 6, 12);
  mesh.indices.resize(mesh.indices.size() - 3);
  EXPECT_EQ(countBoundaryEdges(mesh), 3u);
}

}  // namespace boundary_edges_test
}  // namespace lacrima
