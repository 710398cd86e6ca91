// Rivulets in shots (issue 16, item 2): a liquid tear welling fast enough runs down the cheek as
// one closed water mesh lying just under the skin it wets, drawn with the volume the simulation
// holds; the shot's "rivulet" keys and their messages.
#include <gtest/gtest.h>

#include <limits>

#include "lacrima/geometry/closest_point_grid.hpp"
#include "lacrima/geometry/surface_point.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "liquid_tear_test_support.hpp"
#include "shot_test_support.hpp"

namespace lacrima {
namespace {

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
  const TearLiquidState state = liquidTearStateAt(shot, shot.liquidTears[0], f);
  ASSERT_EQ(state.rivulets.size(), 1u);
  EXPECT_TRUE(state.beads.empty() || state.beads.back().phase == BeadPhase::Hanging);
  const Frame frame = buildFrame(shot, f);
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
  expect("rv_typo.json", R"("rivulet": {"formFlowRate": 4, "brakeFlowRate": 1})",
         "/tears/0/rivulet/brakeFlowRate: unknown key 'brakeFlowRate'; did you mean 'breakFlowRate'?");
}

}  // namespace
}  // namespace lacrima
