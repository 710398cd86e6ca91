// Smooth normals: orientation, accuracy against analytic normals, welding across seams.
#include <gtest/gtest.h>

#include "lacrima/mesh/mesh.hpp"
#include "lacrima/mesh/shapes.hpp"

namespace lacrima {
namespace normals_test {

Mat3 ellipsoidAxes() {
  // Semi-axes 2, 1, 0.5 along a rotated frame, so that no axis is aligned with x, y or z.
  const Mat3 rotation = Eigen::AngleAxisf(0.4f, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  return rotation * Vec3(2.0f, 1.0f, 0.5f).asDiagonal();
}

TEST(SmoothNormals, EllipsoidNormalsPointOutwardAndMatchAnalytic) {
  const Vec3 center(0.3f, -1.0f, 2.0f);
  TriangleMesh mesh = makeEllipsoid(center, ellipsoidAxes(), 64, 128);
  const std::vector<Vec3> analytic = mesh.normals;
  mesh.normals.clear();
  computeSmoothNormals(mesh);
  ASSERT_EQ(mesh.normals.size(), analytic.size());
  float worstCos = 1.0f;
  for (size_t v = 0; v < analytic.size(); ++v) {
    EXPECT_GT(mesh.normals[v].dot(mesh.positions[v] - center), 0.0f) << "vertex " << v << " points inward";
    EXPECT_NEAR(mesh.normals[v].norm(), 1.0f, 1e-5f);
    worstCos = std::min(worstCos, mesh.normals[v].dot(analytic[v]));
  }
  // Area-weighted averages of a 64x128 tessellation of this 4:1 ellipsoid stay within 0.24
  // degrees of the analytic normal (measured); allow 0.5.
  EXPECT_GT(worstCos, std::cos(degreesToRadians(0.5f)));
}

TEST(SmoothNormals, AnalyticEllipsoidNormalsArePerpendicularToTheSurface) {
  // The inverse transpose normal is perpendicular to the tangents dp/dtheta and dp/dphi,
  // approximated here by the edges to neighbouring ring vertices at high resolution.
  const TriangleMesh mesh = makeEllipsoid(Vec3::Zero(), ellipsoidAxes(), 400, 800);
  const size_t v = 1 + 199 * 800 + 100;  // a vertex on the equator ring
  const Vec3 along = mesh.positions[v + 1] - mesh.positions[v - 1];
  const Vec3 across = mesh.positions[v + 800] - mesh.positions[v - 800];
  EXPECT_NEAR(mesh.normals[v].dot(along.normalized()), 0.0f, 1e-3f);
  EXPECT_NEAR(mesh.normals[v].dot(across.normalized()), 0.0f, 1e-3f);
}

// Two triangles folded along a shared edge, with the edge's vertices duplicated (as a UV seam
// splits them) so that the triangles share no index.
TriangleMesh foldedSeam() {
  TriangleMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0.5f, 0),   // left triangle, flat (normal +z)
                    Vec3(0, 0, 0), Vec3(1, 0.5f, 1), Vec3(0, 1, 0)};   // right triangle, tilted
  mesh.uvs = {Vec2(0, 0), Vec2(0, 1), Vec2(-1, 0.5f), Vec2(0.5f, 0), Vec2(1, 0.5f), Vec2(0.5f, 1)};
  mesh.indices = {0, 1, 2, 3, 4, 5};
  return mesh;
}

TEST(SmoothNormals, WeldingGivesSeamCopiesEqualNormals) {
  TriangleMesh welded = foldedSeam();
  computeSmoothNormals(welded, true);
  EXPECT_EQ(welded.normals[0], welded.normals[3]);
  EXPECT_EQ(welded.normals[1], welded.normals[5]);
  // The welded seam normal lies between the two face normals.
  const Vec3 left(0, 0, 1), right = Vec3(-1, 0, 1).normalized();
  // Area weighting: the right triangle (area sqrt 2 / 2) pulls harder than the left (1/2).
  EXPECT_LT((welded.normals[0] - (left + std::sqrt(2.0f) * right).normalized()).norm(), 1e-6f);
  EXPECT_NE(welded.normals[0], left);

  TriangleMesh split = foldedSeam();
  computeSmoothNormals(split, false);
  EXPECT_LT((split.normals[0] - left).norm(), 1e-6f);
  EXPECT_LT((split.normals[3] - right).norm(), 1e-6f);
}

TEST(SmoothNormals, WeldMapOverloadMatchesWeldingByPosition) {
  TriangleMesh a = makeEllipsoid(Vec3::Zero(), Mat3::Identity(), 8, 12);
  a.positions.push_back(a.positions[5]);  // an extra copy of vertex 5, used by a triangle
  a.indices[0] = uint32_t(a.positions.size() - 1);
  const std::vector<uint32_t> map = findCoincidentVertices(a);
  EXPECT_EQ(map.back(), 5u);
  EXPECT_EQ(map[7], 7u);
  TriangleMesh b = a;
  computeSmoothNormals(a, true);
  computeSmoothNormals(b, map);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.normals.back(), a.normals[5]);
}

