// The frame loop: 32x32 tiles rendered in parallel with TBB. Every pixel sample draws its
// random numbers from (seed, frame, pixel, sample index, dimension) and each tile writes only
// its own pixels in a fixed order, so the image does not depend on the thread count or on the
// order in which tiles finish. The pixel filter is importance-sampled (pixel_filter.hpp), not
// splatted, for the same reason.
#include "lacrima/renderer/render.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>

#include "embree_scene.hpp"
#include "integrator.hpp"
#include "lacrima/geometry/error.hpp"
#include "lacrima/renderer/camera.hpp"
#include "lacrima/renderer/pixel_filter.hpp"
#include "light_sampler.hpp"
#include "sample_dimensions.hpp"

namespace lacrima {

namespace {

constexpr int kTileSize = 32;

void validateFrame(const Frame& frame) {
  const RenderSettings& s = frame.settings;
  if (s.width < 1 || s.height < 1 || s.samplesPerPixel < 1 || s.maxDepth < 0)
    throw InputError(fmt::format("cannot render {}x{} pixels at {} samples per pixel with max depth {}", s.width,
                                 s.height, s.samplesPerPixel, s.maxDepth));
  for (const MeshInstance& instance : frame.meshes) {
    const std::string defect = findMeshDefect(instance.mesh);
    if (!defect.empty()) throw InputError(fmt::format("mesh '{}': {}", instance.mesh.name, defect));
    if (instance.materialId >= frame.materials.size())
      throw InputError(fmt::format("mesh '{}' uses material {} of {}", instance.mesh.name, instance.materialId,
                                   frame.materials.size()));
  }
  for (const Sphere& sphere : frame.spheres)
    if (sphere.materialId >= frame.materials.size() || !(sphere.radius > 0.0f))
      throw InputError("a sphere has a non-positive radius or an unknown material");
}

struct TileRect {
  int x0, y0, x1, y1;
};

TileRect tileRect(int tileIndex, int width, int height) {
  const int tilesX = (width + kTileSize - 1) / kTileSize;
  const int x0 = (tileIndex % tilesX) * kTileSize;
  const int y0 = (tileIndex / tilesX) * kTileSize;
  return {x0, y0, std::min(x0 + kTileSize, width), std::min(y0 + kTileSize, height)};
}

// Beauty and alpha are filter-weighted; the AOVs (albedo, normal, depth) are plain averages over
// the samples that hit something, as before.
struct PixelResult {
  Color weightedRadiance = Color::Zero();  // sum of w L
  Color radiance = Color::Zero();          // sum of L
  float weightedCoverage = 0.0f;           // sum of w * hit
  float coverage = 0.0f;                   // sum of hit
  float weight = 0.0f;                     // sum of w
  int samples = 0;                         // finite radiance samples
  Color albedo = Color::Zero();
  Vec3 normal = Vec3::Zero();
  float depth = 0.0f;
  int depthSamples = 0;
};

// Distance along the camera's viewing axis (what compositors expect in Z).
float cameraDepth(const Camera& camera, const Ray& ray, float distance) {
  const Vec3 forward = -camera.cameraToWorld.linear().col(2).normalized();
  return distance * ray.direction.dot(forward);
}

class TileRenderer {
 public:
  TileRenderer(const Frame& frame, const PathIntegrator& integrator, const FilterSampler& filter, Film& film)
      : frame_(frame),
        integrator_(integrator),
        filter_(filter),
        film_(film),
        cameraRays_(frame.camera, frame.settings.width, frame.settings.height),
        hasMotion_(frame.hasMotion()) {}

  void renderTile(const TileRect& rect, PathCounters& counters, uint64_t& nonFinite) const {
    for (int y = rect.y0; y < rect.y1; ++y)
      for (int x = rect.x0; x < rect.x1; ++x) renderPixel(x, y, counters, nonFinite);
  }

 private:
  void renderPixel(int x, int y, PathCounters& counters, uint64_t& nonFinite) const {
    const RenderSettings& s = frame_.settings;
    PixelResult sum;
    for (int i = 0; i < s.samplesPerPixel; ++i) {
      PixelSampler sampler(s.sampler, s.seed, s.frameNumber, x, y, i, s.samplesPerPixel);
      // The point in the filter's footprint and the point on the lens: one 4D block
      // (sample_dimensions::kPixelAndLens), mapped monotonically, so both stay stratified.
      const std::array<float, 4> pixelAndLens = sampler.get4D();
      const FilterSample f = filter_.sample(Vec2(pixelAndLens[0], pixelAndLens[1]));
      const Vec2 lens(pixelAndLens[2], pixelAndLens[3]);
      sampler.setDimension(sample_dimensions::kTime);
      const float time = hasMotion_ ? sampler.get1D() : 0.0f;
      const Ray ray = cameraRays_.generate(float(x) + 0.5f + f.offset.x(), float(y) + 0.5f + f.offset.y(), lens, time);
      FirstHit first;
      Color L = integrator_.radiance(ray, sampler, first, counters);
      if (!isFinite(L)) {
        L = Color::Zero();  // discarded, counted, reported: never on the film (the sample counts as black)
        ++nonFinite;
      }
      sum.weightedRadiance += f.weight * L;
      sum.radiance += L;
      sum.weight += f.weight;
      ++sum.samples;
      if (first.valid) {
        sum.weightedCoverage += f.weight;
        sum.coverage += 1.0f;
        sum.albedo += first.albedo;
        sum.normal += first.normal;
        sum.depth += cameraDepth(frame_.camera, ray, first.distance);
        ++sum.depthSamples;
      }
    }
    store(x, y, sum);
  }

