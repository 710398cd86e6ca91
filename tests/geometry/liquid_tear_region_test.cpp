// Contact angles per skin region for liquid tears (water meets skin at 55-110 degrees, varying over the face): path
// pieces naming a region (LiquidPathSample::contactAngleRegion) use its angles for the sliding
// criterion, the bead's shape and the width of the trail it lays. Analytic planes, gravity -y.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lacrima/base/error.hpp"
#include "lacrima/liquid/liquid_tear.hpp"

namespace lacrima {
namespace liquid_tear_region_test {

constexpr double kPiD = std::numbers::pi;
constexpr double kUl = kMicrolitre;
double deg(double degrees) { return degrees * kPiD / 180.0; }

// A plane tilted by `tilt` from the horizontal, sampled every 0.5 mm down its fall line; the
// pieces from `regionFrom` on name region 0.
std::vector<LiquidPathSample> planePathWithRegion(double tilt, double length, double regionFrom) {
  const Vec3d normal(0.0, std::cos(tilt), std::sin(tilt));
  const Vec3d down(0.0, -std::sin(tilt), std::cos(tilt));
  const double spacing = 5e-4;
  std::vector<LiquidPathSample> path;
  for (int i = 0; i <= int(std::lround(length / spacing)); ++i) {
    LiquidPathSample sample;
    sample.arcLength = i * spacing;
    sample.position = sample.arcLength * down;
    sample.normal = normal;
    sample.contactAngleRegion = sample.arcLength >= regionFrom - 1e-12 ? 0 : -1;
    path.push_back(sample);
  }
  return path;
}

LiquidTearInput regionInput(double tilt, double length, double regionFrom, ContactAngleHysteresis tear,
                            ContactAngleHysteresis region) {
  LiquidTearInput input;
  input.path = planePathWithRegion(tilt, length, regionFrom);
  input.params.source.rate = 0.0;
  input.params.contactAngles = tear;
  input.params.contactAngleRegions = {region};
  return input;
}

SlidingModel modelWith(const LiquidTearParams& p, const ContactAngleHysteresis& angles) {
  return SlidingModel{p.fluid, angles, p.retentionFactor};
}

double meanAngle(const ContactAngleHysteresis& angles) { return 0.5 * (angles.advancing + angles.receding); }

TEST(LiquidTearRegion, ABeadSlidingOnOilySkinPinsWhereItEntersARegionOfLargerHysteresis) {
  // Oily skin 65/55 degrees, clean dry skin from 10 mm on 100/60 (ARCHITECTURE.md "Physics of tears").
  const ContactAngleHysteresis oily{deg(65.0), deg(55.0)}, dry{deg(100.0), deg(60.0)};
  const double volume = 10.0 * kUl, border = 0.01;
  const LiquidTearParams defaults;
  const double slideTilt = *criticalTiltAngle(modelWith(defaults, oily), volume);
  const double pinTilt = *criticalTiltAngle(modelWith(defaults, dry), volume);
  ASSERT_LT(slideTilt, pinTilt);
  const double tilt = 0.5 * (slideTilt + pinTilt);
  LiquidTearInput input = regionInput(tilt, 0.03, border, oily, dry);
  input.params.initialBeads = {{0.005, volume}};
  LiquidTearSimulation simulation(input);

  BeadView before;  // the bead's last view on the oily skin
  bool slid = false;
  double fastest = 0.0;  // the speed it moved at in any step
  for (int step = 0; step < 5000 && !(slid && simulation.beads()[0].phase == BeadPhase::Pinned); ++step) {
    const BeadView view = simulation.state(simulation.time()).beads.at(0);
    if (view.arcLength < border) before = view;
    simulation.step();
    slid = slid || simulation.beads()[0].phase == BeadPhase::Sliding;
    fastest = std::max(fastest, simulation.beads()[0].speed);
    ASSERT_LT(simulation.budget().relativeImbalance(), 1e-6) << step;
  }
  const Bead& bead = simulation.beads()[0];
  ASSERT_TRUE(slid);
  ASSERT_EQ(bead.phase, BeadPhase::Pinned);
  // It pins in the step after its centre crossed the border, within one step's travel of it.
  EXPECT_GE(bead.arcLength, border);
  EXPECT_LT(bead.arcLength, border + fastest * input.params.timeStep + 1e-12);
  // Furmidge 1962 exactly: at the volume it arrived with it would slide on the oily skin, not on the dry.
  EXPECT_TRUE(dropSlides(modelWith(input.params, oily), bead.volume, tilt));
  EXPECT_FALSE(dropSlides(modelWith(input.params, dry), bead.volume, tilt));
  EXPECT_TRUE(simulation.slides(bead.volume, tilt, 0.0));
  EXPECT_FALSE(simulation.slidesAt(bead.arcLength, bead.volume, tilt, 0.0));
  EXPECT_EQ(simulation.contactAnglesAt(bead.arcLength).advancing, dry.advancing);
  EXPECT_EQ(simulation.contactAnglesAt(border - 1e-4).advancing, oily.advancing);

  // Its shape is the cap at the local mean angle: taller and narrower on the dry skin.
  const BeadView after = simulation.state(simulation.time()).beads.at(0);
  EXPECT_EQ(before.contactAngle, meanAngle(oily));
  EXPECT_EQ(after.contactAngle, meanAngle(dry));
  const BeadShape expected = beadShape(input.params.fluid, after.volume, meanAngle(dry), tilt);
  EXPECT_EQ(after.shape.height, expected.height);
  EXPECT_EQ(after.shape.halfWidth, expected.halfWidth);
  EXPECT_GT(after.shape.height, 1.2 * before.shape.height);
  EXPECT_LT(after.shape.halfWidth, 0.95 * before.shape.halfWidth);

  // It stays pinned there.
  simulation.advanceTo(simulation.time() + 0.5);
  EXPECT_EQ(simulation.beads()[0].phase, BeadPhase::Pinned);
  EXPECT_LT(simulation.budget().relativeImbalance(), 1e-6);
}

TEST(LiquidTearRegion, TheTrailFollowsTheLocalBaseWidthAndTheVolumeStillBalances) {
  // Down a wall: dry skin 100/60 to 20 mm, then oily skin 65/55, whose flatter cap is wider.
  const ContactAngleHysteresis dry{deg(100.0), deg(60.0)}, oily{deg(65.0), deg(55.0)};
  const double volume = 10.0 * kUl, border = 0.02;
  LiquidTearInput input = regionInput(deg(90.0), 0.06, border, dry, oily);
  input.params.initialBeads = {{0.005, volume}};
  LiquidTearSimulation simulation(input);
  while (simulation.beads()[0].arcLength < 0.04 && simulation.time() < 20.0) {
    simulation.step();
    ASSERT_LT(simulation.budget().relativeImbalance(), 1e-6) << simulation.time();
  }
  ASSERT_GE(simulation.beads()[0].arcLength, 0.04);
  const double remaining = simulation.beads()[0].volume;
  ASSERT_LT(remaining, volume);
  // w = c_w V^(1/3) with the c_w of each side, for a volume between the one left and the first.
  const auto widthRange = [&](const ContactAngleHysteresis& angles) {
    const double perCubeRoot = slidingBaseWidth(modelWith(input.params, angles), kUl) / std::cbrt(kUl);
    return std::pair{perCubeRoot * std::cbrt(remaining), perCubeRoot * std::cbrt(volume)};
  };
  const auto [dryLow, dryHigh] = widthRange(dry);
  const auto [oilyLow, oilyHigh] = widthRange(oily);
  ASSERT_LT(dryHigh, oilyLow);  // the two sides' widths cannot be told apart otherwise
  for (double s : {0.010, 0.015}) {
    EXPECT_GE(simulation.filmWidthAt(s), dryLow) << s;
    EXPECT_LE(simulation.filmWidthAt(s), dryHigh) << s;
  }
  for (double s : {0.025, 0.030}) {
    EXPECT_GE(simulation.filmWidthAt(s), oilyLow) << s;
    EXPECT_LE(simulation.filmWidthAt(s), oilyHigh) << s;
  }
}

TEST(LiquidTearRegion, RegionsWithTheTearsOwnAnglesChangeNothingBitwise) {
  const ContactAngleHysteresis angles = LiquidTearParams().contactAngles;
  LiquidTearInput plain = regionInput(deg(70.0), 0.05, 1e30, angles, angles);
  plain.params.contactAngleRegions.clear();
  plain.params.source.rate = 10.0 * kUl;
  LiquidTearInput regioned = regionInput(deg(70.0), 0.05, 0.02, angles, angles);
  regioned.params.source.rate = 10.0 * kUl;
  const LiquidTearState a = simulateLiquidTear(plain, 3.0);
  const LiquidTearState b = simulateLiquidTear(regioned, 3.0);
  ASSERT_FALSE(a.beads.empty());
  ASSERT_EQ(a.beads.size(), b.beads.size());
  for (size_t i = 0; i < a.beads.size(); ++i) {
    EXPECT_EQ(a.beads[i].arcLength, b.beads[i].arcLength) << i;
    EXPECT_EQ(a.beads[i].volume, b.beads[i].volume) << i;
    EXPECT_EQ(a.beads[i].shape.height, b.beads[i].shape.height) << i;
  }
  EXPECT_EQ(a.sampleFilmThickness, b.sampleFilmThickness);
}

TEST(LiquidTearRegion, ASampleNamingAMissingRegionIsRejected) {
  const ContactAngleHysteresis angles{deg(80.0), deg(60.0)};
  LiquidTearInput input = regionInput(deg(60.0), 0.01, 0.005, angles, angles);
  input.params.contactAngleRegions.clear();
  try {
    LiquidTearSimulation simulation(input);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "liquid tear: path sample 10 names contact angle region 0, there are 0");
  }
}

}  // namespace liquid_tear_region_test
}  // namespace lacrima
