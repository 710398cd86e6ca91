// Rivulets in shots: a liquid tear welling fast enough runs down the cheek as
// one closed water mesh lying just under the skin it wets, drawn with the volume the simulation
// holds; the shot's "rivulet" keys and their messages.
#include <gtest/gtest.h>

#include <limits>

#include "lacrima/mesh/closest_point_grid.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "liquid_tear_support.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace liquid_rivulet_shot_test {

using test::expectSingleError;
using test::ictFaceShot;
using test::writeShot;

// Wells from the right eye's inner corner at 10 uL/s; from 2 uL on the meniscus overflows, and as
// the rate is above formFlowRate it runs down as a rivulet.
const std::string kTear =
    R"("tears": [{"type": "liquid", "asset": "face", "part": "M_Face", "source": {"landmark": 39}, "material": "water",
       "rate": 10, "overflowVolume": 2, "spillVolume": 2, "rivulet": {"formFlowRate": 4}}])";
constexpr int kFrames = 48;

std::vector<const MeshInstance*> rivuletsOf(const Frame& frame) {
  std::vector<const MeshInstance*> rivulets;
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name == "liquid rivulet") rivulets.push_back(&m);
  return rivulets;
}

TEST(LiquidRivuletShot, ARivuletRunsDownTheCheekAsAClosedMeshJustUnderTheSkinItWets) {
  const Shot shot = loadShot(writeShot("rivulet_shot.json", ictFaceShot(kTear, "", "", kFrames)));
  const int f = 30;
  FrameBuilder builder(shot);
  const LiquidTearState state = builder.liquidTearStateAt(0, f);
  ASSERT_EQ(state.rivulets.size(), 1u);
  EXPECT_TRUE(state.beads.empty() || state.beads.back().phase == BeadPhase::Hanging);
  const Frame frame = builder.build(f);
  const auto rivulets = rivuletsOf(frame);
  ASSERT_EQ(rivulets.size(), 1u);
  const TriangleMesh& mesh = rivulets[0]->mesh;
  EXPECT_EQ(findMeshDefect(mesh), "");
  EXPECT_EQ(findWeldedClosedMeshDefect(mesh), "");
  EXPECT_EQ(rivulets[0]->materialId, uint32_t(shot.findMaterial("water")));
  // The drawn water holds the simulated rivulet's volume (a ruled sweep between cell centres, its
  // rounded ends, the 20 um under the skin and the bends of the cheek: within 15 %).
  EXPECT_NEAR(signedVolume(mesh) / state.rivulets[0].volume, 1.0, 0.15);
  const TriangleMesh& skin = test::skinOf(frame, shot);
  const ClosestPointGrid locator(skin);
  float lowest = std::numeric_limits<float>::infinity();
  for (const Vec3& v : mesh.positions) {
    const SurfacePoint nearest = locator.closest(v);
    lowest = std::min(lowest, (v - surfacePosition(skin, nearest)).dot(triangleNormal(skin, nearest.triangle)));
  }
  // 20 um under the skin at the stations; between them and on the rounded ends the sweep is
  // straight, so where the skin is concave (the lid margin) it runs a little deeper.
  EXPECT_GE(lowest, -6e-5f) << "a rivulet vertex lies " << -lowest << " m under the skin";
  EXPECT_LE(lowest, -1e-5f) << "the rivulet's base lies " << lowest << " m above the skin";
  // The skin under it is wet: the film (m) at its thickness.
  float wettest = 0.0f;
  for (const MeshInstance& m : frame.meshes)
    if (&m.mesh == &skin)
      for (float w : m.wetness) wettest = std::max(wettest, w);
  EXPECT_NEAR(wettest, float(shot.liquidTears[0].params.filmThickness), 1e-7f);
}

