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
#include <variant>

#include "embree_scene.hpp"
#include "lacrima/renderer/adaptive_sampling.hpp"
#include "lacrima/renderer/denoiser.hpp"
#include "lacrima/renderer/light_groups.hpp"
#include "lacrima/renderer/light_paths.hpp"
#include "lacrima/renderer/pixel_sums.hpp"
#include "integrator.hpp"
#include "lacrima/base/error.hpp"
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
  const PixelRegion& r = s.region;
  if (!r.empty() && (r.x < 0 || r.y < 0 || r.x + r.width > s.width || r.y + r.height > s.height))
    throw InputError(fmt::format("the region {}x{} at ({}, {}) does not lie within the {}x{} frame", r.width, r.height,
                                 r.x, r.y, s.width, s.height));
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

int tileCountOf(int width, int height) {
  return ((width + kTileSize - 1) / kTileSize) * ((height + kTileSize - 1) / kTileSize);
}

TileRect tileRect(int tileIndex, int width, int height) {
  const int tilesX = (width + kTileSize - 1) / kTileSize;
  const int x0 = (tileIndex % tilesX) * kTileSize;
  const int y0 = (tileIndex / tilesX) * kTileSize;
  return {x0, y0, std::min(x0 + kTileSize, width), std::min(y0 + kTileSize, height)};
}

// Distance along the camera's viewing axis (what compositors expect in Z).
float cameraDepth(const Camera& camera, const Ray& ray, float distance) {
  const Vec3 forward = -camera.cameraToWorld.linear().col(2).normalized();
  return distance * ray.direction.dot(forward);
}

// The camera the tiles use: with focusOnSurface, focused on the first surface its view axis meets
// at mid-shutter (one ray from the lens centre through the image centre), else as given.
Camera focusedCamera(const Camera& camera, const EmbreeScene& scene) {
  Camera focused = camera;
  if (!camera.focusOnSurface || camera.lensRadius <= 0.0f) return focused;  // a pinhole has no focus
  const Affine3 placement = cameraToWorldAt(camera, 0.5f);
  const Ray axis{placement.translation(), (placement.linear() * Vec3(0.0f, 0.0f, -1.0f)).normalized(), 0.5f};
  SurfaceHit hit;
  if (scene.intersect(axis, hit) && hit.rayDistance > 0.0f) focused.focusDistance = hit.rayDistance;
  return focused;
}

// Cryptomatte's layers in the film (cryptomatte.hpp): per type, its IDs by name index and the
// film layer its ranks go to.
struct CryptomatteLayer {
  std::vector<float> ids;     // cryptomatteIdOf(name) of each name
  FilmLayer* layer = nullptr;
};

// Adds the film layer and header attributes of a Cryptomatte type named `type` over `names`.
CryptomatteLayer addCryptomatteLayer(Film& film, const std::string& type, const std::vector<std::string>& names,
                                     const std::vector<std::string>& manifest, int ranks) {
  FilmLayer layer;
  for (int sub = 0; sub < ranks / 2; ++sub)
    for (const char* c : {"R", "G", "B", "A"}) layer.channels.push_back(fmt::format("{}{:02d}.{}", type, sub, c));
  layer.data.assign(size_t(film.width) * film.height * layer.channels.size(), 0.0f);
  film.layers.push_back(std::move(layer));  // into room the caller reserved
  const std::string prefix = "cryptomatte/" + cryptomatteKey(type) + "/";
  film.attributes[prefix + "name"] = type;
  film.attributes[prefix + "hash"] = "MurmurHash3_32";
  film.attributes[prefix + "conversion"] = "uint32_to_float32";
  film.attributes[prefix + "manifest"] = cryptomatteManifest(manifest);
  CryptomatteLayer out;
  for (const std::string& name : names) out.ids.push_back(cryptomatteIdOf(name));
  out.layer = &film.layers.back();
  return out;
}

