// Skin that pins a liquid tear's contact line harder in some patches and softer in others
// ("pinning": beads stop and start): the course's samples carry the factor of the skin
// under them, a tear on such skin stops where a tear on uniform skin runs on, a frame alone equals
// it in a sequence, and bad values get exact messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "liquid_tear_support.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace liquid_tear_pinning_shot_test {

using test::beadsOf;
using test::expectSingleError;
using test::ictFaceShot;
using test::writeShot;

constexpr int kFrames = 72;

// As in liquid_tear_shot_test.cpp: wells from the right eye's inner corner (landmark 39), overflows
// at frame 25 and sends 8 uL down the cheek; `extra` adds members to the tear.
std::string tearWith(const std::string& extra) {
  return R"("tears": [{"type": "liquid", "asset": "face", "part": "M_Face", "source": {"landmark": 39}, "material": "water",
       "rate": 10, "overflowVolume": 10, "spillVolume": 8)" +
         (extra.empty() ? "" : ", " + extra) + "}]";
}

const std::string kPatchySkin = R"("pinning": {"factor": 2, "patchSize": 0.004})";

Shot loadTearShot(const std::string& name, const std::string& extra) {
  return loadShot(writeShot(name, ictFaceShot(tearWith(extra), "", "", kFrames)));
}

// The arc length the tear's liquid has reached at each frame from the overflow on (the furthest bead).
std::vector<double> frontByFrame(const Shot& shot) {
  std::vector<double> front;
  const std::shared_ptr<const LiquidTearCourses> courses = liquidTearCoursesOf(shot, shot.liquidTears[0]);
  LiquidTearRun run(shot, shot.liquidTears[0], *courses);
  for (int f = 25; f <= kFrames; ++f) {
    run.advanceTo(f);
    double furthest = 0.0;
    for (const BeadView& bead : run.state(f).beads) furthest = std::max(furthest, bead.arcLength);
    front.push_back(furthest);
  }
  return front;
}

TEST(LiquidTearPinningShot, SamplesCarryTheFactorOfTheSkinUnderThem) {
  const Shot shot = loadTearShot("pinning_read.json", kPatchySkin);
  const ShotLiquidTear& tear = shot.liquidTears[0];
  EXPECT_EQ(tear.pinningFactor, 2.0);
  EXPECT_EQ(tear.pinningPatchSize, 0.004);
  ASSERT_FALSE(tear.pinning.empty());
  const auto [low, high] = std::minmax_element(tear.pinning.begin(), tear.pinning.end());
  EXPECT_GE(*low, 0.5f - 1e-6f);
  EXPECT_LE(*high, 2.0f + 1e-5f);
  // The factor under each sample is the skin's, interpolated at the sample's point on the path.
  FrameBuilder builder(shot);
  const std::shared_ptr<const LiquidTearCourse> course = builder.liquidTearCourseAt(0, shot.frameStart);
  const TriangleMesh skin = tear.surface->at(course->frame).skin;
  double fewest = 1e9, most = 0.0;
  for (size_t i = 0; i < course->samples.size(); ++i) {
    const SurfacePoint& point = course->path.points[i];
    double expected = 0.0;
    for (int k = 0; k < 3; ++k) expected += double(point.barycentric[k]) * tear.pinning[skin.indices[3 * point.triangle + k]];
    EXPECT_NEAR(course->samples[i].pinning, expected, 1e-12) << i;
    fewest = std::min(fewest, course->samples[i].pinning);
    most = std::max(most, course->samples[i].pinning);
  }
  // 4 mm patches along a path of several centimetres: the course crosses both kinds.
  std::printf("[ pinning ] factors along the course: %.2f to %.2f over %zu samples\n", fewest, most, course->samples.size());
  EXPECT_LT(fewest, 0.7);
  EXPECT_GT(most, 1.5);
}

TEST(LiquidTearPinningShot, ATearOnPatchySkinWaitsWhereOneOnUniformSkinRunsOn) {
  const std::vector<double> uniform = frontByFrame(loadTearShot("pinning_none.json", ""));
  const std::vector<double> patchy = frontByFrame(loadTearShot("pinning_patchy.json", kPatchySkin));
  // The first frame at which the liquid is 5 cm down the cheek (frames from 25 on).
  const auto frameAt5cm = [](const std::vector<double>& front) {
    for (size_t i = 0; i < front.size(); ++i)
      if (front[i] >= 0.05) return int(i) + 25;
    return 1000;
  };
  std::printf("[ pinning ] 5 cm down the cheek at frame %d on uniform skin, %d on patchy skin\n", frameAt5cm(uniform),
              frameAt5cm(patchy));
  // Here the source lies on a firm patch: the overflowing beads wait at the lid until two more
  // have merged into them (about 20 frames more), then run.
  EXPECT_GE(frameAt5cm(patchy), frameAt5cm(uniform) + 10);
  EXPECT_LE(frameAt5cm(patchy), kFrames);
}

TEST(LiquidTearPinningShot, AFrameAloneEqualsTheSameFrameInASequence) {
  const Shot shot = loadTearShot("pinning_alone.json", kPatchySkin);
  const Frame alone = buildFrame(shot, 66);
  FrameBuilder sequence(shot);
  for (int f : {30, 50, 64}) sequence.build(f);
  const Frame inSequence = sequence.build(66);
  const auto a = beadsOf(alone), b = beadsOf(inSequence);
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i]->mesh.positions, b[i]->mesh.positions);
}

TEST(LiquidTearPinningShot, BadValuesGiveExactMessages) {
  auto expect = [](const std::string& name, const std::string& pinning, const std::string& message) {
    expectSingleError(name, ictFaceShot(tearWith(R"("pinning": )" + pinning), "", "", kFrames), message);
  };
  expect("pn_factor.json", R"({"factor": 0.5})", "/tears/0/pinning/factor: expected a number >= 1, found 0.5");
  expect("pn_missing.json", R"({"patchSize": 0.004})", "/tears/0/pinning: missing required key 'factor' (a number >= 1)");
  expect("pn_size.json", R"({"factor": 2, "patchSize": 0})", "/tears/0/pinning/patchSize: expected a number > 0, found 0");
  expect("pn_object.json", "2", "/tears/0/pinning: expected an object, found 2");
}

}  // namespace liquid_tear_pinning_shot_test
}  // namespace lacrima
