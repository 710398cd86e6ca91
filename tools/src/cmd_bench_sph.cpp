// `lacrima bench --sph`: what the SPH liquid costs (particle updates per second at 100k
// particles on 2 cores, say). A dam break (a water block at one end of a tank three times its
// length, 2.5 mm particles) is stepped for --steps steps after one unmeasured step; the report gives
// the median step, the particle updates per second over the measured steps, the solvers'
// iterations, and the milliseconds to surface the liquid for a frame (sph_surface.hpp).
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "commands.hpp"
#include "lacrima/sph/dfsph.hpp"
#include "lacrima/sph/sph_surface.hpp"

namespace lacrima::cli {

namespace {

// A block of about `count` particles, twice as long and as high as it is deep.
sph::DfsphSolver damBreakOf(size_t count) {
  sph::FluidParams params;
  const double spacing = 2.0 * params.particleRadius;
  const double depthCells = std::max(1.0, std::round(std::cbrt(double(count) / 4.0)));
  const Vec3d block = spacing * Vec3d(2.0 * depthCells, 2.0 * depthCells, depthCells);
  const Vec3d tank(3.0 * block.x(), 2.0 * block.y(), block.z());
  return sph::DfsphSolver(params, sph::latticeBlock(Vec3d::Zero(), block, spacing),
                          sph::boundaryFromSamples(sph::openBoxWalls(Vec3d::Zero(), tank, spacing, 2), params.particleRadius));
}

}  // namespace

int runBenchSph(const BenchOptions& o) {
  tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
  arena.execute([&] {
    const auto buildStart = std::chrono::steady_clock::now();
    sph::DfsphSolver solver = damBreakOf(size_t(o.sphParticles));
    const double buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count();
    std::printf("lacrima bench --sph: dam break, %zu particles (2.5 mm), threads %s, set-up %.2f s\n",
                solver.positions().size(), o.threads ? std::to_string(o.threads).c_str() : "all", buildSeconds);
    solver.step();  // not measured: the first step's allocations
    std::vector<double> stepMs;
    double densityIterations = 0.0, divergenceIterations = 0.0, simulated = 0.0;
    for (int s = 0; s < o.sphSteps; ++s) {
      const auto start = std::chrono::steady_clock::now();
      solver.step();
      stepMs.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      densityIterations += solver.lastStep().densityIterations;
      divergenceIterations += solver.lastStep().divergenceIterations;
      simulated += solver.lastStep().timeStep;
    }
    double total = 0.0;
    for (double ms : stepMs) total += ms;
    std::sort(stepMs.begin(), stepMs.end());
    const double steps = double(stepMs.size());
    std::printf("steps                 %zu (%.1f ms of simulated time)\n", stepMs.size(), 1e3 * simulated);
    std::printf("step ms               %.1f median, %.1f slowest\n", stepMs[stepMs.size() / 2], stepMs.back());
    std::printf("particle updates/s    %.3g (particles x steps over the measured seconds)\n",
                double(solver.positions().size()) * steps / (1e-3 * total));
    std::printf("iterations a step     %.1f density, %.1f divergence\n", densityIterations / steps,
                divergenceIterations / steps);
    // Surfacing, as each rendered frame would (median of 3).
    std::vector<double> surfaceMs;
    size_t triangles = 0;
    for (int k = 0; k < 3; ++k) {
      const auto start = std::chrono::steady_clock::now();
      triangles = sph::surfaceOfParticles(solver.positions(), solver.params().particleRadius).triangleCount();
      surfaceMs.push_back(1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(surfaceMs.begin(), surfaceMs.end());
    std::printf("surfacing ms          %.1f median of 3 (OpenVDB level set, smoothed, meshed: %zu triangles)\n",
                surfaceMs[1], triangles);
  });
  return kExitOk;
}

}  // namespace lacrima::cli
