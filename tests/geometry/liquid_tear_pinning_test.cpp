// Skin that pins contact lines harder in places (LiquidPathSample::pinning, a factor on the
// retention force of a path piece): beads stop on such a patch and go on when they have grown, as
// tears on a face stop and start. Analytic planes, gravity -y.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "lacrima/base/error.hpp"
#include "lacrima/liquid/liquid_tear.hpp"

namespace lacrima {
namespace liquid_tear_pinning_test {

constexpr double kPiD = std::numbers::pi;
constexpr double kUl = kMicrolitre;
double deg(double degrees) { return degrees * kPiD / 180.0; }

// A plane tilted by `tilt` from the horizontal, sampled every 0.5 mm down its fall line; the
// pieces starting in [patchFrom, patchTo) pin by `factor`.
std::vector<LiquidPathSample> planeWithPatch(double tilt, double length, double patchFrom, double patchTo, double factor) {
  const Vec3d normal(0.0, std::cos(tilt), std::sin(tilt));
  const Vec3d down(0.0, -std::sin(tilt), std::cos(tilt));
  const double spacing = 5e-4;
  std::vector<LiquidPathSample> path;
  for (int i = 0; i <= int(std::lround(length / spacing)); ++i) {
    LiquidPathSample sample;
    sample.arcLength = i * spacing;
    sample.position = sample.arcLength * down;
    sample.normal = normal;
    if (sample.arcLength >= patchFrom - 1e-12 && sample.arcLength < patchTo - 1e-12) sample.pinning = factor;
    path.push_back(sample);
  }
  return path;
}

LiquidTearInput wallWithPatch(double patchFrom, double patchTo, double factor) {
  LiquidTearInput input;
  input.path = planeWithPatch(deg(90.0), 0.06, patchFrom, patchTo, factor);
  input.params.source.rate = 0.0;
  return input;
}

// Weight along the slope over the retention force (Furmidge 1962 / ElSherbini & Jacobi 2006) of a
// bead on dry skin of the tear's own contact angles: it slides where this is at least the pinning factor.
double driveOverRetention(const LiquidTearParams& p, double volume, double tilt) {
  const SlidingModel model{p.fluid, p.contactAngles, p.retentionFactor};
  return p.fluid.density * volume * p.fluid.gravity * std::sin(tilt) / retentionForce(model, volume);
}

TEST(LiquidTearPinning, TheCriterionAndTheSpeedUseThePatchFactorOnTheRetentionForce) {
  const double tilt = deg(60.0), factor = 1.7;
  LiquidTearInput input;
  input.path = planeWithPatch(tilt, 0.03, 0.01, 0.02, factor);
  input.params.source.rate = 0.0;
  const LiquidTearSimulation simulation(input);
  const LiquidTearParams& p = input.params;
  const SlidingModel held{p.fluid, p.contactAngles, p.retentionFactor * factor};
  // Volumes across both thresholds: on the patch exactly the criterion of a retention factor k p.
  int slideOff = 0, slideOn = 0;
  for (double volume = 1.0 * kUl; volume <= 40.0 * kUl; volume *= 1.1) {
    EXPECT_EQ(simulation.slidesAt(0.015, volume, tilt, 0.0), dropSlides(held, volume, tilt)) << volume;
    slideOff += simulation.slidesAt(0.005, volume, tilt, 0.0);
    slideOn += simulation.slidesAt(0.015, volume, tilt, 0.0);
    // de Gennes 1985 wedge balance with the patch's retention: v = theta_mean (F_drive - p F_ret) / (3 mu ln(L/a) w).
    const double drive = p.fluid.density * volume * p.fluid.gravity * std::sin(tilt);
    const double excess = drive - retentionForce(held, volume);
    const double thetaMean = 0.5 * (p.contactAngles.advancing + p.contactAngles.receding);
    const double expected = std::max(0.0, thetaMean * excess / (3.0 * p.viscosity * p.contactLineLogRatio *
                                                                 slidingBaseWidth(held, volume)));
    EXPECT_NEAR(simulation.terminalSpeedAt(0.015, volume, tilt, 0.0), expected, 1e-12) << volume;
  }
  // Fewer volumes slide on the patch, and some do on either side: the sweep crossed both thresholds.
  EXPECT_LT(slideOn, slideOff);
  EXPECT_GT(slideOn, 0);
  EXPECT_LT(slideOff, 30);
}

TEST(LiquidTearPinning, ABeadStopsOnAPatchThatHoldsHarderAndGoesOnWhenTheNextBeadMergesIntoIt) {
  // Down a wall, a patch from 20 to 25 mm holds 1.2 times harder than a 10 uL bead's weight can
  // pull: the first bead stops there. A second one, 1 s behind it, runs down its wet trail and
  // merges with it; at about twice the volume (weight over retention grows as V^(2/3)) the merged
  // bead goes on.
  const double volume = 10.0 * kUl, patchFrom = 0.02, patchTo = 0.025;
  const LiquidTearParams defaults;
  const double factor = 1.2 * driveOverRetention(defaults, volume, deg(90.0));
  std::printf("[ pinning ] weight over retention %.3f, patch factor %.3f\n", factor / 1.2, factor);
  ASSERT_GT(factor, 1.0);
  ASSERT_LT(factor, driveOverRetention(defaults, 1.8 * volume, deg(90.0)));
  LiquidTearInput input = wallWithPatch(patchFrom, patchTo, factor);
  input.params.source.rate = volume;  // one bead of 10 uL a second from the lid
  input.params.source.end = 1.5;
  input.params.source.overflowVolume = volume;
  input.params.source.spillVolume = volume;
  input.params.source.initialVolume = 0.999 * volume;  // the first bead leaves at once
  LiquidTearSimulation simulation(input);
  double stoppedAt = -1.0, wentOnAt = -1.0;
  while (simulation.time() < 6.0 && wentOnAt < 0.0) {
    simulation.step();
    ASSERT_LT(simulation.budget().relativeImbalance(), 1e-6) << simulation.time();
    ASSERT_FALSE(simulation.beads().empty());
    const Bead& first = simulation.beads().at(0);
    if (stoppedAt < 0.0 && first.phase == BeadPhase::Pinned && first.arcLength > 0.0) {
      stoppedAt = simulation.time();
      // It stopped as it entered the patch (within one step's travel at its last speed).
      EXPECT_GE(first.arcLength, patchFrom);
      EXPECT_LT(first.arcLength, patchFrom + 1e-3);
    }
    for (const Bead& bead : simulation.beads())
      if (bead.volume > 0.0 && bead.arcLength > patchTo + 0.005 && wentOnAt < 0.0) wentOnAt = simulation.time();
  }
  ASSERT_GT(stoppedAt, 0.0) << "the first bead never stopped";
  ASSERT_GT(wentOnAt, 0.0) << "no bead passed the patch";
  std::printf("[ pinning ] the first bead stopped at %.3f s; liquid passed the patch at %.3f s\n", stoppedAt, wentOnAt);
  // The second bead left the lid 1 s after the first: the first waited for it.
  EXPECT_GT(wentOnAt, 1.0);
  // It went on as the one bead the second merged into (a bead merges into the one ahead).
  ASSERT_EQ(simulation.beads().size(), 2u);
  EXPECT_EQ(simulation.beads()[0].phase, BeadPhase::Sliding);
  EXPECT_EQ(simulation.beads()[1].phase, BeadPhase::Merged);
  EXPECT_EQ(simulation.beads()[1].mergedInto, 0);
  // Without the patch the first bead is past it long before.
  LiquidTearInput single = wallWithPatch(patchFrom, patchTo, 1.0);
  single.params.initialBeads = {{0.0, volume}};
  LiquidTearSimulation free(single);
  while (free.time() < 1.0 && free.beads()[0].arcLength <= patchTo + 0.005) free.step();
  EXPECT_LT(free.time(), 0.5 * wentOnAt);
}

TEST(LiquidTearPinning, RejectsAFactorThatIsNotPositiveAndFinite) {
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    LiquidTearInput input = wallWithPatch(0.0, 0.06, 1.0);
    input.path[7].pinning = bad;
    try {
      LiquidTearSimulation simulation(input);
      FAIL() << "no error for " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("path sample 7 needs a finite pinning factor > 0"), std::string::npos) << e.what();
    }
  }
}

}  // namespace liquid_tear_pinning_test
}  // namespace lacrima