TEST(SmoothNormals, NegativeZeroWeldsWithPositiveZero) {
  TriangleMesh mesh;
  mesh.positions = {Vec3(0.0f, 0, 0), Vec3(-0.0f, 0, 0)};
  const std::vector<uint32_t> map = findCoincidentVertices(mesh);
  EXPECT_EQ(map[1], 0u);
}

TEST(SmoothNormals, FlatRectangleHasItsPlaneNormal) {
  TriangleMesh mesh = makeRectangle(Vec3(1, 2, 3), Vec3(0, 0, 2), Vec3(0, 3, 0));  // normal = z x y = -x
  const std::vector<Vec3> given = mesh.normals;
  computeSmoothNormals(mesh);
  for (size_t v = 0; v < 4; ++v) {
    EXPECT_LT((mesh.normals[v] - Vec3(-1, 0, 0)).norm(), 1e-6f);
    EXPECT_LT((given[v] - Vec3(-1, 0, 0)).norm(), 1e-6f);
  }
}

TEST(SmoothNormals, IsolatedAndDegenerateVerticesGetAFiniteUnitNormal) {
  TriangleMesh mesh;
  mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(5, 5, 5)};  // collinear + isolated
  mesh.indices = {0, 1, 2};
  computeSmoothNormals(mesh);
  for (const Vec3& n : mesh.normals) {
    EXPECT_TRUE(n.allFinite());
    EXPECT_NEAR(n.norm(), 1.0f, 1e-6f);
  }
}

TEST(SmoothNormals, RejectsBadWeldMapsAndIndices) {
  TriangleMesh mesh = makeRectangle(Vec3::Zero(), Vec3(1, 0, 0), Vec3(0, 1, 0));
  EXPECT_THROW(computeSmoothNormals(mesh, std::vector<uint32_t>{0, 1}), std::invalid_argument);
  EXPECT_THROW(computeSmoothNormals(mesh, std::vector<uint32_t>{0, 1, 2, 9}), std::invalid_argument);
  mesh.indices[4] = 17;
  EXPECT_THROW(computeSmoothNormals(mesh), std::invalid_argument);
}

// ---- renewSmoothNormalsAround: the full computation's normals, only where they can change ----

// Moves the vertices within `radius` of `center` along +z by `height` times a smooth bump; the
// moved flags.
std::vector<bool> bump(TriangleMesh& mesh, const Vec3& center, float radius, float height) {
  std::vector<bool> moved(mesh.positions.size(), false);
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const float r = (mesh.positions[v] - center).norm() / radius;
    if (r >= 1.0f) continue;
    mesh.positions[v].z() += height * (1.0f - r * r) * (1.0f - r * r);
    moved[v] = true;
  }
  return moved;
}

