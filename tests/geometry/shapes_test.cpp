// Ellipsoids and rectangles: closed, oriented, the right volume and normals; plus the mesh
// checks and transforms that they exercise.
#include <gtest/gtest.h>

#include <map>

#include "lacrima/base/error.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/mesh/shapes.hpp"

namespace lacrima {
namespace shapes_test {

// Independent of findClosedMeshDefect: counts directed edges by hand.
void expectClosedAndOriented(const TriangleMesh& mesh) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t i = 0; i < mesh.indices.size(); i += 3)
    for (int k = 0; k < 3; ++k) ++directed[{mesh.indices[i + k], mesh.indices[i + (k + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << "directed edge " << edge.first << "->" << edge.second << " appears " << count << " times";
    ASSERT_EQ(directed.count({edge.second, edge.first}), 1u) << "edge " << edge.first << "-" << edge.second << " is open";
  }
  // Euler characteristic of a sphere: V - E + F = 2 (each undirected edge counted once).
  EXPECT_EQ(long(mesh.vertexCount()) - long(directed.size() / 2) + long(mesh.triangleCount()), 2);
  EXPECT_EQ(findClosedMeshDefect(mesh), "");
}

double sphereVolume(const Mat3& axes) { return 4.0 / 3.0 * std::numbers::pi * std::abs(double(axes.determinant())); }

TEST(Ellipsoid, IsClosedOrientedAndWatertight) {
  const Mat3 axes = Vec3(0.003f, 0.002f, 0.0015f).asDiagonal();  // a tear-sized drop, in metres
  const TriangleMesh mesh = makeEllipsoid(Vec3(0.01f, 0.02f, 0.03f), axes, 12, 20);
  EXPECT_EQ(findMeshDefect(mesh), "");
  EXPECT_EQ(mesh.vertexCount(), size_t(2 + 11 * 20));  // single pole vertices, no seam copies
  EXPECT_EQ(mesh.triangleCount(), size_t(2 * 20 * 11));
  expectClosedAndOriented(mesh);
}

TEST(Ellipsoid, VolumeConvergesToFourThirdsPiAbc) {
  const Mat3 axes = Eigen::AngleAxisf(1.0f, Vec3(0, 1, 1).normalized()).toRotationMatrix() *
                    Vec3(2.0f, 1.5f, 0.7f).asDiagonal();
  const double exact = sphereVolume(axes);
  const double coarse = signedVolume(makeEllipsoid(Vec3(5, 5, 5), axes, 24, 48));
  const double fine = signedVolume(makeEllipsoid(Vec3(5, 5, 5), axes, 96, 192));
  // An inscribed polyhedron: slightly smaller, the error falls like 1/n^2.
  EXPECT_LT(coarse, exact);
  EXPECT_LT(fine, exact);
  EXPECT_NEAR(coarse / exact, 1.0, 0.01);
  EXPECT_NEAR(fine / exact, 1.0, 0.001);
  EXPECT_LT(exact - fine, (exact - coarse) / 10.0);
}

TEST(Ellipsoid, NormalsAreUnitAndOutward) {
  const Vec3 center(1, 2, 3);
  const Mat3 axes = Vec3(1.0f, 2.0f, 3.0f).asDiagonal();
  const TriangleMesh mesh = makeEllipsoid(center, axes, 16, 32);
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    EXPECT_NEAR(mesh.normals[v].norm(), 1.0f, 1e-6f);
    EXPECT_GT(mesh.normals[v].dot(mesh.positions[v] - center), 0.0f);
    // Gradient of the implicit function (x/a)^2 + (y/b)^2 + (z/c)^2: its direction is the normal.
    const Vec3 d = mesh.positions[v] - center;
    const Vec3 gradient(d.x() / 1.0f, d.y() / 4.0f, d.z() / 9.0f);
    EXPECT_LT((mesh.normals[v] - gradient.normalized()).norm(), 1e-5f);
  }
  // Every triangle's winding agrees with its vertex normals (outward, counter-clockwise).
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    const Vec3& a = mesh.positions[mesh.indices[i]];
    const Vec3 g = (mesh.positions[mesh.indices[i + 1]] - a).cross(mesh.positions[mesh.indices[i + 2]] - a);
    EXPECT_GT(g.dot(mesh.normals[mesh.indices[i]]), 0.0f) << "triangle " << i / 3;
  }
}

TEST(Ellipsoid, LeftHandedAxesStayOutward) {
  const Mat3 axes = Vec3(-1.0f, 1.0f, 1.0f).asDiagonal();
  const TriangleMesh mesh = makeEllipsoid(Vec3::Zero(), axes, 16, 32);
  expectClosedAndOriented(mesh);
  EXPECT_GT(signedVolume(mesh), 0.0);
  for (size_t v = 0; v < mesh.vertexCount(); ++v) EXPECT_GT(mesh.normals[v].dot(mesh.positions[v]), 0.0f);
}

TEST(Ellipsoid, RejectsBadParameters) {
  EXPECT_THROW(makeEllipsoid(Vec3::Zero(), Mat3::Identity(), 1, 8), InputError);
  EXPECT_THROW(makeEllipsoid(Vec3::Zero(), Mat3::Identity(), 4, 2), InputError);
  Mat3 flat = Mat3::Identity();
  flat(2, 2) = 0.0f;
  EXPECT_THROW(makeEllipsoid(Vec3::Zero(), flat, 8, 8), InputError);
}

TEST(Rectangle, TwoTrianglesFacingEdgeUCrossEdgeV) {
  const TriangleMesh mesh = makeRectangle(Vec3(0, 1, 0), Vec3(2, 0, 0), Vec3(0, 0, -4));  // x cross -z = +y
  EXPECT_EQ(mesh.triangleCount(), 2u);
  EXPECT_EQ(findMeshDefect(mesh), "");
  for (const Vec3& n : mesh.normals) EXPECT_LT((n - Vec3(0, 1, 0)).norm(), 1e-6f);
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    const Vec3& a = mesh.positions[mesh.indices[i]];
    const Vec3 g = (mesh.positions[mesh.indices[i + 1]] - a).cross(mesh.positions[mesh.indices[i + 2]] - a);
    EXPECT_GT(g.y(), 0.0f);
  }
  const Eigen::AlignedBox3f box = computeBounds(mesh);
  EXPECT_LT((box.min() - Vec3(-1, 1, -2)).norm(), 1e-6f);
  EXPECT_LT((box.max() - Vec3(1, 1, 2)).norm(), 1e-6f);
  ASSERT_EQ(mesh.uvs.size(), 4u);
  EXPECT_EQ(mesh.uvs[0], Vec2(0, 0));
  EXPECT_EQ(mesh.uvs[2], Vec2(1, 1));
  EXPECT_THROW(makeRectangle(Vec3::Zero(), Vec3(1, 0, 0), Vec3(2, 0, 0)), InputError);
}

