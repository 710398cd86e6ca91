// `lacrima bench --quality`: time to equal error. Renders a frame at 1, 2, 4, ... samples per
// pixel, measures each render's RMSE against a converged reference of the same frame (rendered
// once with other random numbers and cached), and reports the RMSE-vs-spp slope and the samples
// and seconds needed to reach RMSE targets. Sampling or speed changes are judged by this, not by
// rays per second alone.
#include <OpenImageIO/imagebuf.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

#include "commands.hpp"
#include "lacrima/base/user_cache.hpp"
#include "lacrima/renderer/render.hpp"
#include "lacrima/scenes/shot.hpp"
#include "progress.hpp"
#include "quality_curve.hpp"

namespace lacrima::cli {

namespace {

namespace fs = std::filesystem;

// The reference uses other random numbers than the measured renders (their seed plus this), so
// that its remaining noise does not correlate with theirs and hide their error.
constexpr uint64_t kReferenceSeedOffset = 0x9E3779B97F4A7C15ull;

// FNV-1a of the shot file's bytes: a changed shot gets a new cached reference.
uint64_t fileHash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
  return h;
}

fs::path defaultCacheDirectory() {
  if (fs::path cache = userCacheDirectory("quality"); !cache.empty()) return cache;
  return fs::temp_directory_path() / "lacrima-quality";
}

// Everything the converged image depends on is in its name. The pixel filter is in the shot
// file, but its default is not: references cached before the filter existed (box 1 px) are not
// taken for Blackman-Harris ones.
fs::path referencePath(const BenchOptions& o, const std::string& shotPath, int frame, const RenderSettings& s) {
  const fs::path dir = o.cacheDir.empty() ? defaultCacheDirectory() : fs::path(o.cacheDir);
  return dir / fmt::format("{}.{:016x}.f{}.{}x{}.d{}.{}{}.{}spp.exr", fs::path(shotPath).stem().string(),
                           fileHash(shotPath), frame, o.width, o.height, s.maxDepth, filterTypeName(s.filter.type),
                           s.filter.width, o.referenceSpp);
}

// The film's beauty R, G, B, 3 floats a pixel.
std::vector<float> beautyRgb(const Film& film) {
  std::vector<float> rgb;
  rgb.reserve(size_t(film.width) * film.height * 3);
  for (size_t i = 0; i < film.rgba.size(); i += 4) rgb.insert(rgb.end(), {film.rgba[i], film.rgba[i + 1], film.rgba[i + 2]});
  return rgb;
}

// The cached reference, or nothing when it is missing or unreadable or of another size.
std::optional<std::vector<float>> readReference(const fs::path& path, int width, int height) {
  if (!fs::exists(path)) return std::nullopt;
  OIIO::ImageBuf image(path.string());
  if (!image.read(0, 0, true, OIIO::TypeDesc::FLOAT) || image.spec().width != width ||
      image.spec().height != height || image.spec().nchannels != 3)
    return std::nullopt;
  std::vector<float> rgb(size_t(width) * height * 3);
  if (!image.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rgb.data())) return std::nullopt;
  return rgb;
}

// Written to a temporary name and renamed: an interrupted run never leaves a partial reference.
void writeReference(const fs::path& path, const std::vector<float>& rgb, int width, int height) {
  fs::create_directories(path.parent_path());
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  image.set_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rgb.data());
  const fs::path temporary = path.string() + fmt::format(".tmp-{}.exr", getpid());
  if (!image.write(temporary.string())) throw InputError(path.string() + ": cannot write the reference: " + image.geterror());
  fs::rename(temporary, path);
}

std::vector<float> referenceImage(const BenchOptions& o, Frame frame, const fs::path& path) {
  if (!o.freshReference)
    if (auto cached = readReference(path, o.width, o.height)) {
      std::printf("reference             %s (cached)\n", path.string().c_str());
      return *cached;
    }
  frame.settings.samplesPerPixel = o.referenceSpp;
  frame.settings.adaptive.enabled = false;  // converged everywhere, whatever the measured renders do
  frame.settings.seed += kReferenceSeedOffset;
  std::fprintf(stderr, "lacrima bench: rendering the reference at %d spp ...\n", o.referenceSpp);
  RenderStats stats;
  const std::vector<float> rgb = beautyRgb(renderFrame(frame, &stats));
  writeReference(path, rgb, o.width, o.height);
  std::printf("reference             %s (rendered in %s)\n", path.string().c_str(), formatDuration(stats.seconds).c_str());
  return rgb;
}

