#include "lacrima/renderer/bench.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>

#include "embree_scene.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/renderer/sampler.hpp"
#include "lacrima/materials/sampling.hpp"
#include "lacrima/renderer/camera.hpp"

namespace lacrima {

namespace {

struct RaySet {
  std::vector<Ray> primary;
  std::vector<Ray> bounce;
};

Vec3 cosineDirection(const Vec3& normal, const Vec2& u) {
  return ShadingFrame::fromNormal(normal).toWorld(sampleCosineHemisphere(u));
}

RaySet makeRays(const Frame& frame, const EmbreeScene& scene) {
  const RenderSettings& s = frame.settings;
  RaySet rays;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      for (int i = 0; i < s.samplesPerPixel; ++i) {
        PixelSampler sampler(s.seed, s.frameNumber, x, y, i);
        const Vec2 jitter = sampler.get2D();
        const Ray ray = generateCameraRay(frame.camera, s.width, s.height, x + jitter.x(), y + jitter.y(), sampler.get2D());
        rays.primary.push_back(ray);
        SurfaceHit hit;
        if (!scene.intersect(ray, hit)) continue;
        const Vec3 n = hit.geometricNormal.dot(ray.direction) < 0 ? hit.geometricNormal : Vec3(-hit.geometricNormal);
        rays.bounce.push_back(Ray{hit.position + 1e-4f * n, cosineDirection(n, sampler.get2D())});
      }
  return rays;
}

// Seconds a set of queries took, and how many of them hit (which checks that two ways of asking
// asked the same).
struct QueryTiming {
  double seconds = 0.0;
  uint64_t hits = 0;
};

// Runs count(i) for i in [0, n) split between the threads, `grain` at a time, and times it;
// count(i) returns how many of its queries hit.
template <typename Count>
QueryTiming timeInParallel(size_t n, size_t grain, Count count) {
  std::atomic<uint64_t> sink{0};
  const auto start = std::chrono::steady_clock::now();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, grain), [&](const tbb::blocked_range<size_t>& r) {
    uint64_t hits = 0;
    for (size_t i = r.begin(); i != r.end(); ++i) hits += count(i);
    sink += hits;
  });
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), sink.load()};
}

template <typename Query>
QueryTiming timeQueries(const std::vector<Ray>& rays, Query query) {
  return timeInParallel(rays.size(), 4096, [&](size_t i) { return query(rays[i]) ? 1u : 0u; });
}

constexpr size_t kLanes = 16;

// The rays in packets of 16 (the last one's unused lanes masked off): query(first, count) traces
// one packet and returns its hits. The same number of rays a task as timeQueries.
template <typename PacketQuery>
QueryTiming timePackets(const std::vector<Ray>& rays, PacketQuery query) {
  const size_t packets = (rays.size() + kLanes - 1) / kLanes;
  return timeInParallel(packets, 4096 / kLanes, [&](size_t p) {
    return query(&rays[p * kLanes], std::min(kLanes, rays.size() - p * kLanes));
  });
}

// Fills lane i of a packet's SoA rays (RTCRay16 or the ray of RTCRayHit16) from `ray`, t in [0, inf).
template <typename Ray16>
void setLane(Ray16& r, int i, const Ray& ray) {
  r.org_x[i] = ray.origin.x();
  r.org_y[i] = ray.origin.y();
  r.org_z[i] = ray.origin.z();
  r.dir_x[i] = ray.direction.x();
  r.dir_y[i] = ray.direction.y();
  r.dir_z[i] = ray.direction.z();
  r.tnear[i] = 0.0f;
  r.tfar[i] = std::numeric_limits<float>::infinity();
  r.time[i] = 0.0f;
  r.mask[i] = 0xFFFFFFFFu;
  r.id[i] = 0;
  r.flags[i] = 0;
}

// Lanes [0, count) of a packet hold first[0..count), valid; the others stay masked off.
template <typename Ray16>
void fillPacket(Ray16& packet, int (&valid)[kLanes], const Ray* first, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    valid[i] = -1;
    setLane(packet, int(i), first[i]);
  }
}

// A context whose flag tells Embree whether a packet's rays run together (camera rays through
// neighbouring pixels) or not (bounces).
RTCIntersectContext contextWithFlags(RTCIntersectContextFlags flags) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = flags;
  return context;
}

