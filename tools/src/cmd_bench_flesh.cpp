// `lacrima bench --flesh`: what the simulated flesh costs a frame, at chosen resolutions of its
// volume (the ICT face at about 20k and 100k tetrahedra, say). Each size is simulated
// from the shot's first frame, every step, states not filed; the report gives the median and
// slowest frame, and the Newton and conjugate-gradient iterations a step took.
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "commands.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/scenes/flesh_bench.hpp"
#include "lacrima/scenes/shot.hpp"
#include "median.hpp"

namespace lacrima::cli {

namespace {

void printRow(const FleshBenchResult& r) {
  std::vector<double> ms;
  for (const FleshFrameCost& f : r.frames) ms.push_back(1e3 * f.seconds);
  const double steps = std::max<double>(1.0, double(r.steps));
  std::printf("%9.4f %9zu %9zu %9zu %10.2f %9zu %11.1f %11.1f %9.2f %9.1f\n", r.tetSize, r.tetrahedra, r.nodes,
              r.freeNodes, r.volumeSeconds, r.frames.size(), median(ms),
              ms.empty() ? 0.0 : *std::max_element(ms.begin(), ms.end()), double(r.newtonIterations) / steps,
              double(r.conjugateGradientIterations) / steps);
}

}  // namespace

int runBenchFlesh(const BenchOptions& o) {
  try {
    const std::string shotPath = o.shotPath.empty() ? defaultShot() : o.shotPath;
    const Shot shot = loadShot(shotPath);
    const int lastFrame = o.frame.value_or(shot.frameEnd);
    if (lastFrame <= shot.frameStart)
      throw InputError("bench --flesh: --frame must come after the shot's first frame " + std::to_string(shot.frameStart));
    tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
    std::printf("lacrima bench --flesh: %s, frames %d-%d simulated from the first, threads %s\n", shotPath.c_str(),
                shot.frameStart, lastFrame, o.threads ? std::to_string(o.threads).c_str() : "all");
    std::printf("  tetSize      tets     nodes      free  volume s    frames  median ms  slowest ms  newton/st    cg/st\n");
    for (double tetSize : o.tetSizes) {
      FleshBenchResult result;
      arena.execute([&] { result = measureFleshFrames(shot, tetSize, lastFrame); });
      printRow(result);
      std::fflush(stdout);
    }
    return kExitOk;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
