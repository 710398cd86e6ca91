#pragma once
// Raw Embree throughput on a Frame's geometry, the ceiling the path tracer is measured against.
#include <cstdint>
#include <memory>

#include "lacrima/renderer/film.hpp"
#include "lacrima/renderer/frame.hpp"

namespace lacrima {

struct RawTraceRates {
  uint64_t intersectRays = 0;
  double intersectSeconds = 0.0;
  uint64_t occludedRays = 0;
  double occludedSeconds = 0.0;
  // The same rays in packets of 16 (rtcIntersect16 / rtcOccluded16; camera rays flagged coherent,
  // bounces incoherent): what a renderer that traced its rays in packets would get from Embree.
  double intersect16Seconds = 0.0;
  double occluded16Seconds = 0.0;
  // How many of the queries hit, each way (the same counts: both ways trace the same rays).
  uint64_t intersectHits = 0, intersect16Hits = 0, occludedHits = 0, occluded16Hits = 0;
  double intersectRaysPerSecond() const { return intersectSeconds > 0 ? double(intersectRays) / intersectSeconds : 0; }
  double occludedRaysPerSecond() const { return occludedSeconds > 0 ? double(occludedRays) / occludedSeconds : 0; }
  double intersect16RaysPerSecond() const {
    return intersect16Seconds > 0 ? double(intersectRays) / intersect16Seconds : 0;
  }
  double occluded16RaysPerSecond() const { return occluded16Seconds > 0 ? double(occludedRays) / occluded16Seconds : 0; }
};

// Traces one jittered camera ray per pixel per sample (rtcIntersect1), then from every hit a
// cosine-distributed bounce direction (rtcIntersect1) and a shadow query towards a random
// direction (rtcOccluded1), in TBB tiles with frame.settings.threads threads, like the
// renderer; then the same rays again in packets of 16. Only the Embree calls and the ray set-up
// are timed.
RawTraceRates measureRawEmbreeThroughput(const Frame& frame);

struct SceneUpdateTimes {
  double buildSeconds = 0.0;  // the Embree scene of `frame` from scratch (device included)
  double refitSeconds = 0.0;  // then moved to `deformed` and refitted, as Renderer does
};

// Times what Renderer spends on the Embree scene of the first frame of a shot and of every
// later frame with the same geometry layout, with frame.settings.threads threads. `deformed`
// must have the layout of `frame` (InputError otherwise).
SceneUpdateTimes measureSceneBuildAndRefit(const Frame& frame, const Frame& deformed);

}  // namespace lacrima

// ---- The cost before the first ray, frame after frame (lacrima bench's frame report) ----------

namespace lacrima {

class EmbreeScene;  // renderer/src/embree_scene.hpp
class Renderer;     // lacrima/renderer/render.hpp

// One scene update, as Renderer makes it.
struct SceneUpdateSplit {
  SceneUpdate kind = SceneUpdate::Build;  // a build: the first frame (or another thread count)
  double uploadSeconds = 0.0;  // refit or update: vertices and added geometries' buffers copied into Embree's (0 for a build)
  double bvhSeconds = 0.0;     // refit or update: the commits that refit or rebuild the BVHs; build: all of it
  double totalSeconds() const { return uploadSeconds + bvhSeconds; }
};

// Follows the frames of a shot as Renderer does (a build on the first, then a refit while the
// geometry layout stays, an update of the changed geometries when it does not) with frame.settings.threads threads, timing the parts of each update. A frame
// must outlive the next update.
class SceneUpdateProbe {
 public:
  SceneUpdateProbe();
  ~SceneUpdateProbe();
  SceneUpdateProbe(const SceneUpdateProbe&) = delete;
  SceneUpdateProbe& operator=(const SceneUpdateProbe&) = delete;
  SceneUpdateSplit update(const Frame& frame);

 private:
  std::unique_ptr<EmbreeScene> scene_;
};

// The wall seconds of renderer.render(frame) up to its first ray: frame checks, the scene update,
// the light sampler and the integrator (measured as a render whose cancel flag is set before it
// starts: every tile is skipped).
double secondsBeforeFirstRay(Renderer& renderer, const Frame& frame);

// Raw Embree on the triangle meshes alone, no lacrima code between: a device with
// frame.settings.threads threads, the renderer's scene flags (two-level BVH, robust), one
// geometry per mesh with build quality REFIT and its own vertex and index buffers, committed at
// `from`'s positions; then the meshes whose positions differ are given `to`'s positions and only
// the commits are timed (rtcCommitGeometry of each, rtcCommitScene). `from` and `to` must have
// the same meshes, vertex and triangle counts (InputError otherwise).
struct RawRefitTimes {
  double sameTimeStepsSeconds = 0.0;  // each mesh with the frames' time steps (two when it moves)
  double oneTimeStepSeconds = 0.0;    // every mesh with its shutter-open positions only
  size_t triangles = 0;
};
RawRefitTimes measureRawEmbreeRefit(const Frame& from, const Frame& to);

}  // namespace lacrima
