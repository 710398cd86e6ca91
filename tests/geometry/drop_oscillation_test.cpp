// Falling tear drops ring in the Rayleigh/Lamb mode n = 2: the period and the damping
// measured on the drawn meshes of a simulated drip against Rayleigh's frequency and Lamb's damping
// time, the drawn volume, closed meshes, the initial stretch from the hanging bead, and the state
// as a pure function of time.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "lacrima/liquid/drop_oscillation.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/mesh/shapes.hpp"
#include "lacrima/liquid/liquid_tear.hpp"

namespace lacrima {
namespace drop_oscillation_test {

constexpr double kPiD = std::numbers::pi;

// A vertical wall (normal +z, gravity -y) 2 cm down that then turns under, the way a cheek turns
// under the jaw: without `ceiling` a 1 mm ledge whose normal is kLedgeFromDown from straight down
// (just inside the default overhang cone of 60 degrees), with `ceiling` a ceiling (normal -y) for
// 1 cm. The bead hangs where the skin starts to face down (s = 2 cm) and drips; a wall's end
// alone is no drip site (a pendant drop needs an overhang).
constexpr double kLedgeFromDown = 59.0 * kPiD / 180.0;

LiquidTearInput dripInput(bool ceiling = false) {
  LiquidTearInput input;
  const Vec3d ledgeNormal(0.0, -std::cos(kLedgeFromDown), std::sin(kLedgeFromDown));
  const Vec3d ledgeDown(0.0, -std::sin(kLedgeFromDown), -std::cos(kLedgeFromDown));  // in the ledge, downhill
  const int samples = ceiling ? 30 : 21;
  for (int i = 0; i <= samples; ++i) {
    LiquidPathSample sample;
    sample.arcLength = i * 1e-3;
    const Vec3d corner(0.0, -0.02, 0.0);
    if (i <= 20) {
      sample.position = Vec3d(0.0, -sample.arcLength, 0.0);
    } else {
      sample.position = ceiling ? Vec3d(0.0, -0.02, sample.arcLength - 0.02) : Vec3d(corner + 1e-3 * ledgeDown);
    }
    sample.normal = i < 20 ? Vec3d(Vec3d::UnitZ()) : ceiling ? Vec3d(-Vec3d::UnitY()) : ledgeNormal;
    input.path.push_back(sample);
  }
  input.params.source = WellingSource{.rate = 10.0 * kMicrolitre, .overflowVolume = 8.0 * kMicrolitre,
                                      .spillVolume = 8.0 * kMicrolitre};
  return input;
}

// The simulation advanced to just after its first drop detached.
LiquidTearSimulation simulatedToFirstDrop(const LiquidTearInput& input) {
  LiquidTearSimulation simulation(input);
  while (simulation.drops().empty() && simulation.time() < 30.0) simulation.step();
  EXPECT_EQ(simulation.drops().size(), 1u);
  return simulation;
}

// Semi-axes of a drawn drop measured on its mesh: half its extent along `axis` and across it.
struct MeasuredAxes {
  double along = 0.0, across = 0.0;
};
MeasuredAxes measureAxes(const TriangleMesh& mesh, const Vec3d& centre, const Vec3d& axis) {
  MeasuredAxes m;
  for (const Vec3& p : mesh.positions) {
    const Vec3d d = p.cast<double>() - centre;
    const double along = d.dot(axis);
    m.along = std::max(m.along, std::abs(along));
    m.across = std::max(m.across, (d - along * axis).norm());
  }
  return m;
}

// eps measured on the drawn mesh of the first drop at time t.
double drawnAmplitude(LiquidTearSimulation& simulation, double t) {
  simulation.advanceTo(t);
  const DropView drop = simulation.state(t).drops.at(0);
  const TriangleMesh mesh = makeFallingDropMesh(drop.centre, drop.axis, drop.axes);
  const MeasuredAxes m = measureAxes(mesh, drop.centre, drop.axis);
  return modeTwoAmplitudeFromAspect(m.along / m.across);
}

TEST(DropOscillation, DrawnDropRingsAtRayleighsFrequencyAndDecaysWithLambsTime) {
  const LiquidTearInput input = dripInput();
  LiquidTearSimulation simulation = simulatedToFirstDrop(input);
  const FallingDrop drop = simulation.drops()[0];
  const TearFluid& fluid = input.params.fluid;
  const double radius = std::cbrt(3.0 * drop.volume / (4.0 * kPiD));
  // Rayleigh 1879 (n = 2): omega^2 = 8 sigma / (rho R^3); Lamb 1932: tau = R^2 / (5 nu).
  const double period = 2.0 * kPiD / std::sqrt(8.0 * fluid.surfaceTension / (fluid.density * std::pow(radius, 3)));
  const double tau = radius * radius / (5.0 * input.params.viscosity / fluid.density);

  // Sample eps from the drawn meshes every 0.05 ms over 12 periods; the upward zero crossings
  // (interpolated) give the period, the peaks the decay.
  const double dt = 5e-5;
  std::vector<double> crossings, peakTimes, peaks;
  double previous = drawnAmplitude(simulation, drop.detachTime), beforePrevious = previous;
  for (double t = drop.detachTime + dt; t < drop.detachTime + 12.0 * period; t += dt) {
    const double eps = drawnAmplitude(simulation, t);
    if (previous < 0.0 && eps >= 0.0) crossings.push_back(t - dt * eps / (eps - previous));
    if (previous > beforePrevious && previous >= eps) {
      peakTimes.push_back(t - dt);
      peaks.push_back(previous);
    }
    beforePrevious = previous;
    previous = eps;
  }
  ASSERT_GE(crossings.size(), 10u);
  const double measuredPeriod = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  std::printf("[ drop ] R = %.3f mm, eps0 = %.3f, period %.3f ms (Rayleigh %.3f ms), tau %.3f s\n", radius * 1e3,
              drop.oscillation.initialAmplitude, measuredPeriod * 1e3, period * 1e3, tau);
  EXPECT_NEAR(measuredPeriod, period, 2e-3 * period);

  ASSERT_GE(peaks.size(), 10u);
  const double measuredTau = (peakTimes.back() - peakTimes.front()) / std::log(peaks.front() / peaks.back());
  EXPECT_NEAR(measuredTau, tau, 0.03 * tau);
  EXPECT_GT(drop.oscillation.initialAmplitude, 0.02) << "a hanging drop leaves stretched along gravity";
}

// The drawn hanging bead's half extents: halfLength along the path, halfWidth across, height / 2 out of the skin.
BeadShape hangingShape(const LiquidTearInput& input, double volume) {
  const ContactAngleHysteresis& angles = input.params.contactAngles;
  return beadShape(input.params.fluid, volume, 0.5 * (angles.advancing + angles.receding), 0.5 * kPiD);
}

TEST(DropOscillation, DropLeavesAWallProlateWithTheHangingBeadsStretch) {
  const LiquidTearInput input = dripInput();
  const LiquidTearSimulation simulation = simulatedToFirstDrop(input);
  const FallingDrop drop = simulation.drops()[0];
  const BeadShape shape = hangingShape(input, drop.volume);
  // On the ledge (drawn as on a wall) the bead's long axis runs down the ledge, sin(59 deg) along
  // gravity, its height along the normal, cos(59 deg) along gravity: c is the support of its
  // half-extent ellipsoid along gravity, a^2 c = halfLength halfWidth height / 2.
  const double polar = std::hypot(shape.halfLength * std::sin(kLedgeFromDown), 0.5 * shape.height * std::cos(kLedgeFromDown));
  const double k = polar / std::sqrt(shape.halfLength * shape.halfWidth * 0.5 * shape.height / polar);
  std::printf("[ drop ] from a wall: %.2f uL, drawn bead %.3f x %.3f x %.3f mm, k = %.3f\n", drop.volume * 1e9,
              shape.halfLength * 1e3, shape.halfWidth * 1e3, shape.height * 1e3, k);
  EXPECT_GT(k, 1.2);
  EXPECT_NEAR(drop.oscillation.initialAmplitude, std::min(0.5, 2.0 * (k - 1.0) / (k + 2.0)), 1e-12);
  // At detachment the drawn drop is prolate along gravity by that ratio.
  LiquidTearSimulation again(input);
  again.advanceTo(drop.detachTime);
  const DropView view = again.state(drop.detachTime).drops.at(0);
  const double eps = drop.oscillation.initialAmplitude;
  EXPECT_NEAR(view.axes.polar / view.axes.equatorial, (1.0 + eps) / (1.0 - 0.5 * eps), 1e-9);
  EXPECT_NEAR((view.axis - Vec3d(0, -1, 0)).norm(), 0.0, 1e-12);
}

TEST(DropOscillation, DropLeavesACeilingOblateAsTheFlatCapIsDrawn) {
  const LiquidTearInput input = dripInput(true);
  const LiquidTearSimulation simulation = simulatedToFirstDrop(input);
  const FallingDrop drop = simulation.drops()[0];
  const BeadShape shape = hangingShape(input, drop.volume);
  // Gravity along the normal: c = height / 2.
  const double k = 0.5 * shape.height / std::sqrt(shape.halfLength * shape.halfWidth);
  EXPECT_LT(k, 1.0);
  EXPECT_NEAR(drop.oscillation.initialAmplitude, std::max(-0.5, 2.0 * (k - 1.0) / (k + 2.0)), 1e-12);
}

TEST(DropOscillation, DrawnMeshIsClosedAndKeepsTheDropsVolumeAtEveryAmplitude) {
  const double radius = 1.4e-3;
  const double volume = 4.0 / 3.0 * kPiD * std::pow(radius, 3);
  for (double eps : {-0.4, -0.1, 0.0, 0.2, 0.6}) {
    const SpheroidAxes axes = modeTwoSpheroid(radius, eps);
    EXPECT_NEAR(axes.equatorial * axes.equatorial * axes.polar, std::pow(radius, 3), 1e-12 * std::pow(radius, 3));
    const TriangleMesh mesh = makeFallingDropMesh(Vec3d(0.01, 0.02, 0.1), Vec3d(0.3, -1.0, 0.1), axes);
    EXPECT_EQ(findMeshDefect(mesh), "") << eps;
    EXPECT_EQ(findClosedMeshDefect(mesh), "") << eps;
    // Float vertices 0.1 m from the origin: ~1e-7 relative; the tessellation error is compensated.
    EXPECT_NEAR(signedVolume(mesh), volume, 2e-4 * volume) << eps;
  }
  // Without the compensation an inscribed 24 x 48 tessellation would hold about 1% less.
  const TriangleMesh inscribed = makeEllipsoid(Vec3::Zero(), Mat3::Identity() * float(radius), 24, 48);
  EXPECT_LT(signedVolume(inscribed), 0.995 * volume);
}

TEST(DropOscillation, StateIsAFunctionOfTimeOnly) {
  const LiquidTearInput input = dripInput();
  LiquidTearSimulation stepped = simulatedToFirstDrop(input);
  const double t = stepped.drops()[0].detachTime + 0.0371;
  stepped.advanceTo(t);
  const LiquidTearState direct = simulateLiquidTear(input, t);
  const LiquidTearState sequenced = stepped.state(t);
  ASSERT_EQ(direct.drops.size(), 1u);
  ASSERT_EQ(sequenced.drops.size(), 1u);
  EXPECT_EQ(direct.drops[0].amplitude, sequenced.drops[0].amplitude);
  EXPECT_EQ(direct.drops[0].axes.polar, sequenced.drops[0].axes.polar);
  EXPECT_EQ(direct.drops[0].axis, sequenced.drops[0].axis);
  EXPECT_NE(direct.drops[0].amplitude, direct.drops[0].amplitudeEnvelope) << "mid-ring, not at a peak";
}

TEST(DropOscillation, RejectsBadArguments) {
  EXPECT_THROW(rayleighAngularFrequency(TearFluid{}, 1e-3, 1), InputError);
  EXPECT_THROW(lambDampingTime(-1e-3, 1e-6), InputError);
  EXPECT_THROW(modeTwoSpheroid(1e-3, 2.0), InputError);
  EXPECT_THROW(makeFallingDropMesh(Vec3d::Zero(), Vec3d::Zero(), SpheroidAxes{1e-3, 1e-3}), InputError);
}

}  // namespace drop_oscillation_test
}  // namespace lacrima