// Every vertex of a triangle with a moved corner gets bitwise the full recomputation's normal;
// every other vertex keeps its normal.
void expectRenewedAsFullComputation(const TriangleMesh& before, TriangleMesh deformed, const std::vector<bool>& moved) {
  TriangleMesh full = deformed;
  computeSmoothNormals(full, true);
  renewSmoothNormalsAround(deformed, moved);
  std::vector<bool> around(moved.size(), false);
  for (size_t i = 0; i < deformed.indices.size(); i += 3) {
    const uint32_t* t = &deformed.indices[i];
    if (moved[t[0]] || moved[t[1]] || moved[t[2]]) around[t[0]] = around[t[1]] = around[t[2]] = true;
  }
  size_t renewed = 0;
  for (size_t v = 0; v < moved.size(); ++v) {
    if (around[v]) {
      ++renewed;
      EXPECT_EQ(deformed.normals[v], full.normals[v]) << "vertex " << v;
    } else {
      EXPECT_EQ(deformed.normals[v], before.normals[v]) << "vertex " << v;
    }
  }
  EXPECT_GT(renewed, 0u);
}

TEST(RenewSmoothNormalsAround, MatchesTheFullComputationBitwiseAroundABump) {
  TriangleMesh mesh = makeEllipsoid(Vec3(0.1f, -0.2f, 0.3f), ellipsoidAxes(), 48, 96);
  computeSmoothNormals(mesh, true);
  TriangleMesh deformed = mesh;
  const std::vector<bool> moved = bump(deformed, mesh.positions[mesh.positions.size() / 3], 0.4f, 0.05f);
  expectRenewedAsFullComputation(mesh, deformed, moved);
}

TEST(RenewSmoothNormalsAround, WeldsAcrossASeamLikeTheFullComputation) {
  // Moving the tilted triangle's free corner changes the normals of the seam copies 3 and 5,
  // which weld with 0 and 1 of the flat triangle: their sums take both triangles.
  TriangleMesh mesh = foldedSeam();
  computeSmoothNormals(mesh, true);
  TriangleMesh deformed = mesh;
  deformed.positions[4] += Vec3(0.0f, 0.0f, 0.5f);
  std::vector<bool> moved(deformed.positions.size(), false);
  moved[4] = true;
  expectRenewedAsFullComputation(mesh, deformed, moved);
  TriangleMesh renewed = deformed;
  renewSmoothNormalsAround(renewed, moved);
  EXPECT_NE(renewed.normals[3], Vec3(0, 0, 1));  // welded with the flat triangle, not its own face alone
}

TEST(RenewSmoothNormalsAround, NothingMovedChangesNothing) {
  TriangleMesh mesh = makeEllipsoid(Vec3::Zero(), ellipsoidAxes(), 16, 32);
  const std::vector<Vec3> normals = mesh.normals;
  renewSmoothNormalsAround(mesh, std::vector<bool>(mesh.positions.size(), false));
  EXPECT_EQ(mesh.normals, normals);
}

TEST(RenewSmoothNormalsAround, RejectsMissingNormalsFlagsAndBadIndices) {
  TriangleMesh mesh = makeRectangle(Vec3::Zero(), Vec3(1, 0, 0), Vec3(0, 1, 0));
  computeSmoothNormals(mesh);
  EXPECT_THROW(renewSmoothNormalsAround(mesh, std::vector<bool>(2, true)), std::invalid_argument);
  TriangleMesh noNormals = mesh;
  noNormals.normals.clear();
  EXPECT_THROW(renewSmoothNormalsAround(noNormals, std::vector<bool>(4, true)), std::invalid_argument);
  mesh.indices[4] = 17;
  EXPECT_THROW(renewSmoothNormalsAround(mesh, std::vector<bool>(4, true)), std::invalid_argument);
}

}  // namespace normals_test
}  // namespace lacrima
