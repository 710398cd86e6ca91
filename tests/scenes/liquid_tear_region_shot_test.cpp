// Contact angles per skin region for liquid tears in shots ("contactAngleRegions"): the
// course's samples near a region's centre carry its angles, the bead meshes there are drawn at its
// mean angle (measured on the mesh), a frame alone equals it in a sequence, and bad regions get
// exact messages.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lacrima/mesh/surface_point.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "liquid_tear_support.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace liquid_tear_region_shot_test {

using test::expectSingleError;
using test::ictFaceShot;
using test::writeShot;

constexpr double kPiD = std::numbers::pi;
constexpr int kFrames = 72;

// As in liquid_tear_shot_test.cpp: wells from the right eye's inner corner (landmark 39), overflows
// at frame 25 and sends 8 uL down the cheek; `extra` adds members to the tear.
std::string tearWith(const std::string& extra) {
  return R"("tears": [{"type": "liquid", "asset": "face", "part": "M_Face", "source": {"landmark": 39}, "material": "water",
       "rate": 10, "overflowVolume": 10, "spillVolume": 8)" +
         (extra.empty() ? "" : ", " + extra) + "}]";
}

// Oily skin (65/55 degrees) within 2 cm of the source; the tear's own angles are the defaults (95/65).
const std::string kOilyAroundTheSource =
    R"("contactAngleRegions": [{"center": {"landmark": 39}, "radius": 0.02, "contactAngles": [65, 55]}])";

Shot loadTearShot(const std::string& name, const std::string& extra) {
  return loadShot(writeShot(name, ictFaceShot(tearWith(extra), "", "", kFrames)));
}

using test::beadsOf;
using test::skinOf;

// The bead mesh's default tessellation (LiquidBeadResolution {10, 3, 32}): the apex, then dome
// rings 1..10 of 32 vertices (ring 10 is the contact line), then the base.
constexpr int kSegments = 32, kDomeRings = 10;
uint32_t ringVertex(int ring, int segment) { return uint32_t(1 + (ring - 1) * kSegments + segment); }

// The angle (radians) the dome makes with the skin at the contact line across the bead (segments
// at phi = 90 and 270 degrees, averaged): the chord from the contact line to the dome ring above,
// its rise the difference of the two vertices' signed heights over the skin and its run the distance
// between their feet on the skin (so the skin's own curvature under the bead drops out).
double rimAngle(const TriangleMesh& bead, const TriangleMesh& skin) {
  double sum = 0.0;
  for (int segment : {kSegments / 4, 3 * kSegments / 4}) {
    const Vec3 rim = bead.positions[ringVertex(kDomeRings, segment)];
    const Vec3 above = bead.positions[ringVertex(kDomeRings - 1, segment)];
    const SurfacePoint rimFoot = closestSurfacePoint(skin, rim), aboveFoot = closestSurfacePoint(skin, above);
    // Signed heights: the rim lies just under the skin (the bead wets it, liquid_tear_frame.hpp).
    const auto heightOver = [&skin](const Vec3& p, const SurfacePoint& foot) {
      return double((p - surfacePosition(skin, foot)).dot(triangleNormal(skin, foot.triangle)));
    };
    const double rise = heightOver(above, aboveFoot) - heightOver(rim, rimFoot);
    const double run = (surfacePosition(skin, aboveFoot) - surfacePosition(skin, rimFoot)).norm();
    sum += std::atan2(rise, run);
  }
  return 0.5 * sum;
}

// The same chord's angle for the cap the bead is drawn as, on a flat skin: ring 9 is at psi =
// 0.9 theta on the unit cap (radius rho sin(psi), height rho (cos(psi) - cos(theta))), scaled to
// halfWidth across and to the bead's height.
double expectedRimAngle(const BeadView& bead) {
  const double theta = bead.contactAngle, rho = 1.0 / std::sin(theta);
  const double psi = 0.9 * theta, apexHeight = rho * (1.0 - std::cos(theta));
  const double inwards = bead.shape.halfWidth * (1.0 - rho * std::sin(psi));
  const double up = bead.shape.height * rho * (std::cos(psi) - std::cos(theta)) / apexHeight;
  return std::atan2(up, inwards);
}

TEST(LiquidTearRegionShot, SamplesNearTheRegionsCentreCarryItsAngles) {
  const Shot shot = loadTearShot("region_read.json", kOilyAroundTheSource);
  const ShotLiquidTear& tear = shot.liquidTears[0];
  ASSERT_EQ(tear.contactAngleRegions.size(), 1u);
  EXPECT_EQ(tear.contactAngleRegions[0].radius, 0.02);
  ASSERT_EQ(tear.params.contactAngleRegions.size(), 1u);
  EXPECT_NEAR(tear.params.contactAngleRegions[0].advancing, 65.0 * kPiD / 180.0, 1e-12);
  EXPECT_NEAR(tear.params.contactAngleRegions[0].receding, 55.0 * kPiD / 180.0, 1e-12);
  const Vec3d centre = tear.input.path.front().position;  // the source is the region's centre
  int inside = 0, outside = 0;
  for (const LiquidPathSample& sample : tear.input.path) {
    const bool near = (sample.position - centre).norm() <= 0.02 - 1e-6;
    const bool far = (sample.position - centre).norm() > 0.02 + 1e-6;
    if (near) {
      EXPECT_EQ(sample.contactAngleRegion, 0) << sample.arcLength;
    }
    if (far) {
      EXPECT_EQ(sample.contactAngleRegion, -1) << sample.arcLength;
    }
    inside += near;
    outside += far;
  }
  EXPECT_GT(inside, 3);
  EXPECT_GT(outside, 3);
}