QueryTiming timeIntersect16(RTCScene handle, const std::vector<Ray>& rays, RTCIntersectContextFlags flags) {
  return timePackets(rays, [&](const Ray* first, size_t count) {
    RTCIntersectContext context = contextWithFlags(flags);
    alignas(64) int valid[kLanes] = {};
    alignas(64) RTCRayHit16 rh{};
    fillPacket(rh.ray, valid, first, count);
    for (unsigned& geometry : rh.hit.geomID) geometry = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect16(valid, handle, &context, &rh);
    uint64_t hits = 0;
    for (size_t i = 0; i < count; ++i) hits += rh.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID ? 1 : 0;
    return hits;
  });
}

QueryTiming timeOccluded16(RTCScene handle, const std::vector<Ray>& rays, RTCIntersectContextFlags flags) {
  return timePackets(rays, [&](const Ray* first, size_t count) {
    RTCIntersectContext context = contextWithFlags(flags);
    alignas(64) int valid[kLanes] = {};
    alignas(64) RTCRay16 r{};
    fillPacket(r, valid, first, count);
    rtcOccluded16(valid, handle, &context, &r);
    uint64_t hits = 0;
    for (size_t i = 0; i < count; ++i) hits += r.tfar[i] < 0.0f ? 1 : 0;
    return hits;
  });
}

}  // namespace

RawTraceRates measureRawEmbreeThroughput(const Frame& frame) {
  tbb::task_arena arena(frame.settings.threads > 0 ? frame.settings.threads : tbb::task_arena::automatic);
  RawTraceRates rates;
  arena.execute([&] {
    const EmbreeScene scene(frame, frame.settings.threads);
    const RaySet rays = makeRays(frame, scene);
    const RTCScene handle = scene.handle();
    auto intersect = [handle](const Ray& ray) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRayHit rh{};
      rh.ray = {ray.origin.x(), ray.origin.y(), ray.origin.z(), 0.0f, ray.direction.x(), ray.direction.y(),
                ray.direction.z(), 0.0f, std::numeric_limits<float>::infinity(), 0xFFFFFFFFu, 0, 0};
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(handle, &context, &rh);
      return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    };
    auto occluded = [handle](const Ray& ray) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRay r{ray.origin.x(), ray.origin.y(), ray.origin.z(), 0.0f, ray.direction.x(), ray.direction.y(),
               ray.direction.z(), 0.0f, std::numeric_limits<float>::infinity(), 0xFFFFFFFFu, 0, 0};
      rtcOccluded1(handle, &context, &r);
      return r.tfar < 0.0f;
    };
    std::vector<Ray> all = rays.primary;
    all.insert(all.end(), rays.bounce.begin(), rays.bounce.end());
    rates.intersectRays = all.size();
    const QueryTiming intersect1 = timeQueries(all, intersect);
    rates.intersectSeconds = intersect1.seconds;
    rates.intersectHits = intersect1.hits;
    rates.occludedRays = rays.bounce.size();
    const QueryTiming occluded1 = timeQueries(rays.bounce, occluded);
    rates.occludedSeconds = occluded1.seconds;
    rates.occludedHits = occluded1.hits;
    const QueryTiming primary16 = timeIntersect16(handle, rays.primary, RTC_INTERSECT_CONTEXT_FLAG_COHERENT);
    const QueryTiming bounce16 = timeIntersect16(handle, rays.bounce, RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT);
    rates.intersect16Seconds = primary16.seconds + bounce16.seconds;
    rates.intersect16Hits = primary16.hits + bounce16.hits;
    const QueryTiming occluded16 = timeOccluded16(handle, rays.bounce, RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT);
    rates.occluded16Seconds = occluded16.seconds;
    rates.occluded16Hits = occluded16.hits;
  });
  return rates;
}

SceneUpdateTimes measureSceneBuildAndRefit(const Frame& frame, const Frame& deformed) {
  const int threads = frame.settings.threads;
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  SceneUpdateTimes times;
  arena.execute([&] {
    const auto buildStart = std::chrono::steady_clock::now();
    EmbreeScene scene(frame, threads);
    times.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count();
    if (!scene.canRefitTo(deformed, threads))
      throw InputError("bench: the deformed frame does not have the geometry layout of the frame");
    const auto refitStart = std::chrono::steady_clock::now();
    scene.follow(deformed);
    times.refitSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - refitStart).count();
  });
  return times;
}

}  // namespace lacrima
