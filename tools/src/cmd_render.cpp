// `lacrima render`: shot -> frames -> EXR (+ PNG preview).
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "frame_range.hpp"
#include "lacrima/renderer/camera.hpp"
#include "lacrima/renderer/image_output.hpp"
#include "lacrima/renderer/render.hpp"
#include "lacrima/scenes/shot.hpp"
#include "progress.hpp"

namespace lacrima::cli {

namespace {

// Above this fraction of discarded NaN/Inf samples a frame is a failed render, not a noisy one.
constexpr double kMaxNonFiniteFraction = 1e-4;

// The frames to render, all inside the shot's range (checked before anything is rendered).
std::vector<int> framesToRender(const RenderOptions& options, const Shot& shot) {
  if (!options.frames) {
    std::vector<int> frames;
    for (int f = shot.frameStart; f <= shot.frameEnd; ++f) frames.push_back(f);
    return frames;
  }
  const std::string& text = *options.frames;
  const std::string shown = text.empty() ? "''" : text;
  std::string error;
  auto frames = parseFrameList(text, error);
  if (!frames) throw InputError("--frames " + shown + ": " + error);
  for (int f : *frames)
    if (f < shot.frameStart || f > shot.frameEnd)
      throw InputError(fmt::format("--frames {}: frame {} is outside the frame range {}-{} of {}", shown, f,
                                   shot.frameStart, shot.frameEnd, shot.path.string()));
  return *frames;
}

void applyOverrides(const RenderOptions& o, RenderSettings& s) {
  if (o.spp) s.samplesPerPixel = *o.spp;
  if (o.width) s.width = *o.width;
  if (o.height) s.height = *o.height;
  if (o.threads) s.threads = *o.threads;
  if (o.maxDepth) s.maxDepth = *o.maxDepth;
  if (o.seed) s.seed = *o.seed;
  if (o.floatOutput) s.floatOutput = true;
}

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string outputPattern(const RenderOptions& o, const Shot& shot, size_t frameCount) {
  const std::string pattern = o.outputPattern.empty() ? shot.outputPattern : o.outputPattern;
  // The same expansion the frames get: a pattern with a frame field ('#' run, %d, %04d)
  // names different files for different frames.
  const bool hasFrameField = expandFramePattern(pattern, 1) != expandFramePattern(pattern, 2);
  if (frameCount > 1 && !hasFrameField)
    throw InputError(fmt::format("output '{}' has no #### frame field but {} frames are to be rendered: every frame "
                                 "would overwrite the last",
                                 pattern, frameCount));
  // Frames are always OpenEXR; another extension would mislead, and with --preview a '.png'
  // output would be overwritten by its own preview.
  if (lowerExtension(expandFramePattern(pattern, 1)) != ".exr")
    throw InputError(fmt::format("output '{}': frames are OpenEXR files, the name must end in .exr", pattern));
  return pattern;
}

std::string previewOcioConfig(const Shot& shot) {
  return shot.ocioConfig.empty() ? defaultOcioConfig() : shot.ocioConfig.string();
}

// A missing OCIO config would otherwise only show after the first frame has rendered.
void checkPreviewConfig(const RenderOptions& o, const Shot& shot) {
  if (!o.preview) return;
  const std::string config = previewOcioConfig(shot);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(config, ec))
    throw InputError(fmt::format("OCIO config '{}' for --preview: file not found (or not a regular file)", config));
}

ExrMetadata metadataFor(const Shot& shot, const Frame& frame, const RenderStats& stats) {
  ExrMetadata m;
  m.shotFile = std::filesystem::absolute(shot.path).string();
  m.frame = frame.settings.frameNumber;
  m.seed = frame.settings.seed;
  m.samplesPerPixel = frame.settings.samplesPerPixel;
  m.renderSeconds = stats.seconds;
  m.worldToCamera = worldToCameraMatrix(frame.camera);
  m.worldToNDC = worldToNdcMatrix(frame.camera, frame.settings.width, frame.settings.height);
  m.extra["lacrima:maxDepth"] = std::to_string(frame.settings.maxDepth);
  m.extra["lacrima:nonFiniteSamples"] = std::to_string(stats.nonFiniteSamples);
  return m;
}

// Renders and writes one frame; returns false when the frame failed (not written).
bool renderOneFrame(Renderer& renderer, const RenderOptions& o, const Shot& shot, const std::string& pattern,
                    int frameNumber, int index, int count) {
  Frame frame = buildFrame(shot, frameNumber);
  applyOverrides(o, frame.settings);
  frame.settings.frameNumber = frameNumber;
  ProgressReporter reporter(frameNumber, index, count, o.quiet);
  RenderStats stats;
  const Film film = renderer.render(frame, &stats, [&](const RenderProgress& p) { reporter.update(p); });
  reporter.finish();

  const RenderSettings& s = frame.settings;
  const double nonFiniteFraction = double(stats.nonFiniteSamples) / double(std::max<uint64_t>(1, stats.cameraPaths));
  if (nonFiniteFraction > kMaxNonFiniteFraction) {
    std::fprintf(stderr, "lacrima: frame %d FAILED: %llu of %llu samples were NaN/Inf (limit %.4f%%); not written\n",
                 frameNumber, (unsigned long long)stats.nonFiniteSamples, (unsigned long long)stats.cameraPaths,
                 100.0 * kMaxNonFiniteFraction);
    return false;
  }
  const std::filesystem::path exrPath = expandFramePattern(pattern, frameNumber);
  writeExr(exrPath, film, metadataFor(shot, frame, stats), s.floatOutput);
  std::string previewNote;
  if (o.preview) {
    std::filesystem::path pngPath = exrPath;
    pngPath.replace_extension(".png");
    writePreviewPng(pngPath, film, previewOcioConfig(shot));
    previewNote = " + " + pngPath.filename().string();
  }
  std::fprintf(stderr, "frame %d: %dx%d, %d spp, %s (scene %s %.3f s), %srays/s, %llu NaN/Inf samples discarded -> %s%s\n",
               frameNumber, s.width, s.height, s.samplesPerPixel, formatDuration(stats.seconds).c_str(),
               stats.sceneUpdate == SceneUpdate::Refit ? "refit" : "build", stats.sceneUpdateSeconds,
               formatRate(stats.rays / std::max(stats.seconds, 1e-9)).c_str(),
               (unsigned long long)stats.nonFiniteSamples, exrPath.string().c_str(), previewNote.c_str());
  return true;
}

}  // namespace

int runRender(const RenderOptions& o) {
  try {
    const Shot shot = loadShot(o.shotPath);
    const std::vector<int> frames = framesToRender(o, shot);
    const std::string pattern = outputPattern(o, shot, frames.size());
    checkPreviewConfig(o, shot);
    printShotWarnings(shot);
    int failed = 0;
    Renderer renderer;  // keeps the Embree scene from frame to frame (refit when the topology stays)
    for (size_t i = 0; i < frames.size(); ++i)
      if (!renderOneFrame(renderer, o, shot, pattern, frames[i], int(i), int(frames.size()))) ++failed;
    if (failed > 0) {
      std::fprintf(stderr, "lacrima: %d of %zu frames failed\n", failed, frames.size());
      return kExitRenderFailure;
    }
    return kExitOk;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