// Renders at 1, 2, 4, ... up to maxSpp samples (under adaptive sampling, each pixel's maximum;
// "mean spp" is what the pixels took); seconds are path tracing only (the Embree scene build,
// the same for every count, is left out).
std::vector<QualityPoint> measureCurve(const BenchOptions& o, Frame frame, const std::vector<float>& reference) {
  std::vector<QualityPoint> points;
  std::printf("%8s %10s %12s %10s\n", "spp", "mean spp", "seconds", "RMSE");
  for (int spp = 1; spp <= o.maxSpp; spp *= 2) {
    frame.settings.samplesPerPixel = spp;
    RenderStats stats;
    const std::vector<float> rgb = beautyRgb(renderFrame(frame, &stats));
    points.push_back({spp, stats.seconds - stats.sceneUpdateSeconds, rootMeanSquareError(rgb, reference)});
    const double meanSpp = double(stats.cameraPaths) / (double(o.width) * o.height);
    std::printf("%8d %10.1f %12.3f %10.5f\n", spp, meanSpp, points.back().seconds, points.back().rmse);
    std::fflush(stdout);
  }
  return points;
}

void printTimesToQuality(const std::vector<QualityPoint>& points, const std::vector<double>& targets) {
  for (double target : targets) {
    const std::optional<TimeToQuality> t = timeToReach(points, target);
    if (!t) {
      std::printf("RMSE %-8g          not reached (the error does not fall with more samples)\n", target);
      continue;
    }
    std::printf("RMSE %-8g          %.0f spp, %.2f s%s\n", target, t->spp, t->seconds,
                t->extrapolated ? " (extrapolated along the slope)" : "");
  }
}

}  // namespace

int runBenchQuality(const BenchOptions& o) {
  try {
    const std::string shotPath = o.shotPath.empty() ? defaultShot() : o.shotPath;
    const Shot shot = loadShot(shotPath);
    const int frameNumber = o.frame ? *o.frame : shot.frameStart;
    if (frameNumber < shot.frameStart || frameNumber > shot.frameEnd)
      throw InputError(fmt::format("--frame {}: the shot's frames are {}-{}", frameNumber, shot.frameStart, shot.frameEnd));
    Frame frame = buildFrame(shot, frameNumber);
    frame.settings.width = o.width;
    frame.settings.height = o.height;
    frame.settings.threads = o.threads;
    // The curve is the raw beauty's error: a shot's denoiser would only add its time (and its
    // sample order) to the renders. The denoiser is measured by FLIP (docs/denoising.md).
    frame.settings.denoise = false;
    if (o.adaptiveThreshold) {
      frame.settings.adaptive.enabled = *o.adaptiveThreshold > 0.0;
      if (frame.settings.adaptive.enabled) frame.settings.adaptive.threshold = float(*o.adaptiveThreshold);
    }
    const AdaptiveSampling& adaptive = frame.settings.adaptive;
    const Caustics measuredCaustics = o.caustics.value_or(frame.settings.caustics);
    std::printf("lacrima bench --quality: %s frame %d, %dx%d, max depth %d, threads %s, adaptive %s, caustics %s\n",
                shotPath.c_str(), frameNumber, o.width, o.height, frame.settings.maxDepth,
                o.threads ? std::to_string(o.threads).c_str() : "all",
                adaptive.enabled ? fmt::format("threshold {} min {} spp", adaptive.threshold, adaptive.minSamples).c_str()
                                 : "off",
                causticsName(measuredCaustics));
    const fs::path path = referencePath(o, shotPath, frameNumber, frame.settings);
    // The reference keeps the shot's caustics: the measured modes (MNEE and brute force converge
    // to the same image; straight does not) are then judged against one answer.
    const std::vector<float> reference = referenceImage(o, frame, path);
    frame.settings.caustics = measuredCaustics;
    const std::vector<QualityPoint> points = measureCurve(o, frame, reference);
    std::printf("RMSE-vs-spp slope     %.3f (independent samples: -0.5; stratified sampling is steeper)\n",
                rmseSlope(points));
    printTimesToQuality(points, o.targets);
    return kExitOk;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  } catch (const fs::filesystem_error& e) {
    std::fprintf(stderr, "lacrima bench: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
