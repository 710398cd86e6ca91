// Rivulets: Duffy & Moffatt 1995's small-width rivulet law against its own
// lubrication integral, and the tear simulation's rivulet: it carries the welling rate at the
// law's width, its front runs at the kinematic shock speed, it swallows beads, drains and breaks
// into beads when the welling stops, and keeps the volume to 1e-6 throughout.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "lacrima/base/error.hpp"
#include "lacrima/liquid/rivulet.hpp"
#include "lacrima/liquid/liquid_tear.hpp"

namespace lacrima {
namespace rivulet_test {

constexpr double kPiD = std::numbers::pi;
constexpr double kUl = kMicrolitre;
double deg(double degrees) { return degrees * kPiD / 180.0; }

RivuletFlow wallFlow(double contactAngleDegrees = 65.0) {
  RivuletFlow flow;
  flow.contactAngle = deg(contactAngleDegrees);
  flow.slope = deg(90.0);
  return flow;
}

TEST(RivuletLaw, FluxIsTheLubricationFluxIntegratedAcrossTheParabolicProfile) {
  for (double angle : {20.0, 45.0, 65.0, 80.0})
    for (double slope : {30.0, 90.0}) {
      RivuletFlow flow = wallFlow(angle);
      flow.slope = deg(slope);
      const double a = 2.5e-4;
      // q(y) = rho g sin(alpha) h(y)^3 / (3 mu), midpoint rule over 20,000 strips.
      const int strips = 20000;
      double flux = 0.0, area = 0.0;
      for (int i = 0; i < strips; ++i) {
        const double y = -a + (i + 0.5) * 2.0 * a / strips;
        const double h = std::tan(flow.contactAngle) * (a * a - y * y) / (2.0 * a);
        flux += flow.fluid.density * flow.fluid.gravity * std::sin(flow.slope) * h * h * h / (3.0 * flow.viscosity) *
                (2.0 * a / strips);
        area += h * (2.0 * a / strips);
      }
      EXPECT_NEAR(rivuletArea(flow, a) / area, 1.0, 1e-6) << angle;
      EXPECT_NEAR(rivuletFlux(flow, rivuletArea(flow, a)) / flux, 1.0, 1e-6) << angle << " " << slope;
      EXPECT_NEAR(rivuletHalfWidthForFlux(flow, flux) / a, 1.0, 1e-6);
      EXPECT_NEAR(rivuletHalfWidth(flow, area) / a, 1.0, 1e-6);
      EXPECT_NEAR(rivuletHeight(flow, a), std::tan(flow.contactAngle) * a / 2.0, 1e-15);
    }
}

// The closed form Q = (4/105) (rho g sin(alpha) / mu) tan^3(theta) a^4 at a crying rate.
TEST(RivuletLaw, SixMicrolitresASecondDownAWallRunAboutAFifthOfAMillimetreWide) {
  const RivuletFlow flow = wallFlow(65.0);
  const double a = rivuletHalfWidthForFlux(flow, 6.0 * kUl);
  const double expected =
      std::pow(105.0 * 1.5e-3 * 6e-9 / (4.0 * 1000.0 * 9.81 * std::pow(std::tan(deg(65.0)), 3.0)), 0.25);
  EXPECT_NEAR(a, expected, 1e-12);
  EXPECT_NEAR(a, 0.222e-3, 0.002e-3);
  // Narrow against the capillary length, as the small-width limit needs.
  EXPECT_LT(a, 0.15 * TearFluid{}.capillaryLength());
  // Flat ground carries nothing; a steeper slope carries more through the same section.
  RivuletFlow level = flow;
  level.slope = 0.0;
  EXPECT_EQ(rivuletFluxCoefficient(level), 0.0);
  EXPECT_EQ(rivuletHalfWidthForFlux(level, 6.0 * kUl), 0.0);
  RivuletFlow gentle = flow;
  gentle.slope = deg(30.0);
  EXPECT_NEAR(rivuletFluxCoefficient(gentle) / rivuletFluxCoefficient(flow), 0.5, 1e-12);
}

TEST(RivuletLaw, BreakupSpacingIsRayleighsWavelengthOfTheEdgeArc) {
  const RivuletFlow flow = wallFlow(65.0);
  EXPECT_NEAR(rivuletBreakupSpacing(flow, 2e-4), 9.02 * 2e-4 / std::sin(deg(65.0)), 1e-12);
}

TEST(RivuletLaw, RejectsAnglesOutsideTheLubricationModel) {
  EXPECT_THROW(validateRivuletFlow(wallFlow(90.0)), InputError);
  EXPECT_THROW(validateRivuletFlow(wallFlow(0.0)), InputError);
  RivuletFlow flow = wallFlow();
  flow.viscosity = -1.0;
  EXPECT_THROW(validateRivuletFlow(flow), InputError);
  EXPECT_NO_THROW(validateRivuletFlow(wallFlow()));
}

// A wall (tilt 90 degrees) down the fall line from the origin, turning under (a ceiling) at
// `overhangFrom`, samples every millimetre.
std::vector<LiquidPathSample> wallPath(double length, double overhangFrom) {
  std::vector<LiquidPathSample> path;
  for (int i = 0; i <= int(std::lround(length / 1e-3)); ++i) {
    LiquidPathSample sample;
    sample.arcLength = i * 1e-3;
    if (sample.arcLength < overhangFrom - 1e-12) {
      sample.position = Vec3d(0.0, -sample.arcLength, 0.0);
      sample.normal = Vec3d::UnitZ();
    } else {
      sample.position = Vec3d(0.0, -overhangFrom, sample.arcLength - overhangFrom);
      sample.normal = -Vec3d::UnitY();
    }
    path.push_back(sample);
  }
  return path;
}

LiquidTearInput cryingInput(double rate, double wellEnd, double length = 0.12, double overhangFrom = 0.1) {
  LiquidTearInput input;
  input.path = wallPath(length, overhangFrom);
  input.params.source = WellingSource{.rate = rate, .start = 0.0, .end = wellEnd, .overflowVolume = 2.0 * kUl,
                                      .spillVolume = 2.0 * kUl};
  input.params.hangingContactRadius = 0.9e-3;
  input.params.rivulet.formFlowRate = 4.0 * kUl;
  return input;
}

// Cells of the trail holding rivulet liquid, as the lowest one's far edge (m), and how many.
double rivuletFront(const LiquidTearSimulation& simulation, double cellLength) {
  double front = 0.0;
  const std::vector<double>& cells = simulation.cellRivuletVolume();
  for (size_t cell = 0; cell < cells.size(); ++cell)
    if (cells[cell] > 1e-3 * kUl * cellLength / 1e-3) front = double(cell + 1) * cellLength;
  return front;
}

TEST(RivuletSimulation, TheFrontRunsAtTheShockSpeedAndTheRivuletCarriesTheWellingRateAtItsWidth) {
  const double rate = 6.0 * kUl;
  LiquidTearInput input = cryingInput(rate, 1e30);
  LiquidTearSimulation simulation(input);
  const RivuletFlow flow = simulation.rivuletFlowAt(0.05);
  const double a = rivuletHalfWidthForFlux(flow, rate);
  // Into dry skin the front is a shock, speed [Q] / [A] (Lighthill & Whitham 1955), where the jump
  // in volume per length is the cross-section plus the film it leaves on the skin it wets.
  const double speed = rate / (rivuletArea(flow, a) + input.params.filmThickness * 2.0 * a);
  const double cell = input.params.trailCellLength;
  double worst = 0.0;
  // The meniscus (2 uL) is full at 1/3 s; from then on the rivulet runs.
  const double start = input.params.source.overflowVolume / rate;
  for (double t : {0.6, 0.8, 1.0}) {
    while (simulation.time() < t - 1e-9) {
      simulation.step();
      worst = std::max(worst, simulation.budget().relativeImbalance());
    }
    const double front = rivuletFront(simulation, cell);
    std::printf("[ rivulet ] t %.1f s: front %.1f mm, shock %.1f mm\n", t, front * 1e3, speed * (t - start) * 1e3);
    EXPECT_NEAR(front, speed * (t - start), 3.0 * cell) << t;
  }
  simulation.advanceTo(8.0);  // long enough for the drop under the overhang to reach Tate's 25 uL
  // Steady: mid-path the cross-section carries the welling rate at Duffy & Moffatt's width.
  const LiquidTearState state = simulation.state(simulation.time());
  ASSERT_EQ(state.rivulets.size(), 1u);
  const RivuletView& rivulet = state.rivulets[0];
  EXPECT_EQ(rivulet.begin, 0.0);
  EXPECT_NEAR(rivulet.end, 0.1, cell);
  for (const RivuletStation& station : rivulet.stations) {
    if (station.arcLength < 0.02 || station.arcLength > 0.09) continue;
    EXPECT_NEAR(station.halfWidth / a, 1.0, 0.01) << station.arcLength;
    const double area = rivuletArea(flow, station.halfWidth);
    EXPECT_NEAR(rivuletFlux(flow, area) / rate, 1.0, 0.03) << station.arcLength;
    EXPECT_NEAR(station.height, rivuletHeight(flow, station.halfWidth), 1e-15);
  }
  // It wets the skin it covers, feeds the drop under the overhang, and the drop lets go.
  EXPECT_NEAR(simulation.filmWidthAt(0.05), 2.0 * a, 0.02 * a);
  EXPECT_NEAR(simulation.filmThicknessAt(0.05) / input.params.filmThickness, 1.0, 1e-3);  // less a step's evaporation
  EXPECT_FALSE(simulation.drops().empty());
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(simulation.budget().relativeImbalance(), 1e-6);
}

TEST(RivuletSimulation, WhenTheWellingStopsTheRivuletDrainsAndBreaksIntoBeads) {
  LiquidTearInput input = cryingInput(8.0 * kUl, 2.0);
  LiquidTearSimulation simulation(input);
  simulation.advanceTo(1.99);
  ASSERT_EQ(simulation.state(simulation.time()).rivulets.size(), 1u);
  EXPECT_TRUE(simulation.wellsAsRivulet());
  double worst = 0.0;
  int mostBeads = 0;
  while (simulation.time() < 8.0) {
    simulation.step();
    worst = std::max(worst, simulation.budget().relativeImbalance());
    int live = 0;
    for (const Bead& bead : simulation.beads())
      if (isLiveBeadPhase(bead.phase) && bead.phase != BeadPhase::Hanging) ++live;
    mostBeads = std::max(mostBeads, live);
  }
  EXPECT_FALSE(simulation.wellsAsRivulet());
  const LiquidTearState state = simulation.state(simulation.time());
  std::printf("[ rivulet ] 6 s after the welling stopped: %zu stretches, %zu beads (at most %d), %.3f uL of rivulet\n",
              state.rivulets.size(), state.beads.size(), mostBeads, simulation.budget().rivulet / kUl);
  EXPECT_TRUE(state.rivulets.empty());
  EXPECT_EQ(simulation.budget().rivulet, 0.0);
  EXPECT_GE(mostBeads, 3);  // the stream broke into several beads, not one
  // The beads it broke into are about one Rayleigh spacing apart (or merged: more).
  const RivuletFlow flow = simulation.rivuletFlowAt(0.05);
  const double spacing = rivuletBreakupSpacing(flow, rivuletHalfWidthForFlux(flow, 8.0 * kUl));
  std::vector<double> arcs;
  for (const BeadView& bead : state.beads)
    if (bead.phase != BeadPhase::Hanging) arcs.push_back(bead.arcLength);
  std::sort(arcs.begin(), arcs.end());
  for (size_t i = 1; i < arcs.size(); ++i) EXPECT_GT(arcs[i] - arcs[i - 1], 0.5 * spacing);
  EXPECT_LT(worst, 1e-6);
}

TEST(RivuletSimulation, TheRivuletSwallowsABeadInItsWay) {
  LiquidTearInput input = cryingInput(6.0 * kUl, 1e30);
  input.params.initialBeads = {{0.02, 0.3 * kUl}};  // too small to slide down the wall
  LiquidTearSimulation simulation(input);
  simulation.advanceTo(0.3);
  ASSERT_EQ(simulation.beads()[0].phase, BeadPhase::Pinned);
  simulation.advanceTo(1.5);
  EXPECT_EQ(simulation.beads()[0].phase, BeadPhase::InRivulet);
  EXPECT_EQ(simulation.beads()[0].volume, 0.0);
  EXPECT_LT(simulation.budget().relativeImbalance(), 1e-6);
}

TEST(RivuletSimulation, BelowTheFormingRateTheTearSpillsBeadsExactlyAsWithoutRivulets) {
  LiquidTearInput with = cryingInput(3.0 * kUl, 3.0);
  LiquidTearInput without = with;
  without.params.rivulet.formFlowRate = 0.0;
  LiquidTearSimulation a(with), b(without);
  a.advanceTo(5.0);
  b.advanceTo(5.0);
  EXPECT_EQ(a.budget().rivulet, 0.0);
  ASSERT_EQ(a.beads().size(), b.beads().size());
  for (size_t i = 0; i < a.beads().size(); ++i) {
    EXPECT_EQ(a.beads()[i].arcLength, b.beads()[i].arcLength);
    EXPECT_EQ(a.beads()[i].volume, b.beads()[i].volume);
  }
  EXPECT_EQ(a.cellFilmVolume(), b.cellFilmVolume());
}

TEST(WellingSource, AKeyedRateIsIntegratedExactlyBetweenItsKeys) {
  WellingSource source;
  source.rateKeys = {{1.0, 0.0}, {2.0, 10.0 * kUl}, {3.0, 10.0 * kUl}, {4.0, 0.0}};
  EXPECT_EQ(source.rateAt(0.5), 0.0);
  EXPECT_NEAR(source.rateAt(1.5), 5.0 * kUl, 1e-18);
  EXPECT_NEAR(source.rateAt(3.75), 2.5 * kUl, 1e-18);
  EXPECT_NEAR(source.volumeBetween(0.0, 5.0), 20.0 * kUl, 1e-18);
  EXPECT_NEAR(source.volumeBetween(1.5, 2.5), (0.5 * (5.0 + 10.0) * 0.5 + 10.0 * 0.5) * kUl, 1e-18);
  double sum = 0.0;  // step by step as the simulation wells: the same total
  for (int i = 0; i < 5000; ++i) sum += source.volumeBetween(i * 1e-3, (i + 1) * 1e-3);
  EXPECT_NEAR(sum, 20.0 * kUl, 1e-15);
  source.start = 1.5;  // the window still applies
  source.end = 3.5;
  EXPECT_EQ(source.rateAt(1.4), 0.0);
  EXPECT_EQ(source.rateAt(3.5), 0.0);
  EXPECT_NEAR(source.volumeBetween(0.0, 5.0), (0.5 * (5.0 + 10.0) * 0.5 + 10.0 + 0.5 * (10.0 + 5.0) * 0.5) * kUl, 1e-18);
}

// Crying eases: the rate falls from 10 uL/s to nothing over two seconds. The rivulet narrows as it
// carries less (Q ~ a^4), the meniscus goes back to spilling beads once the rate is under the
// forming rate, and the stream breaks up into beads.
TEST(RivuletSimulation, AsTheCryingEasesTheRivuletNarrowsAndBreaksIntoBeads) {
  LiquidTearInput input = cryingInput(0.0, 1e30);
  input.params.source.rateKeys = {{2.5, 10.0 * kUl}, {4.5, 0.0}};
  LiquidTearSimulation simulation(input);
  auto halfWidthAt = [&](double s) {
    const LiquidTearState state = simulation.state(simulation.time());
    for (const RivuletView& rivulet : state.rivulets)
      for (const RivuletStation& station : rivulet.stations)
        if (std::abs(station.arcLength - s) < 3e-4) return station.halfWidth;
    return 0.0;
  };
  simulation.advanceTo(2.5);
  const double full = halfWidthAt(0.03);
  EXPECT_NEAR(full / rivuletHalfWidthForFlux(simulation.rivuletFlowAt(0.03), 10.0 * kUl), 1.0, 0.02);
  simulation.advanceTo(3.3);  // about 6 uL/s welling; the cell 3 cm down carries what left the lid ~0.3 s before
  const double easing = halfWidthAt(0.03);
  EXPECT_LT(easing, 0.97 * full);
  EXPECT_GT(easing, 0.8 * full);
  double worst = 0.0;
  bool spilledBeads = false;
  while (simulation.time() < 8.0) {
    simulation.step();
    worst = std::max(worst, simulation.budget().relativeImbalance());
    // The meniscus stays full while it feeds the rivulet; a spill empties it.
    if (simulation.time() > 3.69 && simulation.time() < 4.5)
      spilledBeads |= simulation.meniscusVolume() < input.params.source.overflowVolume - 1.0 * kUl;
  }
  std::printf("[ rivulet ] easing: half-width %.3f mm at 10 uL/s, %.3f mm 0.8 s later\n", full * 1e3, easing * 1e3);
  EXPECT_TRUE(spilledBeads);  // under 4 uL/s (from 3.7 s) the full meniscus spills a bead again
  EXPECT_TRUE(simulation.state(simulation.time()).rivulets.empty());
  EXPECT_EQ(simulation.budget().rivulet, 0.0);
  EXPECT_LT(worst, 1e-6);
}

TEST(RivuletSimulation, RejectsBadRivuletParameters) {
  LiquidTearInput input = cryingInput(6.0 * kUl, 1e30);
  input.params.rivulet.breakFlowRate = 5.0 * kUl;
  input.params.rivulet.formFlowRate = 4.0 * kUl;
  EXPECT_THROW(LiquidTearSimulation{input}, InputError);
  input = cryingInput(6.0 * kUl, 1e30);
  input.params.contactAngles = ContactAngleHysteresis{deg(110.0), deg(95.0)};
  try {
    LiquidTearSimulation simulation(input);
    FAIL() << "a receding angle of 95 degrees was accepted for a rivulet";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("receding"), std::string::npos) << e.what();
  }
  input.params.rivulet.formFlowRate = 0.0;  // without rivulets any angle goes
  EXPECT_NO_THROW(LiquidTearSimulation{input});
  input.params.source.rateKeys = {{1.0, 1.0 * kUl}, {1.0, 2.0 * kUl}};
  EXPECT_THROW(LiquidTearSimulation{input}, InputError);
  input.params.source.rateKeys = {{1.0, -1.0 * kUl}};
  EXPECT_THROW(LiquidTearSimulation{input}, InputError);
}

}  // namespace rivulet_test
}  // namespace lacrima
