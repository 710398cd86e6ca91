// The liquid bead mesh: closed and outward, the spherical cap's volume on a flat skin, draped over
// convex and concave skin without dipping into it, long axis along the given direction.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "geometry/height_field_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/liquid/liquid_bead_mesh.hpp"

namespace lacrima {
namespace liquid_bead_mesh_test {

using test::heightFieldMesh;

LiquidBeadPlacement placement(float contactAngleDegrees) {
  LiquidBeadPlacement p;
  p.contact = Vec3::Zero();
  p.normal = Vec3::UnitZ();
  p.along = Vec3(0, -1, 0.3f);  // projected onto the plane: -y
  p.halfLength = 0.003f;
  p.halfWidth = 0.002f;
  p.height = 0.0015f;
  p.contactAngle = contactAngleDegrees * float(std::numbers::pi) / 180.0f;
  p.baseOffset = 2e-5f;
  return p;
}

// Volume of the unit-base cap of angle theta scaled to the placement's semi-axes and height.
double capVolume(const LiquidBeadPlacement& p) {
  const double theta = p.contactAngle, rho = 1.0 / std::sin(theta), eta = rho * (1.0 - std::cos(theta));
  const double unit = std::numbers::pi * std::pow(rho, 3) * std::pow(1.0 - std::cos(theta), 2) * (2.0 + std::cos(theta)) / 3.0;
  return unit * p.halfLength * p.halfWidth * p.height / eta;
}

TEST(LiquidBeadMesh, IsClosedOutwardAndHasTheCapVolumeOnAFlatSkin) {
  const TriangleMesh skin = heightFieldMesh(20, 0.01f, [](float, float) { return 0.0f; });
  for (float angle : {40.0f, 80.0f, 110.0f}) {
    const LiquidBeadPlacement p = placement(angle);
    const TriangleMesh bead = makeLiquidBeadMesh(skin, p, {24, 3, 64});
    EXPECT_EQ(bead.name, "liquid bead");
    EXPECT_EQ(findMeshDefect(bead), "");
    EXPECT_EQ(findWeldedClosedMeshDefect(bead), "");
    EXPECT_NEAR(signedVolume(bead), capVolume(p), 0.01 * capVolume(p)) << angle;
    float lowest = 1.0f, highest = -1.0f;
    for (const Vec3& v : bead.positions) {
      lowest = std::min(lowest, v.z());
      highest = std::max(highest, v.z());
    }
    EXPECT_NEAR(lowest, p.baseOffset, 1e-7f);
    EXPECT_NEAR(highest, p.baseOffset + p.height, 1e-7f);
    // Long axis along -y (the projection of `along`): the footprint is longer in y than in x.
    const Eigen::AlignedBox3f box = computeBounds(bead);
    EXPECT_GT(box.sizes().y(), 1.4f * box.sizes().x()) << angle;
  }
}

// The contact line is a sharp edge: its base copy's normals point into the skin, its dome copy's
// lean out by about the contact angle (shared vertices would average the two, and water refracts
// by its shading normal).
TEST(LiquidBeadMesh, DomeAndBaseKeepTheirOwnNormalsAlongTheContactLine) {
  const TriangleMesh skin = heightFieldMesh(20, 0.01f, [](float, float) { return 0.0f; });
  LiquidBeadPlacement p = placement(80.0f);
  p.halfLength = p.halfWidth = 0.002f;  // round, so the rim's angle is the contact angle all round
  p.height = 0.002f * (1.0f - std::cos(p.contactAngle)) / std::sin(p.contactAngle);
  const TriangleMesh bead = makeLiquidBeadMesh(skin, p, {48, 3, 64});
  int dome = 0, base = 0;
  for (size_t v = 0; v < bead.positions.size(); ++v) {
    if (std::abs(bead.positions[v].z() - p.baseOffset) > 1e-9f || bead.positions[v].head<2>().norm() < 0.0019f) continue;
    const Vec3& n = bead.normals[v];
    if (n.z() < -0.999f) {
      ++base;
    } else {
      ++dome;
      // The smooth normal averages the last ring of faces: within that ring's angle (80 / 48 degrees) and a bit.
      EXPECT_NEAR(std::acos(n.z()) * 180.0f / float(std::numbers::pi), 80.0f, 2.5f);
    }
  }
  EXPECT_EQ(dome, 64);
  EXPECT_EQ(base, 64);
}

TEST(LiquidBeadMesh, FollowsCurvedSkinWithoutDippingIntoIt) {
  for (float curvature : {-60.0f, 60.0f}) {  // 1/m: convex (cheek) and concave (a fold)
    auto height = [curvature](float x, float y) { return 0.5f * curvature * (x * x + y * y); };
    const TriangleMesh skin = heightFieldMesh(60, 0.01f, height);
    const LiquidBeadPlacement p = placement(80.0f);
    const TriangleMesh bead = makeLiquidBeadMesh(skin, p);
    EXPECT_EQ(findWeldedClosedMeshDefect(bead), "");
    EXPECT_GT(signedVolume(bead), 0.0);
    for (const Vec3& v : bead.positions) {
      // The skin's triangles are chords of the analytic surface: they sag below it by at most
      // curvature d^2 / 8 = 1.7e-6 m for the 0.47 mm cell diagonals here.
      EXPECT_GE(v.z() - height(v.x(), v.y()), p.baseOffset - 2e-6f) << curvature << " " << v.transpose();
    }
  }
}

// A negative offset sinks the base under the skin, so the skin under the bead is inside the water
// (the renderer then sees water in contact with skin, not an air gap under the bead).
TEST(LiquidBeadMesh, ANegativeOffsetSinksTheBaseJustUnderCurvedSkin) {
  for (float curvature : {-60.0f, 60.0f}) {
    auto height = [curvature](float x, float y) { return 0.5f * curvature * (x * x + y * y); };
    const TriangleMesh skin = heightFieldMesh(60, 0.01f, height);
    LiquidBeadPlacement p = placement(80.0f);
    p.baseOffset = -2e-5f;
    const TriangleMesh bead = makeLiquidBeadMesh(skin, p);
    EXPECT_EQ(findWeldedClosedMeshDefect(bead), "");
    EXPECT_GT(signedVolume(bead), 0.0);
    int under = 0;
    for (const Vec3& v : bead.positions) {
      const float aboveSkin = v.z() - height(v.x(), v.y());
      // Chords sag by at most 1.7e-6 m (as above): no vertex deeper than the offset, and the
      // base's vertices (the flat side) all under the skin.
      EXPECT_GE(aboveSkin, p.baseOffset - 2e-6f) << curvature << " " << v.transpose();
      if (aboveSkin < 0.0f) {
        EXPECT_NEAR(aboveSkin, p.baseOffset, 2e-6f) << curvature << " " << v.transpose();
        ++under;
      }
    }
    EXPECT_GT(under, int(bead.positions.size()) / 4) << curvature;  // the base rings and the rim
  }
}

TEST(LiquidBeadMesh, RejectsBadPlacements) {
  const TriangleMesh skin = heightFieldMesh(2, 0.01f, [](float, float) { return 0.0f; });
  LiquidBeadPlacement p = placement(80.0f);
  p.height = 0.0f;
  EXPECT_THROW(makeLiquidBeadMesh(skin, p), InputError);
  p = placement(80.0f);
  p.along = Vec3::UnitZ();
  EXPECT_THROW(makeLiquidBeadMesh(skin, p), InputError);
  p = placement(180.0f);
  EXPECT_THROW(makeLiquidBeadMesh(skin, p), InputError);
  p = placement(80.0f);
  p.baseOffset = -p.height;  // the whole bead under the skin
  EXPECT_THROW(makeLiquidBeadMesh(skin, p), InputError);
  p.baseOffset = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(makeLiquidBeadMesh(skin, p), InputError);
}

}  // namespace liquid_bead_mesh_test
}  // namespace lacrima
