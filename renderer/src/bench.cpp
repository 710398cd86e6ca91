#include "lacrima/renderer/bench.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>

#include "embree_scene.hpp"
#include "lacrima/geometry/error.hpp"
#include "lacrima/geometry/sampler.hpp"
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

template <typename Query>
double timeQueries(const std::vector<Ray>& rays, Query query) {
  std::atomic<int> sink{0};
  const auto start = std::chrono::steady_clock::now();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
    int hits = 0;
    for (size_t i = r.begin(); i != r.end(); ++i) hits += query(rays[i]) ? 1 : 0;
    sink += hits;
  });
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
    rates.intersectSeconds = timeQueries(all, intersect);
    rates.occludedRays = rays.bounce.size();
    rates.occludedSeconds = timeQueries(rays.bounce, occluded);
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
    scene.refitTo(deformed);
    times.refitSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - refitStart).count();
  });
  return times;
}

}  // namespace lacrima
