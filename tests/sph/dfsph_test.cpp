// Divergence-free SPH (dfsph.hpp): a water column at rest stays at rest with a pressure that grows
// as rho g h; a dam break's front runs as Martin & Moyce measured; the density stays within its
// tolerance and no mass is lost; the same run is bitwise the same with one thread or all.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lacrima/sph/dfsph.hpp"

namespace lacrima::sph {
namespace dfsph_test {

constexpr double kGravity = 9.81;

// Water `height` deep in a 10 cm square tank twice as tall, particles 1 cm apart, more viscous
// than water so that the start from a lattice settles within a second.
DfsphSolver waterColumn(double height) {
  FluidParams params;
  params.particleRadius = 0.005;
  params.xsphViscosity = 0.05;
  const double spacing = 2.0 * params.particleRadius;
  const Vec3d tankLo(0.0, 0.0, 0.0), tankHi(0.1, 2.0 * height, 0.1);
  return DfsphSolver(params, latticeBlock(tankLo, Vec3d(0.1, height, 0.1), spacing),
                     boundaryFromSamples(openBoxWalls(tankLo, tankHi, spacing, 2), params.particleRadius));
}

TEST(Dfsph, WaterColumnStaysAtRestWithAPressureGrowingAsRhoGH) {
  const double height = 0.1, spacing = 0.01;
  DfsphSolver solver = waterColumn(height);
  solver.advanceTo(1.5);
  const double rho0 = solver.params().restDensity;
  double top = 0.0, meanSpeed = 0.0;
  for (const Vec3d& x : solver.positions()) top = std::max(top, x.y() + 0.5 * spacing);
  for (const Vec3d& v : solver.velocities()) meanSpeed += v.norm() / double(solver.velocities().size());
  std::printf("[ dfsph ] column top %.4f m, mean speed %.2e m/s, density error %.2e, iterations %d + %d\n", top,
              meanSpeed, solver.lastStep().densityError, solver.lastStep().densityIterations,
              solver.lastStep().divergenceIterations);
  EXPECT_NEAR(top, height, 0.01 * height);  // incompressible: the column keeps its height
  EXPECT_LT(meanSpeed, 0.01);
  EXPECT_LE(solver.lastStep().densityError, solver.params().maxDensityError);
  // Layer means of the pressure, averaged over 20 steps, against rho0 g (top - y). The interior
  // layers read 6-24 % above it: in a tank ten particles wide most particles are within a support
  // of a side wall, whose boundary term carries no pressure gradient, so the pressure rises faster
  // to carry the weight (0.94-0.99x in a 40 cm tank; docs/sph.md "Water at rest"); the layer
  // on the floor reads about 1.9x, as expected of Akinci et al.'s one-sided boundary force (a
  // fluid neighbour would push with twice the term); it is left out, and the layer above it,
  // within the boundary's reach, is only checked against rho0 g h.
  std::vector<double> layerSum(10, 0.0);
  std::vector<int> layerCount(10, 0);
  for (int s = 0; s < 20; ++s) {
    solver.step();
    const std::vector<double> pressure = solver.pressures();
    for (size_t i = 0; i < pressure.size(); ++i) {
      const int layer = int(solver.positions()[i].y() / spacing);
      if (layer < 0 || layer >= 10) continue;
      layerSum[layer] += pressure[i];
      ++layerCount[layer];
    }
  }
  double previous = 1e30;
  for (int layer = 1; layer < 9; ++layer) {
    const double mean = layerSum[layer] / layerCount[layer];
    const double expected = rho0 * kGravity * (top - (layer + 0.5) * spacing);
    std::printf("[ dfsph ] layer %d: p %.0f Pa, rho0 g h %.0f Pa (%.2f)\n", layer, mean, expected, mean / expected);
    // Above the boundary's reach (layers 2 and up) the pressure grows with depth.
    if (layer > 2) {
      EXPECT_LT(mean, previous) << "pressure grows with depth";
    }
    if (layer < 8) {
      EXPECT_NEAR(mean / expected, 1.15, 0.15) << "layer " << layer;
    }
    previous = mean;
  }
}

// Martin & Moyce 1952 (Phil. Trans. R. Soc. A 244, 312-324), the collapse of a square column of
// water, a = 2.25 in: the surge front Z = z / a against T = t sqrt(2 g / a), as tabulated in
// their Table 2 (the values every dam-break validation reproduces).
constexpr double kMartinMoyceT[] = {0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32, 2.51, 2.65, 2.83, 2.98};
constexpr double kMartinMoyceZ[] = {1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78, 3.00, 3.22, 3.44, 3.67};

// A 10 cm square column of water 4 cm deep (a slab between two walls) at the end of a 50 cm tank,
// particles 5 mm apart (3,200).
DfsphSolver damBreak(double columnSize) {
  FluidParams params;
  params.particleRadius = 0.0025;
  const double spacing = 2.0 * params.particleRadius, depth = 0.04;
  return DfsphSolver(params, latticeBlock(Vec3d::Zero(), Vec3d(columnSize, columnSize, depth), spacing),
                     boundaryFromSamples(openBoxWalls(Vec3d::Zero(), Vec3d(0.5, 0.2, depth), spacing, 2),
                                         params.particleRadius));
}

// The front: the 99.5th percentile of the particles' distance along the tank plus a radius (a few
// particles thrown ahead are spray, not the surge front the experiment timed).
double surgeFront(const DfsphSolver& solver) {
  std::vector<double> xs;
  for (const Vec3d& x : solver.positions()) xs.push_back(x.x());
  std::sort(xs.begin(), xs.end());
  return xs[size_t(0.995 * double(xs.size() - 1))] + solver.params().particleRadius;
}

TEST(Dfsph, DamBreakFrontRunsAsMartinAndMoyceMeasured) {
  const double a = 0.1;
  DfsphSolver solver = damBreak(a);
  for (size_t k = 0; k < std::size(kMartinMoyceT); ++k) {
    solver.advanceTo(kMartinMoyceT[k] / std::sqrt(2.0 * kGravity / a));
    const double z = surgeFront(solver) / a;
    std::printf("[ dfsph ] T %.2f: Z %.2f, Martin & Moyce %.2f\n", kMartinMoyceT[k], z, kMartinMoyceZ[k]);
    // Early on every simulation runs ahead of the experiment, whose gate took time to lift (it is
    // ahead by 0.1-0.26 a here); once the surge is established the front agrees within 0.1 a
    // (measured: within 0.08).
    if (kMartinMoyceT[k] < 1.9) {
      EXPECT_GT(z, kMartinMoyceZ[k] - 0.05);
      EXPECT_LT(z, kMartinMoyceZ[k] + 0.3);
    } else {
      EXPECT_NEAR(z, kMartinMoyceZ[k], 0.1);
    }
    EXPECT_LE(solver.lastStep().densityError, solver.params().maxDensityError);
  }
}

TEST(Dfsph, EveryStepOfADamBreakEndsWithinTheDensityAndDivergenceTolerancesAndKeepsItsMass) {
  // The collapse's first 100 steps (the column falling and the surge starting, where the velocity
  // field changes most): both solves converge to their tolerances (0.1 % average compression; 0.1 %
  // average density change over a step), never stopped by the iteration cap. Mass is conserved
  // exactly: no particle is created, lost or reweighted, and none leaks out of the tank.
  DfsphSolver solver = damBreak(0.1);
  const size_t count = solver.positions().size();
  const double mass = solver.particleMass(), r = solver.params().particleRadius;
  int mostDensity = 0, mostDivergence = 0;
  for (int k = 0; k < 100; ++k) {
    solver.step();
    ASSERT_EQ(solver.positions().size(), count) << "step " << k;
    ASSERT_EQ(solver.particleMass(), mass) << "step " << k;
    for (const Vec3d& x : solver.positions())
      ASSERT_TRUE(x.x() > -r && x.x() < 0.5 + r && x.y() > -r && x.z() > -r && x.z() < 0.04 + r)
          << "step " << k << ": a particle at " << x.transpose() << " left the 50 x 20 x 4 cm tank";
    const StepStats& s = solver.lastStep();
    ASSERT_LE(s.densityError, solver.params().maxDensityError) << "step " << k;
    ASSERT_LE(s.divergenceError, solver.params().maxDivergenceError) << "step " << k;
    ASSERT_LT(s.densityIterations, solver.params().maxIterations) << "step " << k;
    ASSERT_LT(s.divergenceIterations, solver.params().maxIterations) << "step " << k;
    mostDensity = std::max(mostDensity, s.densityIterations);
    mostDivergence = std::max(mostDivergence, s.divergenceIterations);
  }
  std::printf("[ dfsph ] 100 steps to t = %.3f s: at most %d density and %d divergence iterations a step\n",
              solver.time(), mostDensity, mostDivergence);
}

TEST(Dfsph, TheSameRunWithOneThreadOrAll) {
  std::vector<Vec3d> one, all;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    DfsphSolver solver = damBreak(0.05);
    solver.advanceTo(0.05);
    one = solver.positions();
  }
  DfsphSolver solver = damBreak(0.05);
  solver.advanceTo(0.05);
  all = solver.positions();
  ASSERT_EQ(one.size(), all.size());
  for (size_t i = 0; i < one.size(); ++i) ASSERT_TRUE(one[i] == all[i]) << "particle " << i;
  EXPECT_GT((all[0] - latticeBlock(Vec3d::Zero(), Vec3d(0.05, 0.05, 0.04), 0.005)[0]).norm(), 1e-4);  // it moved
}

}  // namespace dfsph_test
}  // namespace lacrima::sph
