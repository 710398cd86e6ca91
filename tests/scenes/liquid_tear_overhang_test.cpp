// A liquid tear's "overhangAngle" (docs/shot-format.md "Liquid tears"): how far from straight
// down the skin's normal may be where a bead hangs and drips; its conversion, its effect on where
// the beads hang, and the exact message for a bad value.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace liquid_tear_overhang_test {

// Wells from the right eye's inner corner since 2 s before the shot; the path runs beside the
// nose and turns under it, where the beads hang.
const std::string kTear =
    R"("tears": [{"type": "liquid", "asset": "face", "part": "M_Face", "source": {"landmark": 39}, "material": "water",
       "rate": 10, "wellStart": -47, "overflowVolume": 10, "spillVolume": 8, "maxLength": 0.15}])";
constexpr int kFrames = 48;

Shot loadTearShot(const std::string& name, const std::string& extra) {
  return loadShot(test::writeShot(name, test::ictFaceShot(test::replaced(kTear, R"("maxLength": 0.15)",
                                                                         R"("maxLength": 0.15)" + extra),
                                                          "", "", kFrames)));
}

// The first hanging bead of the shot (frame by frame), or none.
std::optional<BeadView> firstHangingBead(const Shot& shot) {
  FrameBuilder builder(shot);
  for (int f = 1; f <= kFrames; ++f)
    for (const BeadView& bead : builder.liquidTearStateAt(0, f).beads)
      if (bead.phase == BeadPhase::Hanging) return bead;
  return std::nullopt;
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

TEST(LiquidTearOverhang, AngleSetsTheDripSiteCosine) {
  EXPECT_DOUBLE_EQ(loadTearShot("overhang_default.json", "").liquidTears[0].params.overhangCosine, 0.5);
  EXPECT_NEAR(loadTearShot("overhang_30.json", R"(, "overhangAngle": 30)").liquidTears[0].params.overhangCosine,
              std::sqrt(3.0) / 2.0, 1e-12);
}

TEST(LiquidTearOverhang, ASmallerAngleHangsTheBeadsWhereTheSkinFacesFurtherDown) {
  const auto wide = firstHangingBead(loadTearShot("overhang_wide.json", ""));
  const auto steep = firstHangingBead(loadTearShot("overhang_steep.json", R"(, "overhangAngle": 30)"));
  ASSERT_TRUE(wide && steep);
  // tilt is the skin's angle from the horizontal: 180 degrees under a ceiling.
  EXPECT_GE(degrees(wide->tilt), 180.0 - 60.0 - 1.0);
  EXPECT_LT(degrees(wide->tilt), 180.0 - 30.0);
  EXPECT_GE(degrees(steep->tilt), 180.0 - 30.0 - 1.0);
  EXPECT_GT(steep->arcLength, wide->arcLength + 0.001);
}

TEST(LiquidTearOverhang, BadAngleGivesAnExactMessage) {
  test::expectSingleError("overhang_bad.json",
                          test::ictFaceShot(test::replaced(kTear, R"("maxLength": 0.15)",
                                                           R"("maxLength": 0.15, "overhangAngle": 0)"),
                                            "", "", kFrames),
                          "/tears/0/overhangAngle: expected a number in (0, 180), found 0");
}

}  // namespace liquid_tear_overhang_test
}  // namespace lacrima
