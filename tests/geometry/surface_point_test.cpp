// Surface points at a vertex and at a texture coordinate.
#include <gtest/gtest.h>

#include "lacrima/mesh/surface_point.hpp"

namespace lacrima {
namespace surface_point_test {

// Two triangles over the unit square, uv = (x, y); vertex 4 is unused.
TriangleMesh unitSquare() {
  TriangleMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(5, 5, 5)};
  mesh.uvs = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1), Vec2(9, 9)};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

TEST(SurfacePointAt, VertexUsesTheFirstTriangleWithWeightOneAtItsCorner) {
  const TriangleMesh mesh = unitSquare();
  const auto p = vertexSurfacePoint(mesh, 3);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->triangle, 1u);
  EXPECT_EQ(p->barycentric, Vec3(0, 0, 1));
  EXPECT_EQ(surfacePosition(mesh, *p), mesh.positions[3]);
  EXPECT_EQ(vertexSurfacePoint(mesh, 2)->triangle, 0u) << "the lowest triangle index wins";
  EXPECT_FALSE(vertexSurfacePoint(mesh, 4)) << "unused vertex";
  EXPECT_FALSE(vertexSurfacePoint(mesh, 99)) << "out of range";
}

TEST(SurfacePointAt, UvInsideATriangleGivesThePointWithThoseCoordinates) {
  const TriangleMesh mesh = unitSquare();
  for (const Vec2& uv : {Vec2(0.7f, 0.2f), Vec2(0.2f, 0.7f), Vec2(0.5f, 0.5f), Vec2(0, 0), Vec2(1, 1)}) {
    const auto p = surfacePointAtUv(mesh, uv);
    ASSERT_TRUE(p) << uv.transpose();
    EXPECT_NEAR(p->barycentric.sum(), 1.0f, 1e-6f);
    EXPECT_GE(p->barycentric.minCoeff(), 0.0f);
    const Vec3 position = surfacePosition(mesh, *p);
    EXPECT_NEAR(position.x(), uv.x(), 1e-6f);
    EXPECT_NEAR(position.y(), uv.y(), 1e-6f);
  }
  EXPECT_EQ(surfacePointAtUv(mesh, Vec2(0.7f, 0.2f))->triangle, 0u);
  EXPECT_EQ(surfacePointAtUv(mesh, Vec2(0.2f, 0.7f))->triangle, 1u);
}

TEST(SurfacePointAt, UvOutsideOrWithoutCoordinatesGivesNothing) {
  TriangleMesh mesh = unitSquare();
  EXPECT_FALSE(surfacePointAtUv(mesh, Vec2(1.5f, 0.5f)));
  EXPECT_FALSE(surfacePointAtUv(mesh, Vec2(-0.001f, 0.5f)));
  mesh.uvs.clear();
  EXPECT_FALSE(surfacePointAtUv(mesh, Vec2(0.5f, 0.5f)));
}

}  // namespace surface_point_test
}  // namespace lacrima
