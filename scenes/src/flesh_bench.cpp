#include "lacrima/scenes/flesh_bench.hpp"

#include <fmt/format.h>

#include <chrono>

#include "frame/flesh_frame.hpp"
#include "lacrima/flesh/flesh_volume_cache.hpp"
#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

FleshBenchResult measureFleshFrames(const Shot& shot, double tetSize, int lastFrame) {
  if (shot.flesh.empty() || !shot.flesh.front().tetVolume) throw InputError("bench --flesh: the shot simulates no flesh");
  ShotFlesh flesh = shot.flesh.front();
  flesh.volume.maxTetVolume = flesh::regularTetVolume(tetSize);  // as the shot's "tetSize"
  FleshBenchResult result;
  result.tetSize = tetSize;
  const auto volumeStart = std::chrono::steady_clock::now();
  try {
    flesh.tetVolume = std::make_shared<const flesh::FleshVolume>(
        flesh::cachedFleshVolume(*flesh.patch, flesh.volume, shotfile::fleshCacheDirectory()));
  } catch (const flesh::FleshVolumeError& e) {
    throw InputError(fmt::format("bench --flesh: no volume at tetSize {}: {}", tetSize, e.what()));
  }
  result.volumeSeconds = secondsSince(volumeStart);
  result.nodes = flesh.tetVolume->mesh.nodes.size();
  result.tetrahedra = flesh.tetVolume->mesh.tets.size();
  for (bool kinematic : flesh.tetVolume->kinematic) result.freeNodes += kinematic ? 0 : 1;
  shotfile::FleshRun run(shot, flesh, shotfile::FleshRun::StateFiling::Off);
  for (int frame = shot.frameStart + 1; frame <= lastFrame; ++frame) {
    const auto start = std::chrono::steady_clock::now();
    run.nodeOffsetsAt(frame);
    result.frames.push_back({frame, secondsSince(start)});
  }
  const shotfile::FleshRunCounts counts = run.counts();
  result.steps = counts.steps;
  result.newtonIterations = counts.newtonIterations;
  result.conjugateGradientIterations = counts.conjugateGradientIterations;
  return result;
}

}  // namespace lacrima