class TileRenderer {
 public:
  // `camera`: the frame's, focused (focusedCamera); it must outlive the tiles.
  TileRenderer(const Frame& frame, const Camera& camera, const PathIntegrator& integrator, const FilterSampler& filter,
               Film& film)
      : frame_(frame),
        integrator_(integrator),
        filter_(filter),
        film_(film),
        cameraRays_(camera, frame.settings.width, frame.settings.height),
        hasMotion_(frame.hasMotion()),
        order_(frame.settings.adaptive.enabled || frame.settings.denoise ? SampleOrder::Progressive
                                                                          : SampleOrder::Shuffled) {
    // Every further layer is added here, into room reserved first: their addresses are kept.
    film.layers.reserve(integrator.lightGroups().size() + kLightPathCount + 2);
    if (frame.settings.lightGroups) addLightGroupLayers(film, integrator.lightGroups());
    if (frame.settings.lightPaths.any()) addLightPathLayers(film, frame.settings.lightPaths);
    // The denoiser filters the subsurface light apart: the integrator splits it off like a
    // light-path pass, written or not.
    splitSubsurface_ = frame.settings.denoise && hasSubsurface(frame.materials);
    if (splitSubsurface_ && !frame.settings.lightPaths.any()) splitLayers_.resize(groupCount_ + kLightPathCount, nullptr);
    const CryptomatteSettings& crypto = frame.settings.cryptomatte;
    if (!crypto.any()) return;
    const CryptomatteNames names = cryptomatteNames(frame);
    if (crypto.objects) objects_ = addCryptomatteLayer(film, "CryptoObject", names.objects, names.objects, crypto.ranks);
    if (crypto.materials)
      materials_ = addCryptomatteLayer(film, "CryptoMaterial", names.materials, names.materialManifest, crypto.ranks);
  }

  // Where store() also writes each pixel's two half buffers (null: nowhere), and those of its
  // subsurface light when the denoiser filters that apart (splitsSubsurface()).
  void keepHalvesIn(DenoiseInput* halves) { halves_ = halves; }
  bool splitsSubsurface() const { return splitSubsurface_; }

  // Every pixel of the tile with all its samples (no adaptive sampling).
  void renderTile(const TileRect& rect, PathCounters& counters, uint64_t& nonFinite) const {
    for (int y = rect.y0; y < rect.y1; ++y)
      for (int x = rect.x0; x < rect.x1; ++x) {
        PixelSums sum;
        addSamples(x, y, frame_.settings.samplesPerPixel, sum, counters, nonFinite);
        store(x, y, sum);
      }
  }

  // The pixel's samples from sum.samples up to (not including) `end`, added to its sums. (x, y):
  // the film's pixel (of the region, when rendering one).
  void addSamples(int x, int y, int end, PixelSums& sum, PathCounters& counters, uint64_t& nonFinite) const {
    const RenderSettings& s = frame_.settings;
    // This sample's radiance by light group and by light path.
    std::vector<Color> splits(splitLayers_.size(), Color::Zero());
    RadianceSplits into;
    if (groupCount_ > 0) into.groups = splits.data();
    if (splits.size() > groupCount_) into.paths = splits.data() + groupCount_;
    // The pixel's place in the whole frame: a region's pixels are the frame's.
    const int frameX = x + s.region.x, frameY = y + s.region.y;
    for (int i = sum.samples; i < end; ++i) {
      PixelSampler sampler(s.sampler, s.seed, s.frameNumber, frameX, frameY, i, s.samplesPerPixel, order_);
      // The point in the filter's footprint and the point on the lens: one 4D block
      // (sample_dimensions::kPixelAndLens), mapped monotonically, so both stay stratified.
      const std::array<float, 4> pixelAndLens = sampler.get4D();
      const FilterSample f = filter_.sample(Vec2(pixelAndLens[0], pixelAndLens[1]));
      const Vec2 lens(pixelAndLens[2], pixelAndLens[3]);
      sampler.setDimension(sample_dimensions::kTime);
      const float time = hasMotion_ ? sampler.get1D() : 0.0f;
      const Ray ray =
          cameraRays_.generate(float(frameX) + 0.5f + f.offset.x(), float(frameY) + 0.5f + f.offset.y(), lens, time);
      FirstHit first;
      std::fill(splits.begin(), splits.end(), Color::Zero());
      Color L = integrator_.radiance(ray, sampler, first, counters, into);
      if (!isFinite(L)) {
        L = Color::Zero();  // discarded, counted, reported: never on the film (the sample counts as black)
        std::fill(splits.begin(), splits.end(), Color::Zero());
        ++nonFinite;
      }
      addSplits(sum, splits, f.weight);
      sum.weightedRadiance += f.weight * L;
      sum.weight += f.weight;
      addRadiance(sum, L);
      if (splitSubsurface_) addSubsurface(sum, splits[groupCount_ + size_t(LightPath::Subsurface)]);
      if (first.valid) {
        if (objects_.layer && first.ids.object >= 0) sum.objectIds.add(objects_.ids[size_t(first.ids.object)], f.weight);
        if (materials_.layer && first.ids.material >= 0)
          sum.materialIds.add(materials_.ids[size_t(first.ids.material)], f.weight);
        sum.weightedCoverage += f.weight;
        sum.coverage += 1.0f;
        sum.albedo += first.albedo;
        sum.normal += first.normal;
        sum.depth += cameraDepth(frame_.camera, ray, first.distance);
        ++sum.depthSamples;
      }
    }
  }

