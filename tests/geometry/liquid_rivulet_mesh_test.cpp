// The liquid rivulet mesh: closed and outward, the parabolic section's volume along a straight
// rivulet plus its two rounded ends, following a bend of the skin, and bad stations rejected.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "lacrima/base/error.hpp"
#include "lacrima/liquid/liquid_rivulet_mesh.hpp"

namespace lacrima {
namespace liquid_rivulet_mesh_test {

// Stations every `spacing` down -y on the plane z = 0.
std::vector<LiquidRivuletStation> straightStations(int count, float spacing, float halfWidth, float height) {
  std::vector<LiquidRivuletStation> stations;
  for (int i = 0; i < count; ++i)
    stations.push_back({Vec3(0.0f, -spacing * float(i), 0.0f), Vec3::UnitZ(), Vec3(0.0f, -1.0f, 0.2f), halfWidth, height});
  return stations;
}

TEST(LiquidRivuletMesh, IsClosedOutwardAndHoldsTheSectionAlongItsLengthPlusTwoRoundedEnds) {
  const float a = 2.2e-4f, h = 2.4e-4f, spacing = 5e-4f;
  for (int count : {1, 2, 40}) {
    const TriangleMesh mesh = makeLiquidRivuletMesh(straightStations(count, spacing, a, h), 0.0f, {64, 4, 16});
    EXPECT_EQ(findWeldedClosedMeshDefect(mesh), "") << count;
    EXPECT_EQ(countBoundaryEdges(mesh), 0u) << count;
    // Section (4/3) a h; each end an ellipsoidal quarter of it: (2/3) a of full section.
    const double section = 4.0 / 3.0 * a * h;
    const double expected = section * (double(count - 1) * spacing + 2.0 * (2.0 / 3.0) * a);
    EXPECT_NEAR(signedVolume(mesh) / expected, 1.0, 0.01) << count;
  }
}

// The crease along the edges stays sharp: the top's normals there tilt by the parabola's edge
// angle, atan(2 height / halfWidth), from the skin's normal; the base's point into the skin.
TEST(LiquidRivuletMesh, TopAndBaseKeepTheirOwnNormalsAtTheEdges) {
  const float a = 3e-4f, h = 2e-4f;
  const TriangleMesh mesh = makeLiquidRivuletMesh(straightStations(9, 5e-4f, a, h), 0.0f, {24, 4, 4});
  const float edgeTilt = std::atan(2.0f * h / a);
  int topEdges = 0, baseEdges = 0;
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec3& p = mesh.positions[v];
    if (std::abs(std::abs(p.x()) - a) > 1e-9f || p.y() < -4e-3f + 1e-6f || p.y() > -1e-6f) continue;  // mid stations' edges
    const Vec3& n = mesh.normals[v];
    if (n.z() < 0.0f) {
      EXPECT_NEAR(n.z(), -1.0f, 1e-5f);
      ++baseEdges;
    } else {
      // The smooth normal averages the faces around it: within the angle of one segment of the edge's.
      EXPECT_NEAR(std::acos(n.z()), edgeTilt, 0.12f);
      EXPECT_GT(n.x() * p.x(), 0.0f);  // leaning outwards
      ++topEdges;
    }
  }
  EXPECT_EQ(topEdges, 2 * 7);
  EXPECT_EQ(baseEdges, 2 * 7);
}

TEST(LiquidRivuletMesh, TheBaseLiesBaseOffsetAlongTheNormalAndTheTopAtTheHeight) {
  const float a = 3e-4f, h = 2e-4f;
  const TriangleMesh mesh = makeLiquidRivuletMesh(straightStations(5, 5e-4f, a, h), -2e-5f);
  float lowest = std::numeric_limits<float>::max(), highest = -lowest, widest = 0.0f;
  for (const Vec3& p : mesh.positions) {
    lowest = std::min(lowest, p.z());
    highest = std::max(highest, p.z());
    widest = std::max(widest, std::abs(p.x()));
  }
  EXPECT_NEAR(lowest, -2e-5f, 1e-9f);
  EXPECT_NEAR(highest, h - 2e-5f, 1e-9f);
  EXPECT_NEAR(widest, a, 1e-9f);
}

// Stations around a cylinder of radius 1 cm (skin curving away under the rivulet): the mesh stays
// closed and outward, every station's section sits on its own tangent plane.
TEST(LiquidRivuletMesh, FollowsTheStationsRoundABend) {
  std::vector<LiquidRivuletStation> stations;
  const float radius = 0.01f;
  for (int i = 0; i < 30; ++i) {
    const float angle = 0.05f * float(i);
    const Vec3 normal(0.0f, std::sin(angle), std::cos(angle));
    const Vec3 along(0.0f, std::cos(angle), -std::sin(angle));
    stations.push_back({radius * normal, normal, along, 2e-4f, 2e-4f});
  }
  const TriangleMesh mesh = makeLiquidRivuletMesh(stations, -2e-5f);
  EXPECT_EQ(findWeldedClosedMeshDefect(mesh), "");
  EXPECT_GT(signedVolume(mesh), 0.0);
  for (const Vec3& p : mesh.positions) {
    const float fromAxis = std::hypot(p.y(), p.z());
    EXPECT_GT(fromAxis, radius - 2.5e-5f);
    EXPECT_LT(fromAxis, radius + 2.1e-4f);
  }
}

TEST(LiquidRivuletMesh, RejectsBadStationsAndResolution) {
  const auto good = straightStations(3, 5e-4f, 2e-4f, 2e-4f);
  EXPECT_THROW(makeLiquidRivuletMesh({}, 0.0f), InputError);
  auto bad = good;
  bad[1].halfWidth = 0.0f;
  EXPECT_THROW(makeLiquidRivuletMesh(bad, 0.0f), InputError);
  bad = good;
  bad[2].along = Vec3::UnitZ();
  EXPECT_THROW(makeLiquidRivuletMesh(bad, 0.0f), InputError);
  bad = good;
  bad[0].contact.x() = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(makeLiquidRivuletMesh(bad, 0.0f), InputError);
  EXPECT_THROW(makeLiquidRivuletMesh(good, -3e-4f), InputError);  // the base below the whole section
  EXPECT_THROW(makeLiquidRivuletMesh(good, 0.0f, {1, 4, 4}), InputError);
  EXPECT_NO_THROW(makeLiquidRivuletMesh(good, -2e-5f));
}

}  // namespace liquid_rivulet_mesh_test
}  // namespace lacrima
