// `lacrima bench`: renderer throughput against the raw Embree ceiling, same geometry, same
// threads, same run, then the cost before the first ray frame by frame (bench_frame_costs.hpp).
// Reports medians (the machine is noisy).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "bench_frame_costs.hpp"
#include "commands.hpp"
#include "frame_range.hpp"
#include "frame_selection.hpp"
#include "lacrima/renderer/bench.hpp"
#include "lacrima/renderer/render.hpp"
#include "lacrima/scenes/shot.hpp"
#include "median.hpp"
#include "progress.hpp"

namespace lacrima::cli {

namespace {

size_t triangleCount(const Frame& frame) {
  size_t count = 0;
  for (const MeshInstance& m : frame.meshes) count += m.mesh.triangleCount();
  return count;
}

// The frame with every mesh vertex moved by up to 0.05 mm in a direction that varies from
// vertex to vertex: a deformation between two frames of a face, same topology, so the Embree
// scene can be refitted (a still frame would leave nothing to refit).
Frame deformedCopy(const Frame& frame) {
  Frame deformed = frame;
  constexpr float kAmplitudeMetres = 5e-5f;
  for (MeshInstance& instance : deformed.meshes)
    for (size_t i = 0; i < instance.mesh.positions.size(); ++i) {
      const float k = float(i);
      instance.mesh.positions[i] += kAmplitudeMetres * Vec3(std::sin(k), std::cos(1.3f * k), std::sin(0.7f * k));
    }
  return deformed;
}

void printThroughput(const BenchOptions& o, const std::string& shotPath, const Shot& shot) {
  Frame frame = buildFrame(shot, shot.frameStart);
  frame.settings.width = o.width;
  frame.settings.height = o.height;
  frame.settings.samplesPerPixel = o.spp;
  frame.settings.threads = o.threads;
  std::printf("lacrima bench: %s frame %d, %dx%d, %d spp, threads %s, %zu triangles, %zu spheres, %d repetitions\n",
              shotPath.c_str(), shot.frameStart, o.width, o.height, o.spp,
              o.threads ? std::to_string(o.threads).c_str() : "all", triangleCount(frame), frame.spheres.size(),
              o.repetitions);
  const Frame deformed = deformedCopy(frame);
  std::vector<double> seconds, tracingSeconds, pathRates, rayRates, intersectRates, occludedRates, intersect16Rates,
      occluded16Rates, buildSeconds, refitSeconds;
  for (int r = 0; r < o.repetitions; ++r) {
    RenderStats stats;
    renderFrame(frame, &stats);
    seconds.push_back(stats.seconds);
    tracingSeconds.push_back(stats.tracingSeconds);
    // Over the path tracing alone, as the raw rates are over the queries alone: the scene build
    // is reported on its own below (at the default 4 spp it is as long as the tracing).
    pathRates.push_back(stats.cameraPaths / stats.tracingSeconds);
    rayRates.push_back(stats.rays / stats.tracingSeconds);
    const RawTraceRates raw = measureRawEmbreeThroughput(frame);
    intersectRates.push_back(raw.intersectRaysPerSecond());
    occludedRates.push_back(raw.occludedRaysPerSecond());
    intersect16Rates.push_back(raw.intersect16RaysPerSecond());
    occluded16Rates.push_back(raw.occluded16RaysPerSecond());
    const SceneUpdateTimes sceneTimes = measureSceneBuildAndRefit(frame, deformed);
    buildSeconds.push_back(sceneTimes.buildSeconds);
    refitSeconds.push_back(sceneTimes.refitSeconds);
  }
  const double renderRays = median(rayRates), rawIntersect = median(intersectRates);
  std::printf("render seconds        %.3f (median; scene build, set-up and path tracing)\n", median(seconds));
  std::printf("tracing seconds       %.3f (median; path tracing alone)\n", median(tracingSeconds));
  std::printf("paths/s               %s (over the tracing seconds)\n", formatRate(median(pathRates)).c_str());
  std::printf("renderer rays/s       %s (intersect + occluded queries, with shading, over the tracing seconds)\n",
              formatRate(renderRays).c_str());
  std::printf("raw rtcIntersect1/s   %s (camera + bounce rays, no shading)\n", formatRate(rawIntersect).c_str());
  std::printf("raw rtcOccluded1/s    %s\n", formatRate(median(occludedRates)).c_str());
  std::printf("renderer / raw ratio  %.2f\n", rawIntersect > 0 ? renderRays / rawIntersect : 0.0);
  std::printf("raw rtcIntersect16/s  %s (the same rays in packets of 16: camera rays coherent, bounces not)\n",
              formatRate(median(intersect16Rates)).c_str());
  std::printf("raw rtcOccluded16/s   %s\n", formatRate(median(occluded16Rates)).c_str());
  std::printf("scene build seconds   %.4f (median; Embree device + BVH from scratch, first frame of a shot)\n",
              median(buildSeconds));
  std::printf("scene refit seconds   %.4f (median; every vertex moved, BVH refitted, later frames)\n",
              median(refitSeconds));
}

void printFrameCosts(const BenchOptions& o, const Shot& shot) {
  const std::vector<int> frames = o.costFrames ? selectShotFrames(o.costFrames, shot) : defaultFrameCostFrames(shot);
  RenderSettings settings;
  settings.width = o.width;
  settings.height = o.height;
  settings.samplesPerPixel = o.spp;
  settings.threads = o.threads;
  std::printf("frame costs: frames %s in this order, as lacrima render prepares them (one renderer, its scene kept), "
              "%dx%d, threads %s; ms per frame, B = scene built, U = scene updated (geometries replaced; medians of the scene columns leave B frames out, raw columns refitted frames only)\n",
              formatFrameList(frames).c_str(), o.width, o.height, o.threads ? std::to_string(o.threads).c_str() : "all");
  std::printf("%s", formatFrameCosts(measureFrameCosts(shot, frames, settings)).c_str());
}

}  // namespace

int runBench(const BenchOptions& o) {
  try {
    const std::string shotPath = o.shotPath.empty() ? defaultShot() : o.shotPath;
    const auto loadStart = std::chrono::steady_clock::now();
    const Shot shot = loadShot(shotPath);
    const double loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loadStart).count();
    if (!o.frameCostsOnly) printThroughput(o, shotPath, shot);
    std::printf("shot load seconds     %.3f (once per shot: assets, rig, skin refinement under details and along "
                "liquid trails, resolving)\n",
                loadSeconds);
    printFrameCosts(o, shot);
    return kExitOk;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