  void store(int x, int y, const PixelSums& sum) const {
    const size_t p = film_.pixelIndex(x, y);
    const PixelValue value = pixelValue(sum);
    for (int c = 0; c < 3; ++c) film_.rgba[4 * p + c] = value.radiance[c];
    film_.rgba[4 * p + 3] = value.alpha;
    const float invHits = sum.depthSamples > 0 ? 1.0f / float(sum.depthSamples) : 0.0f;
    for (int c = 0; c < 3; ++c) film_.albedo[3 * p + c] = sum.albedo[c] * invHits;
    const Vec3 n = sum.normal.norm() > 0.0f ? Vec3(sum.normal.normalized()) : Vec3::Zero();
    for (int c = 0; c < 3; ++c) film_.normal[3 * p + c] = n[c];
    film_.depth[p] = sum.depthSamples > 0 ? sum.depth * invHits : std::numeric_limits<float>::infinity();
    if (!film_.sampleCount.empty()) film_.sampleCount[p] = float(sum.samples);
    for (size_t i = 0; i < splitLayers_.size(); ++i) {
      if (!splitLayers_[i]) continue;
      const Color value = splitValue(sum, i);
      std::copy_n(value.data(), 3, splitLayers_[i]->data.begin() + long(3 * p));
    }
    storeRanks(objects_, sum.objectIds, p, sum.weight);
    storeRanks(materials_, sum.materialIds, p, sum.weight);
    if (halves_) {
      const PixelHalves halves = pixelHalves(sum);
      // Under 2 samples both halves are the one sample: any share will do.
      halves_->firstHalfShare[p] = sum.samples >= 2 ? float(halves.firstSamples) / float(sum.samples) : 0.5f;
      storeHalves(p, halves, halfMeanVariance(sum), halves_->halfA, halves_->halfB, halves_->variance);
      if (splitSubsurface_)
        storeHalves(p, subsurfaceHalves(sum), subsurfaceHalfMeanVariance(sum), halves_->subsurfaceA,
                    halves_->subsurfaceB, halves_->subsurfaceVariance);
    }
  }

 private:
  static FilmLayer* addRgbLayer(Film& film, const std::string& layer) {
    film.layers.push_back(FilmLayer{{layer + ".R", layer + ".G", layer + ".B"},
                                    std::vector<float>(size_t(film.width) * film.height * 3, 0.0f)});
    return &film.layers.back();
  }

  // A layer per light group, "lightgroup_<name>.R/G/B"; they come first among the splits.
  void addLightGroupLayers(Film& film, const LightGroups& groups) {
    for (const std::string& name : groups.names) splitLayers_.push_back(addRgbLayer(film, lightGroupLayer(name)));
    groupCount_ = splitLayers_.size();
  }