  void store(int x, int y, const PixelResult& sum) const {
    const size_t p = film_.pixelIndex(x, y);
    const Filtered f = filtered(sum);
    for (int c = 0; c < 3; ++c) film_.rgba[4 * p + c] = f.radiance[c];
    film_.rgba[4 * p + 3] = f.alpha;
    const float invHits = sum.depthSamples > 0 ? 1.0f / float(sum.depthSamples) : 0.0f;
    for (int c = 0; c < 3; ++c) film_.albedo[3 * p + c] = sum.albedo[c] * invHits;
    const Vec3 n = sum.normal.norm() > 0.0f ? Vec3(sum.normal.normalized()) : Vec3::Zero();
    for (int c = 0; c < 3; ++c) film_.normal[3 * p + c] = n[c];
    film_.depth[p] = sum.depthSamples > 0 ? sum.depth * invHits : std::numeric_limits<float>::infinity();
  }

  struct Filtered {
    Color radiance;
    float alpha;
  };

  // The pixel is the weighted average sum(w L) / sum(w) (pbrt-v4's RGBFilm does the same), not
  // sum(w L) / N: both are consistent, but the ratio reproduces a constant radiance exactly
  // whatever the weights, so a flat sky keeps no noise from a filter's negative lobes. Without
  // negative lobes every w is exactly 1 and this is the plain mean, bitwise. With them (Mitchell),
  // w = +-c and sum(w) can be 0 or negative with few samples (2 samples of opposite signs); such a
  // pixel takes the plain mean instead, the estimate of the filter |f|.
  static Filtered filtered(const PixelResult& sum) {
    if (sum.samples == 0) return {Color::Zero(), 0.0f};
    if (sum.weight > 0.0f) {
      const float inv = 1.0f / sum.weight;
      // Coverage is a fraction: a negative lobe may ring the colour but not the alpha past [0, 1].
      return {sum.weightedRadiance * inv, std::clamp(sum.weightedCoverage * inv, 0.0f, 1.0f)};
    }
    const float inv = 1.0f / float(sum.samples);
    return {sum.radiance * inv, sum.coverage * inv};
  }

  const Frame& frame_;
  const PathIntegrator& integrator_;
  const FilterSampler& filter_;
  Film& film_;
  CameraRays cameraRays_;
  bool hasMotion_;
};

}  // namespace

Renderer::Renderer() = default;
Renderer::~Renderer() = default;

// Runs inside the frame's task arena: Embree's BVH builders use the calling TBB arena.
SceneUpdate Renderer::updateScene(const Frame& frame) {
  const int threads = frame.settings.threads;
  try {
    if (scene_ && scene_->canRefitTo(frame, threads)) {
      scene_->refitTo(frame);
      return SceneUpdate::Refit;
    }
    scene_.reset();  // release the old device before creating the next
    scene_ = std::make_unique<EmbreeScene>(frame, threads);
    return SceneUpdate::Build;
  } catch (...) {
    scene_.reset();  // a half-updated scene must not serve the next frame
    throw;
  }
}

Film Renderer::render(const Frame& frame, RenderStats* stats, const ProgressCallback& progress,
                      const std::atomic<bool>* cancel) {
  validateFrame(frame);
  const auto start = std::chrono::steady_clock::now();
  const RenderSettings& s = frame.settings;
  tbb::task_arena arena(s.threads > 0 ? s.threads : tbb::task_arena::automatic);

  Film film(s.width, s.height);
  const int tilesX = (s.width + kTileSize - 1) / kTileSize;
  const int tilesY = (s.height + kTileSize - 1) / kTileSize;
  const int tileCount = tilesX * tilesY;
  std::atomic<uint64_t> rays{0}, nonFinite{0};
  std::atomic<int> tilesDone{0};
  std::mutex progressMutex;
  SceneUpdate sceneUpdate = SceneUpdate::Build;
  double sceneUpdateSeconds = 0.0, tracingSeconds = 0.0;

  arena.execute([&] {
    const auto updateStart = std::chrono::steady_clock::now();
    sceneUpdate = updateScene(frame);
    sceneUpdateSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - updateStart).count();
    const EmbreeScene& scene = *scene_;
    const LightSampler lights(frame);
    const PathIntegrator integrator(frame, scene, lights);
    const FilterSampler filter(s.filter);
    const TileRenderer tiles(frame, integrator, filter, film);
    const auto tracingStart = std::chrono::steady_clock::now();
    tbb::parallel_for(tbb::blocked_range<int>(0, tileCount, 1), [&](const tbb::blocked_range<int>& range) {
      for (int t = range.begin(); t != range.end(); ++t) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return;  // skip what is left, cheaply
        PathCounters counters;
        uint64_t tileNonFinite = 0;
        tiles.renderTile(tileRect(t, s.width, s.height), counters, tileNonFinite);
        rays += counters.rays;
        nonFinite += tileNonFinite;
        const int done = ++tilesDone;
        if (progress) {
          const std::lock_guard lock(progressMutex);
          const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          progress(RenderProgress{done, tileCount, elapsed, rays.load()});
        }
      }
    });
    tracingSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tracingStart).count();
  });
  if (cancel && cancel->load()) throw RenderCancelled();

  if (stats) {
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->tracingSeconds = tracingSeconds;
    stats->cameraPaths = uint64_t(s.width) * s.height * s.samplesPerPixel;
    stats->rays = rays.load();
    stats->nonFiniteSamples = nonFinite.load();
    stats->sceneUpdate = sceneUpdate;
    stats->sceneUpdateSeconds = sceneUpdateSeconds;
  }
  return film;
}

Film renderFrame(const Frame& frame, RenderStats* stats, const ProgressCallback& progress,
                 const std::atomic<bool>* cancel) {
  Renderer renderer;
  return renderer.render(frame, stats, progress, cancel);
}

}  // namespace lacrima
