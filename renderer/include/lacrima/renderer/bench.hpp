#pragma once
// Raw Embree throughput on a Frame's geometry, the ceiling the path tracer is measured against.
#include <cstdint>

#include "lacrima/renderer/frame.hpp"

namespace lacrima {

struct RawTraceRates {
  uint64_t intersectRays = 0;
  double intersectSeconds = 0.0;
  uint64_t occludedRays = 0;
  double occludedSeconds = 0.0;
  double intersectRaysPerSecond() const { return intersectSeconds > 0 ? double(intersectRays) / intersectSeconds : 0; }
  double occludedRaysPerSecond() const { return occludedSeconds > 0 ? double(occludedRays) / occludedSeconds : 0; }
};

// Traces one jittered camera ray per pixel per sample (rtcIntersect1), then from every hit a
// cosine-distributed bounce direction (rtcIntersect1) and a shadow query towards a random
// direction (rtcOccluded1), in TBB tiles with frame.settings.threads threads, like the
// renderer. Only the Embree calls and the ray set-up are timed.
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