TEST(LiquidTearRegionShot, BeadMeshesInTheRegionAreDrawnAtItsContactAngle) {
  const Shot plain = loadTearShot("region_none.json", "");
  const Shot oily = loadTearShot("region_oily.json", kOilyAroundTheSource);
  double rims[2] = {0.0, 0.0};
  int k = 0;
  for (const Shot* shot : {&plain, &oily}) {
    // Frame 26: the first bead, a frame after the overflow; on the oily skin it already slides (6 mm
    // down), on the tear's own angles it is still pinned at the source.
    const int f = 26;
    FrameBuilder builder(*shot);
    const LiquidTearState state = builder.liquidTearStateAt(0, f);
    const Frame frame = builder.build(f);
    const auto beads = beadsOf(frame);
    ASSERT_EQ(state.beads.size(), 1u);
    ASSERT_EQ(beads.size(), 1u);
    // Apex, dome rings, the contact ring's copy for the base, two inner base rings, base centre.
    ASSERT_EQ(beads[0]->mesh.positions.size(), size_t(1 + (kDomeRings + 3) * kSegments + 1));
    const ContactAngleHysteresis& angles =
        shot == &oily ? shot->liquidTears[0].params.contactAngleRegions[0] : shot->liquidTears[0].params.contactAngles;
    EXPECT_EQ(state.beads[0].contactAngle, 0.5 * (angles.advancing + angles.receding));
    rims[k] = rimAngle(beads[0]->mesh, skinOf(frame, *shot));
    std::printf("[ region ] %s: bead at %.4f m, mean contact angle %.1f deg, mesh rim angle %.2f deg (cap chord %.2f deg)\n",
                k == 0 ? "no region" : "oily region", state.beads[0].arcLength, state.beads[0].contactAngle * 180.0 / kPiD, rims[k] * 180.0 / kPiD,
                expectedRimAngle(state.beads[0]) * 180.0 / kPiD);
    EXPECT_NEAR(rims[k], expectedRimAngle(state.beads[0]), 2.0 * kPiD / 180.0);
    ++k;
  }
  EXPECT_GT(rims[0] - rims[1], 8.0 * kPiD / 180.0);  // 80 degrees mean against 60
}

TEST(LiquidTearRegionShot, AFrameAloneEqualsTheSameFrameInASequence) {
  const Shot shot = loadTearShot("region_alone.json", kOilyAroundTheSource);
  const Frame alone = buildFrame(shot, 40);
  FrameBuilder sequence(shot);
  for (int f : {10, 30, 50}) sequence.build(f);
  const Frame inSequence = sequence.build(40);
  const auto a = beadsOf(alone), b = beadsOf(inSequence);
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i]->mesh.positions, b[i]->mesh.positions);
    EXPECT_EQ(a[i]->mesh.normals, b[i]->mesh.normals);
  }
}

TEST(LiquidTearRegionShot, BadRegionsGiveExactMessages) {
  auto expect = [](const std::string& name, const std::string& regions, const std::string& message) {
    expectSingleError(name, ictFaceShot(tearWith(R"("contactAngleRegions": )" + regions), "", "", kFrames), message);
  };
  expect("rg_radius.json", R"([{"center": {"landmark": 39}, "contactAngles": [70, 60]}])",
         "/tears/0/contactAngleRegions/0: missing required key 'radius' (a number > 0)");
  expect("rg_negative.json", R"([{"center": {"landmark": 39}, "radius": -0.01, "contactAngles": [70, 60]}])",
         "/tears/0/contactAngleRegions/0/radius: expected a number > 0, found -0.01");
  expect("rg_range.json", R"([{"center": {"landmark": 39}, "radius": 0.01, "contactAngles": [70, 0]}])",
         "/tears/0/contactAngleRegions/0/contactAngles/1: expected a number in (0, 180), found 0");
  expect("rg_order.json", R"([{"center": {"landmark": 39}, "radius": 0.01, "contactAngles": [60, 70]}])",
         "/tears/0/contactAngleRegions/0/contactAngles: the receding angle (70 degrees) must not exceed the advancing "
         "angle (60 degrees)");
  expect("rg_landmark.json",
         R"([{"center": {"landmark": 39}, "radius": 0.01, "contactAngles": [70, 60]},
             {"center": {"landmark": 999}, "radius": 0.01, "contactAngles": [70, 60]}])",
         "/tears/0/contactAngleRegions/1/center/landmark: expected an integer in [0, 67], found 999");
  expect("rg_angles.json", R"([{"center": {"landmark": 39}, "radius": 0.01}])",
         "/tears/0/contactAngleRegions/0: missing required key 'contactAngles' ([advancing, receding] in degrees)");
  expect("rg_array.json", R"({"center": {"landmark": 39}})",
         "/tears/0/contactAngleRegions: expected an array of regions {\"center\", \"radius\", \"contactAngles\"}, found "
         "an object");
}

}  // namespace liquid_tear_region_shot_test
}  // namespace lacrima
