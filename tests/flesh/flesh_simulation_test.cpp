// Time integration of the flesh: conservation laws without damping, an elastic bar's vibration
// against its analytic period (converging under refinement), the rig's pose as the equilibrium,
// and damping that settles the jiggle.
#include "lacrima/flesh/flesh_simulation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

namespace lacrima::flesh {
namespace flesh_simulation_test {

const LameParameters kLame = LameParameters::fromYoung(3000.0, 0.4);

std::vector<Vec3d> zeros(size_t n) { return std::vector<Vec3d>(n, Vec3d::Zero()); }

// A block at rest shape `mesh`, every node free, given a random push.
FleshSimulation pushedFreeBlock(const TetMesh& mesh, FleshIntegrator integrator, double stiffnessDamping) {
  FleshDynamicsParams params;
  params.integrator = integrator;
  params.stiffnessDamping = stiffnessDamping;
  params.newtonIterations = 8;
  params.newtonTolerance = 1e-10;
  params.cgTolerance = 1e-12;
  params.cgIterations = 1000;
  FleshSimulation sim(mesh, FleshMaterial::FixedCorotated, kLame, params, std::vector<bool>(mesh.nodes.size(), false));
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<Vec3d> v;
  for (size_t i = 0; i < mesh.nodes.size(); ++i) v.emplace_back(u(random) + 0.02, u(random), u(random));
  sim.setState(mesh.nodes, v);
  return sim;
}

TEST(FleshSimulation, FreeBlockKeepsItsMomentum) {
  const TetMesh mesh = makeBoxTetMesh(Vec3d(0.02, 0.02, 0.02), 2, 2, 2);
  for (FleshIntegrator integrator : {FleshIntegrator::BackwardEuler, FleshIntegrator::ImplicitMidpoint}) {
    FleshSimulation sim = pushedFreeBlock(mesh, integrator, 0.002);
    const Vec3d before = sim.momentum();
    for (int s = 0; s < 50; ++s) sim.step(1e-3, mesh.nodes, zeros(mesh.nodes.size()));
    EXPECT_LT((sim.momentum() - before).norm(), 1e-8 * before.norm()) << int(integrator);
  }
}

double totalEnergyRatioAfter(const TetMesh& mesh, FleshIntegrator integrator, double h, int steps) {
  FleshSimulation sim = pushedFreeBlock(mesh, integrator, 0.0);
  const double start = sim.kineticEnergy() + sim.elasticEnergy();
  // The rest shape is the mesh's (strain does not see where the block has drifted to).
  for (int s = 0; s < steps; ++s) sim.step(h, mesh.nodes, zeros(mesh.nodes.size()));
  return (sim.kineticEnergy() + sim.elasticEnergy()) / start;
}

TEST(FleshSimulation, MidpointConservesEnergyAndBackwardEulerDissipatesIt) {
  const TetMesh mesh = makeBoxTetMesh(Vec3d(0.02, 0.02, 0.02), 2, 2, 2);
  const double midpoint = totalEnergyRatioAfter(mesh, FleshIntegrator::ImplicitMidpoint, 1e-3, 200);
  EXPECT_NEAR(midpoint, 1.0, 2e-3);
  // Backward Euler loses energy, and less with a shorter step: a mode of frequency omega keeps
  // exp(-omega^2 h t) of its energy while omega h << 1, so halving h halves the log of the loss;
  // the block's fastest modes (omega h ~ 1 here) give somewhat less.
  const double coarse = totalEnergyRatioAfter(mesh, FleshIntegrator::BackwardEuler, 2e-4, 250);
  const double fine = totalEnergyRatioAfter(mesh, FleshIntegrator::BackwardEuler, 1e-4, 500);
  std::printf("energy kept after 0.05 s: backward Euler %.5f (h = 2e-4), %.5f (h = 1e-4); midpoint %.6f\n", coarse,
              fine, midpoint);
  EXPECT_LT(coarse, fine);
  EXPECT_LT(fine, 1.0);
  const double logRatio = std::log(coarse) / std::log(fine);
  EXPECT_GT(logRatio, 1.3);
  EXPECT_LT(logRatio, 2.1);
}

// The period of a bar's first longitudinal mode, clamped at z = 0, with n cells along its length.
double barPeriod(int cellsAlong, double young, double density, double length) {
  const double width = length / 16.0;
  const TetMesh mesh = makeBoxTetMesh(Vec3d(width, width, length), 1, 1, cellsAlong);
  std::vector<bool> clamped(mesh.nodes.size());
  for (size_t i = 0; i < clamped.size(); ++i) clamped[i] = mesh.nodes[i].z() < 1e-12;
  FleshDynamicsParams params;
  params.density = density;
  params.integrator = FleshIntegrator::ImplicitMidpoint;
  params.newtonIterations = 6;
  params.newtonTolerance = 1e-10;
  params.cgTolerance = 1e-12;
  params.cgIterations = 2000;
  // Poisson's ratio 0: the one-dimensional wave equation is then the bar's exact continuum model.
  FleshSimulation sim(mesh, FleshMaterial::FixedCorotated, LameParameters::fromYoung(young, 0.0), params, clamped);
  std::vector<Vec3d> stretched = mesh.nodes;
  for (Vec3d& p : stretched) p.z() *= 1.001;
  sim.setState(stretched, zeros(mesh.nodes.size()));
  const double expected = 4.0 * length / std::sqrt(young / density);
  const double h = expected / 400.0;
  const auto tipStretch = [&] {
    double sum = 0.0;
    int count = 0;
    for (size_t i = 0; i < mesh.nodes.size(); ++i)
      if (mesh.nodes[i].z() > length - 1e-12) sum += sim.positions()[i].z() - length, ++count;
    return sum / count;
  };
  std::vector<double> downCrossings;
  double previous = tipStretch(), time = 0.0;
  while (downCrossings.size() < 4 && time < 6.0 * expected) {
    sim.step(h, mesh.nodes, zeros(mesh.nodes.size()));
    time += h;
    const double now = tipStretch();
    if (previous > 0.0 && now <= 0.0) downCrossings.push_back(time - h * now / (now - previous));
    previous = now;
  }
  if (downCrossings.size() < 4) return 0.0;
  return (downCrossings[3] - downCrossings[0]) / 3.0;
}

TEST(FleshSimulation, BarVibratesAtTheWaveEquationsPeriodUnderRefinement) {
  // Clamped-free bar: T = 4 L / c, c = sqrt(E / rho). Lumped masses and linear tetrahedra err by
  // about (pi / 2n)^2 / 24 for n cells: the error must shrink as the bar is refined.
  const double young = 1e4, density = 1000.0, length = 0.1;
  const double expected = 4.0 * length / std::sqrt(young / density);
  double previousError = 1.0;
  for (int cells : {4, 8, 16}) {
    const double period = barPeriod(cells, young, density, length);
    const double error = std::abs(period / expected - 1.0);
    std::printf("bar of %d cells: period %.6f s against %.6f s (%.3f %%)\n", cells, period, expected, 100 * error);
    EXPECT_LT(error, previousError) << cells;
    previousError = error;
  }
  EXPECT_LT(previousError, 0.01);
}

// A block whose bottom layer the rig moves; the rest free.
struct RiggedBlock {
  TetMesh mesh = makeBoxTetMesh(Vec3d(0.02, 0.02, 0.03), 2, 2, 3);
  std::vector<bool> base;
  RiggedBlock() {
    for (const Vec3d& p : mesh.nodes) base.push_back(p.z() < 1e-12);
  }
  FleshSimulation simulation(double massDamping, double stiffnessDamping) const {
    FleshDynamicsParams params;
    params.massDamping = massDamping;
    params.stiffnessDamping = stiffnessDamping;
    return FleshSimulation(mesh, FleshMaterial::FixedCorotated, kLame, params, base);
  }
  std::vector<Vec3d> shifted(const Vec3d& offset) const {
    std::vector<Vec3d> out = mesh.nodes;
    for (Vec3d& p : out) p += offset;
    return out;
  }
};

double largestOffset(const std::vector<Vec3d>& a, const std::vector<Vec3d>& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (a[i] - b[i]).norm());
  return worst;
}

TEST(FleshSimulation, AStillPoseIsLeftExactlyAsTheRigMadeIt) {
  const RiggedBlock block;
  FleshSimulation sim = block.simulation(5.0, 0.002);
  for (int s = 0; s < 20; ++s) sim.step(1.0 / 96, block.mesh.nodes, zeros(block.mesh.nodes.size()));
  EXPECT_LT(largestOffset(sim.positions(), block.mesh.nodes), 1e-12);
}

TEST(FleshSimulation, SteadyMotionOfTheRigCarriesTheFleshWithoutLag) {
  // The mass damping acts on the velocity relative to the rig's: at a constant rig velocity the
  // flesh keeps the pose.
  const RiggedBlock block;
  FleshSimulation sim = block.simulation(20.0, 0.002);
  const Vec3d velocity(0.1, 0.0, 0.0);
  const double h = 1.0 / 96;
  std::vector<Vec3d> v(block.mesh.nodes.size(), velocity);
  sim.setState(block.mesh.nodes, v);
  for (int s = 1; s <= 48; ++s) sim.step(h, block.shifted(velocity * (s * h)), v);
  EXPECT_LT(largestOffset(sim.positions(), block.shifted(velocity * 0.5)), 1e-9);
}

TEST(FleshSimulation, AJerkOfTheRigJigglesTheFleshAndDampingSettlesIt) {
  const RiggedBlock block;
  const double h = 1.0 / 240;
  const auto topOffsetOverTime = [&](double massDamping) {
    FleshSimulation sim = block.simulation(massDamping, 0.0);
    std::vector<double> offsets;
    const Vec3d jump(0.004, 0.0, 0.0);  // the base moves 4 mm in one step, then stays
    for (int s = 0; s < 240; ++s) {
      sim.step(h, block.shifted(jump), zeros(block.mesh.nodes.size()));
      offsets.push_back(sim.positions().back().x() - (block.mesh.nodes.back().x() + jump.x()));
    }
    return offsets;
  };
  const std::vector<double> lively = topOffsetOverTime(0.0), damped = topOffsetOverTime(30.0);
  // The top lags behind (negative), overshoots (positive), and keeps moving without mass damping...
  EXPECT_LT(*std::min_element(lively.begin(), lively.begin() + 24), -0.001);
  EXPECT_GT(*std::max_element(lively.begin(), lively.end()), 0.0005);
  double lateLively = 0.0, lateDamped = 0.0;
  for (size_t s = 200; s < 240; ++s) {
    lateLively = std::max(lateLively, std::abs(lively[s]));
    lateDamped = std::max(lateDamped, std::abs(damped[s]));
  }
  // ...while damping brings it to rest on the rig's pose.
  EXPECT_GT(lateLively, 10.0 * lateDamped);
  EXPECT_LT(lateDamped, 1e-5);
}

TEST(FleshSimulation, NewtonConvergesInOneStepWhileTheRigTurnsTheFlesh) {
  // The rig turns the block's base 90 degrees over 24 steps (a head turn) and the flesh swings
  // with it. The stiffness with the rotation's own differential is the residual's exact
  // derivative near rest: one Newton step (each linear solve to 1e-4) mostly takes the residual to
  // a hundredth (30 Newton steps over the 24 steps). With the rotation held fixed every step ran
  // to the limit of four (96).
  const RiggedBlock block;
  FleshDynamicsParams params;
  params.newtonTolerance = 1e-2;
  params.cgTolerance = 1e-4;
  FleshSimulation sim(block.mesh, FleshMaterial::FixedCorotated, kLame, params, block.base);
  const double h = 1.0 / 96;
  int newtonSteps = 0;
  for (int s = 1; s <= 24; ++s) {
    const Eigen::AngleAxisd turn(0.5 * M_PI * s / 24.0, Vec3d::UnitZ());
    std::vector<Vec3d> target = block.mesh.nodes, velocity(target.size());
    for (size_t i = 0; i < target.size(); ++i) {
      target[i] = turn * block.mesh.nodes[i];
      velocity[i] = Vec3d(0.0, 0.0, 0.5 * M_PI / (24.0 * h)).cross(target[i]);
    }
    newtonSteps += sim.step(h, target, velocity).newtonIterations;
  }
  EXPECT_LE(newtonSteps, 36);
}

TEST(FleshSimulation, APositionToleranceSolvesToWhatCanBeSeenInFewerIterations) {
  // The jerked block of the test above, 24 steps: solved to relative tolerances alone, and also
  // stopping once no node would move by more than 0.1 um. The positions agree to about a micrometre
  // (the jerk moves the top by millimetres); the second takes far fewer iterations.
  const RiggedBlock block;
  const auto run = [&](double positionTolerance, std::vector<Vec3d>& positions) {
    FleshDynamicsParams params;
    params.massDamping = 4.0;
    params.newtonTolerance = 1e-2;
    params.cgTolerance = 1e-3;
    params.positionTolerance = positionTolerance;
    FleshSimulation sim(block.mesh, FleshMaterial::FixedCorotated, kLame, params, block.base);
    int iterations = 0;
    for (int s = 0; s < 24; ++s)
      iterations += sim.step(1.0 / 96, block.shifted(Vec3d(0.004, 0.0, 0.0)), zeros(block.mesh.nodes.size())).cgIterations;
    positions = sim.positions();
    return iterations;
  };
  std::vector<Vec3d> relative, visible;
  const int relativeIterations = run(0.0, relative), visibleIterations = run(1e-7, visible);
  EXPECT_LT(largestOffset(relative, visible), 2e-6);
  EXPECT_LT(visibleIterations, relativeIterations * 3 / 4);
  std::printf("[ solver ] conjugate-gradient iterations over 24 steps: %d relative, %d with the position tolerance; "
              "largest difference %.2g m\n", relativeIterations, visibleIterations, largestOffset(relative, visible));
}

TEST(FleshSimulation, AStepFromAStateGivenBackIsTheStepOfTheRunThatReachedIt) {
  // Filed states hold positions and velocities only: a frame rendered alone continues from one and
  // must step as the run that filed it, also when the rig's pose (the rest shape) flattens the
  // tetrahedra (as a squint does to a few of the default shot's).
  const TetMesh mesh = makeBoxTetMesh(Vec3d(0.02, 0.02, 0.02), 2, 2, 2);
  std::vector<Vec3d> stretched = mesh.nodes, flat = mesh.nodes;
  for (Vec3d& p : stretched) p.x() *= 1.2;
  for (Vec3d& p : flat) p.z() = 0.0;
  const size_t n = mesh.nodes.size();
  FleshDynamicsParams params;
  const std::vector<bool> free(n, false);
  FleshSimulation through(mesh, FleshMaterial::FixedCorotated, kLame, params, free);
  through.setState(mesh.nodes, zeros(n));
  through.step(1e-2, stretched, zeros(n));
  FleshSimulation resumed(mesh, FleshMaterial::FixedCorotated, kLame, params, free);
  resumed.setState(through.positions(), through.velocities());
  through.step(1e-2, flat, zeros(n));
  resumed.step(1e-2, flat, zeros(n));
  EXPECT_EQ(resumed.positions(), through.positions());
  EXPECT_EQ(resumed.velocities(), through.velocities());
  EXPECT_NE(through.positions(), mesh.nodes);  // the steps moved the block: the comparison means something
}

TEST(FleshSimulation, BadArgumentsAreRefused) {
  const RiggedBlock block;
  FleshSimulation sim = block.simulation(0.0, 0.0);
  EXPECT_THROW(sim.step(0.0, block.mesh.nodes, zeros(block.mesh.nodes.size())), std::invalid_argument);
  EXPECT_THROW(sim.step(0.01, {}, zeros(block.mesh.nodes.size())), std::invalid_argument);
  EXPECT_THROW(sim.setState({}, {}), std::invalid_argument);
}

}  // namespace flesh_simulation_test
}  // namespace lacrima::flesh