// A keyed rate ("rate": {"keys": ...}) reaches the simulation in seconds from its start and m^3/s:
// linear keys as they are, other interpolations as a polyline of 8 points a frame.
TEST(LiquidRivuletShot, AKeyedRateReachesTheSimulationInSIUnits) {
  const std::string linear = test::replaced(kTear, R"("rate": 10)", R"("wellStart": -23, "rate": {"keys": [[1, 10], [25, 2]], "interpolation": "linear"})");
  const Shot a = loadShot(writeShot("rivulet_rate_linear.json", ictFaceShot(linear, "", "", kFrames)));
  const WellingSource& source = a.liquidTears[0].params.source;
  ASSERT_EQ(source.rateKeys.size(), 2u);
  EXPECT_NEAR(source.rateKeys[0].first, 1.0, 1e-12);  // frame 1 is 1 s after the simulation's start, frame -23
  EXPECT_NEAR(source.rateKeys[0].second, 10.0 * kMicrolitre, 1e-18);
  EXPECT_NEAR(source.rateKeys[1].first, 2.0, 1e-12);
  EXPECT_NEAR(source.rateKeys[1].second, 2.0 * kMicrolitre, 1e-18);
  EXPECT_NEAR(source.rateAt(1.5), 6.0 * kMicrolitre, 1e-18);
  const std::string smooth = test::replaced(kTear, R"("rate": 10)", R"("rate": {"keys": [[1, 10], [25, 2]]})");
  const Shot b = loadShot(writeShot("rivulet_rate_smooth.json", ictFaceShot(smooth, "", "", kFrames)));
  const WellingSource& polyline = b.liquidTears[0].params.source;
  ASSERT_EQ(polyline.rateKeys.size(), size_t(24 * 8 + 1));
  EXPECT_NEAR(polyline.rateKeys.front().second, 10.0 * kMicrolitre, 1e-15);
  EXPECT_NEAR(polyline.rateKeys.back().first, 1.0, 1e-9);
  EXPECT_NEAR(polyline.rateKeys.back().second, 2.0 * kMicrolitre, 1e-15);
  EXPECT_EQ(b.liquidTears[0].input.params.source.rateKeys, polyline.rateKeys);  // what the simulation runs on
  // The whole simulation keeps its volume with a keyed rate.
  EXPECT_LT(liquidTearVolumeBudget(b.liquidTears[0].input, 2.0).relativeImbalance(), 1e-6);
}

TEST(LiquidRivuletShot, BadRivuletKeysGiveExactMessages) {
  auto expect = [](const std::string& name, const std::string& to, const std::string& message) {
    expectSingleError(name, ictFaceShot(test::replaced(kTear, R"("rivulet": {"formFlowRate": 4})", to), "", "", kFrames),
                      message);
  };
  expect("rv_break.json", R"("rivulet": {"formFlowRate": 4, "breakFlowRate": 5})",
         "/tears/0/rivulet/breakFlowRate: the rivulet breaks at 5 uL/s, above the 4 uL/s it forms at; it must not exceed "
         "formFlowRate");
  expect("rv_form.json", R"("rivulet": {"breakFlowRate": 1})",
         "/tears/0/rivulet: missing required key 'formFlowRate' (a number > 0)");
  expect("rv_zero.json", R"("rivulet": {"formFlowRate": 0})",
         "/tears/0/rivulet/formFlowRate: expected a number > 0, found 0");
  expect("rv_angle.json", R"("contactAngles": [110, 95], "rivulet": {"formFlowRate": 4})",
         "/tears/0/contactAngles: a rivulet needs a receding contact angle below 90 degrees, got 95 degrees");
  expectSingleError("rv_rate.json",
                    ictFaceShot(test::replaced(kTear, R"("rate": 10)", R"("rate": {"keys": [[1, 10], [25, -2]]})"), "", "",
                                kFrames),
                    "/tears/0/rate/keys/1/1: expected a number >= 0, found -2");
  expect("rv_typo.json", R"("rivulet": {"formFlowRate": 4, "brakeFlowRate": 1})",
         "/tears/0/rivulet/brakeFlowRate: unknown key 'brakeFlowRate'; did you mean 'breakFlowRate'?");
}

}  // namespace liquid_rivulet_shot_test
}  // namespace lacrima