  // After the groups, every light path is split (so the integrator's split is whole); only the
  // passes asked for get a layer ("diffuse_direct.R/G/B", ...).
  void addLightPathLayers(Film& film, const LightPathSet& passes) {
    for (const LightPath pass : allLightPaths())
      splitLayers_.push_back(passes.has(pass) ? addRgbLayer(film, lightPathName(pass)) : nullptr);
  }

  static void storeHalves(size_t p, const PixelHalves& h, const Color& variance, std::vector<float>& a,
                          std::vector<float>& b, std::vector<float>& v) {
    for (int c = 0; c < 3; ++c) {
      a[3 * p + c] = h.first[c];
      b[3 * p + c] = h.rest[c];
      v[3 * p + c] = variance[c];
    }
  }

  static bool hasSubsurface(const std::vector<Material>& materials) {
    return std::any_of(materials.begin(), materials.end(), [](const Material& m) {
      const auto* skin = std::get_if<SkinParams>(&m.params);
      return skin && skin->subsurface.has_value();
    });
  }

  static void addSplits(PixelSums& sum, const std::vector<Color>& splits, float weight) {
    if (splits.empty()) return;
    if (sum.splitWeighted.empty()) sum.splitWeighted.assign(splits.size(), Color::Zero());
    if (sum.splitPlain.empty()) sum.splitPlain.assign(splits.size(), Color::Zero());
    for (size_t i = 0; i < splits.size(); ++i) {
      sum.splitWeighted[i] += weight * splits[i];
      sum.splitPlain[i] += splits[i];
    }
  }

  void storeRanks(const CryptomatteLayer& crypto, const IdCoverage& coverage, size_t p, float totalWeight) const {
    if (!crypto.layer) return;
    const size_t channels = crypto.layer->channels.size();
    const std::vector<float> ranked = coverage.ranked(int(channels / 2), totalWeight);
    std::copy(ranked.begin(), ranked.end(), crypto.layer->data.begin() + long(p * channels));
  }

  const Frame& frame_;
  const PathIntegrator& integrator_;
  const FilterSampler& filter_;
  Film& film_;
  CameraRays cameraRays_;
  bool hasMotion_;
  // Progressive under adaptive sampling (a pixel may stop after any round) and when denoising
  // (the half buffers are then stratified on their own).
  SampleOrder order_;
  DenoiseInput* halves_ = nullptr;
  bool splitSubsurface_ = false;
  CryptomatteLayer objects_, materials_;  // no layer: not written
  // Per split of the radiance: the light groups (groupCount_ of them), then the light paths; null
  // for a light path not written.
  std::vector<FilmLayer*> splitLayers_;
  size_t groupCount_ = 0;
};

// The denoiser's input: the half buffers (already filled by the tiles) and the film's features.
void denoiseFilm(DenoiseInput& input, Film& film) {
  input.width = film.width;
  input.height = film.height;
  input.albedo = film.albedo;
  input.normal = film.normal;
  input.depth = film.depth;
  film.denoised = denoise(input);
}

// Counts what the tiles did, reports progress as camera samples done over those still planned,
// and polls the cancel flag.
class TracingProgress {
 public:
  TracingProgress(std::chrono::steady_clock::time_point start, const ProgressCallback& callback,
                  const std::atomic<bool>* cancel)
      : start_(start), callback_(callback), cancel_(cancel) {}

  bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
  uint64_t rays() const { return rays_.load(); }
  uint64_t nonFiniteSamples() const { return nonFinite_.load(); }

  // The camera samples still to come (adaptive sampling re-plans them after every round).
  void planMore(uint64_t samples) { planned_ = done_.load() + samples; }

  void tileDone(const PathCounters& counters, uint64_t nonFinite, uint64_t samples) {
    rays_ += counters.rays;
    nonFinite_ += nonFinite;
    const uint64_t done = done_ += samples;
    if (!callback_) return;
    const std::lock_guard lock(mutex_);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    callback_(RenderProgress{done, std::max(planned_.load(), done), elapsed, rays_.load()});
  }