TEST(TransformMesh, NonUniformScaleKeepsNormalsPerpendicular) {
  TriangleMesh mesh = makeEllipsoid(Vec3::Zero(), Mat3::Identity(), 16, 32);  // unit sphere
  Affine3 t = Affine3::Identity();
  t.translate(Vec3(1, 0, 0)).rotate(Eigen::AngleAxisf(0.3f, Vec3::UnitY())).scale(Vec3(3, 1, 0.5f));
  transformMesh(mesh, t);
  const TriangleMesh expected = makeEllipsoid(Vec3(1, 0, 0), t.linear(), 16, 32);
  for (size_t v = 0; v < mesh.vertexCount(); ++v) {
    EXPECT_LT((mesh.positions[v] - expected.positions[v]).norm(), 1e-5f);
    EXPECT_LT((mesh.normals[v] - expected.normals[v]).norm(), 1e-5f);
  }
}

TEST(TransformMesh, MirrorFlipsWindingToStayOutward) {
  TriangleMesh mesh = makeEllipsoid(Vec3::Zero(), Mat3::Identity(), 8, 16);
  const double before = signedVolume(mesh);
  Affine3 mirror = Affine3::Identity();
  mirror.scale(Vec3(1, -1, 1));
  transformMesh(mesh, mirror);
  EXPECT_NEAR(signedVolume(mesh), before, 1e-6);
  expectClosedAndOriented(mesh);
  for (size_t v = 0; v < mesh.vertexCount(); ++v) EXPECT_GT(mesh.normals[v].dot(mesh.positions[v]), 0.0f);
}

TEST(MeshChecks, FindMeshDefectNamesTheProblem) {
  const TriangleMesh good = makeRectangle(Vec3::Zero(), Vec3(1, 0, 0), Vec3(0, 1, 0));
  EXPECT_EQ(findMeshDefect(good), "");
  TriangleMesh m = good;
  m.indices[5] = 4;
  EXPECT_NE(findMeshDefect(m).find("index 5"), std::string::npos) << findMeshDefect(m);
  m = good;
  m.indices.pop_back();
  EXPECT_NE(findMeshDefect(m).find("multiple of 3"), std::string::npos);
  m = good;
  m.positions[2].y() = std::numeric_limits<float>::infinity();
  EXPECT_NE(findMeshDefect(m).find("vertex 2"), std::string::npos);
  m = good;
  m.normals.pop_back();
  EXPECT_NE(findMeshDefect(m).find("normals"), std::string::npos);
  m = good;
  m.uvs.push_back(Vec2(0, 0));
  EXPECT_NE(findMeshDefect(m).find("uvs"), std::string::npos);
  m = good;
  m.normals[1].x() = std::nanf("");
  EXPECT_NE(findMeshDefect(m).find("normal"), std::string::npos);
}

TEST(MeshChecks, FindClosedMeshDefectSeesOpenAndFlippedMeshes) {
  EXPECT_NE(findClosedMeshDefect(makeRectangle(Vec3::Zero(), Vec3(1, 0, 0), Vec3(0, 1, 0))).find("open"), std::string::npos);
  TriangleMesh flipped = makeEllipsoid(Vec3::Zero(), Mat3::Identity(), 6, 8);
  std::swap(flipped.indices[1], flipped.indices[2]);  // one triangle turned inside out
  EXPECT_NE(findClosedMeshDefect(flipped), "");
  TriangleMesh holed = makeEllipsoid(Vec3::Zero(), Mat3::Identity(), 6, 8);
  holed.indices.resize(holed.indices.size() - 3);
  EXPECT_NE(findClosedMeshDefect(holed).find("open"), std::string::npos);
}

}  // namespace shapes_test
}  // namespace lacrima