 private:
  std::chrono::steady_clock::time_point start_;
  const ProgressCallback& callback_;
  const std::atomic<bool>* cancel_;
  std::atomic<uint64_t> rays_{0}, nonFinite_{0}, done_{0}, planned_{0};
  std::mutex mutex_;
};

// Without adaptive sampling: every tile once, each pixel with all its samples. Returns the
// camera samples taken.
uint64_t renderAllSamples(const TileRenderer& tiles, const RenderSettings& s, TracingProgress& tracing) {
  const int width = s.filmWidth(), height = s.filmHeight();
  const int tileCount = tileCountOf(width, height);
  tracing.planMore(uint64_t(width) * height * s.samplesPerPixel);
  tbb::parallel_for(tbb::blocked_range<int>(0, tileCount, 1), [&](const tbb::blocked_range<int>& range) {
    for (int t = range.begin(); t != range.end(); ++t) {
      if (tracing.cancelled()) return;  // skip what is left, cheaply
      PathCounters counters;
      uint64_t nonFinite = 0;
      const TileRect rect = tileRect(t, width, height);
      tiles.renderTile(rect, counters, nonFinite);
      tracing.tileDone(counters, nonFinite, uint64_t(rect.x1 - rect.x0) * (rect.y1 - rect.y0) * s.samplesPerPixel);
    }
  });
  return uint64_t(width) * height * s.samplesPerPixel;
}

// Adaptive sampling (adaptive_sampling.hpp) in rounds over the whole image: each round, every
// active pixel goes on to its next sample count, tiles in parallel; between rounds the pixels
// that go on are chosen from all the sums. The rounds and choices depend on the sums alone, so
// the image does not depend on the thread count. Returns the camera samples taken.
uint64_t renderAdaptively(const TileRenderer& tiles, const RenderSettings& s, TracingProgress& tracing) {
  const int width = s.filmWidth(), height = s.filmHeight();
  const size_t pixelCount = size_t(width) * height;
  std::vector<PixelSums> sums(pixelCount);
  std::vector<uint8_t> active(pixelCount, 1);
  const int tileCount = tileCountOf(width, height);
  for (;;) {
    std::vector<int> activeTiles;
    uint64_t planned = 0;
    for (int t = 0; t < tileCount; ++t) {
      const TileRect rect = tileRect(t, width, height);
      bool any = false;
      for (int y = rect.y0; y < rect.y1; ++y)
        for (int x = rect.x0; x < rect.x1; ++x) {
          const size_t p = size_t(y) * width + x;
          if (!active[p]) continue;
          any = true;
          planned += uint64_t(s.samplesPerPixel - sums[p].samples);
        }
      if (any) activeTiles.push_back(t);
    }
    if (activeTiles.empty() || tracing.cancelled()) break;
    tracing.planMore(planned);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, activeTiles.size(), 1), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        if (tracing.cancelled()) return;
        PathCounters counters;
        uint64_t nonFinite = 0, taken = 0;
        const TileRect rect = tileRect(activeTiles[i], width, height);
        for (int y = rect.y0; y < rect.y1; ++y)
          for (int x = rect.x0; x < rect.x1; ++x) {
            PixelSums& sum = sums[size_t(y) * width + x];
            if (!active[size_t(y) * width + x]) continue;
            const int before = sum.samples;
            tiles.addSamples(x, y, nextSampleCount(before, s.adaptive, s.samplesPerPixel), sum, counters, nonFinite);
            taken += uint64_t(sum.samples - before);
          }
        tracing.tileDone(counters, nonFinite, taken);
      }
    });
    selectActivePixels(sums, width, height, s.adaptive, s.samplesPerPixel, active);
  }
  uint64_t samples = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const PixelSums& sum = sums[size_t(y) * width + x];
      tiles.store(x, y, sum);
      samples += uint64_t(sum.samples);
    }
  return samples;
}

}  // namespace

Renderer::Renderer() = default;
Renderer::~Renderer() = default;

// Runs inside the frame's task arena: Embree's BVH builders use the calling TBB arena.
void Renderer::updateScene(const Frame& frame, RenderStats& stats) {
  const int threads = frame.settings.threads;
  try {
    SceneFollowReport report;
    if (scene_ && scene_->canFollow(threads)) {
      report = scene_->follow(frame);
      stats.sceneUpdate = report.keptLayout() ? SceneUpdate::Refit : SceneUpdate::Update;
    } else {
      scene_.reset();  // release the old device before creating the next
      scene_ = std::make_unique<EmbreeScene>(frame, threads, &report);
      stats.sceneUpdate = SceneUpdate::Build;
    }
    stats.sceneGeometriesAttached = report.attached;
    stats.sceneGeometriesDetached = report.detached;
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

  Film film(s.filmWidth(), s.filmHeight());
  film.frameWidth = s.width;
  film.frameHeight = s.height;
  film.originX = s.region.x;
  film.originY = s.region.y;
  const size_t pixelCount = size_t(film.width) * film.height;
  if (s.adaptive.enabled) film.sampleCount.assign(pixelCount, 0.0f);
  TracingProgress tracing(start, progress, cancel);
  RenderStats update;  // the scene update's fields
  double sceneUpdateSeconds = 0.0, tracingSeconds = 0.0, denoiseSeconds = 0.0;
  float focusDistance = frame.camera.focusDistance;
  uint64_t cameraPaths = 0;

  arena.execute([&] {
    const auto updateStart = std::chrono::steady_clock::now();
    updateScene(frame, update);
    sceneUpdateSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - updateStart).count();
    const EmbreeScene& scene = *scene_;
    const LightSampler lights(frame);
    const PathIntegrator integrator(frame, scene, lights);
    const FilterSampler filter(s.filter);
    const Camera camera = focusedCamera(frame.camera, scene);
    focusDistance = camera.focusDistance;
    TileRenderer tiles(frame, camera, integrator, filter, film);
    DenoiseInput halves;
    if (s.denoise) {
      halves.halfA.assign(pixelCount * 3, 0.0f);
      halves.halfB.assign(pixelCount * 3, 0.0f);
      halves.variance.assign(pixelCount * 3, 0.0f);
      halves.firstHalfShare.assign(pixelCount, 0.5f);
      if (tiles.splitsSubsurface()) {
        halves.subsurfaceA.assign(pixelCount * 3, 0.0f);
        halves.subsurfaceB.assign(pixelCount * 3, 0.0f);
        halves.subsurfaceVariance.assign(pixelCount * 3, 0.0f);
      }
      tiles.keepHalvesIn(&halves);
    }
    const auto tracingStart = std::chrono::steady_clock::now();
    cameraPaths = s.adaptive.enabled ? renderAdaptively(tiles, s, tracing) : renderAllSamples(tiles, s, tracing);
    const auto tracingEnd = std::chrono::steady_clock::now();
    tracingSeconds = std::chrono::duration<double>(tracingEnd - tracingStart).count();
    if (s.denoise && !tracing.cancelled()) {
      denoiseFilm(halves, film);
      denoiseSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tracingEnd).count();
    }
  });
  if (tracing.cancelled()) throw RenderCancelled();

  if (stats) {
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->tracingSeconds = tracingSeconds;
    stats->cameraPaths = cameraPaths;
    stats->rays = tracing.rays();
    stats->nonFiniteSamples = tracing.nonFiniteSamples();
    stats->sceneUpdate = update.sceneUpdate;
    stats->sceneGeometriesAttached = update.sceneGeometriesAttached;
    stats->sceneGeometriesDetached = update.sceneGeometriesDetached;
    stats->sceneUpdateSeconds = sceneUpdateSeconds;
    stats->denoiseSeconds = denoiseSeconds;
    stats->focusDistance = focusDistance;
  }
  return film;
}

Film renderFrame(const Frame& frame, RenderStats* stats, const ProgressCallback& progress,
                 const std::atomic<bool>* cancel) {
  Renderer renderer;
  return renderer.render(frame, stats, progress, cancel);
}

}  // namespace lacrima
