// `lacrima render`: shot -> frames -> EXR (+ PNG preview).
#include <fmt/format.h>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "frame_check.hpp"
#include "frame_range.hpp"
#include "frame_selection.hpp"
#include "interrupt.hpp"
#include "memory_usage.hpp"
#include "lacrima/renderer/camera.hpp"
#include "lacrima/renderer/image_output.hpp"
#include "lacrima/renderer/render.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/shot.hpp"
#include "output_check.hpp"
#include "progress.hpp"
#include "render_plan.hpp"
#include "thread_cap.hpp"

namespace lacrima::cli {

namespace {

// Above this fraction of discarded NaN/Inf samples a frame is a failed render, not a noisy one.
constexpr double kMaxNonFiniteFraction = 1e-4;

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
  for (const auto& [name, value] : pixelSettingsMetadata(frame.settings)) m.extra[name] = value;
  m.extra["lacrima:nonFiniteSamples"] = std::to_string(stats.nonFiniteSamples);
  if (frame.camera.lensRadius > 0.0f) m.extra["lacrima:focusDistance"] = fmt::format("{:.6g}", stats.focusDistance);
  return m;
}

// --resume: the frames already complete on disk, each announced on stderr. An existing file that
// cannot be used (truncated, corrupt, other settings) is announced too: it will be rendered again.
std::vector<int> framesAlreadyComplete(const RenderOptions& o, const Shot& shot, const std::string& pattern,
                                       const std::vector<int>& frames) {
  std::vector<int> complete;
  for (int f : frames) {
    const std::string why = whyFrameIsNotComplete(o, shot, pattern, f);
    const std::string exrPath = expandFramePattern(pattern, f);
    if (why == "missing") continue;
    if (why.empty()) {
      std::fprintf(stderr, "frame %d: skipped (--resume): %s is complete\n", f, exrPath.c_str());
      complete.push_back(f);
    } else {
      std::fprintf(stderr, "frame %d: rendering again (--resume): %s is not usable: %s\n", f, exrPath.c_str(),
                   why.c_str());
    }
  }
  return complete;
}

// The distinct directories the frames go to (a pattern may put the frame number in a directory).
std::vector<std::filesystem::path> outputDirectories(const std::string& pattern, const std::vector<int>& frames) {
  std::vector<std::filesystem::path> directories;
  for (int f : frames) {
    std::filesystem::path directory = std::filesystem::path(expandFramePattern(pattern, f)).parent_path();
    if (directory.empty()) directory = ".";
    if (std::find(directories.begin(), directories.end(), directory) == directories.end())
      directories.push_back(directory);
  }
  return directories;
}

// Said once, as soon as the render notices the first Ctrl-C / SIGTERM.
void announceStopAfterFrame(int frameNumber) {
  static std::atomic<bool> announced{false};
  if (announced.exchange(true)) return;
  std::fprintf(stderr, "%slacrima: interrupted: finishing frame %d, then stopping (interrupt again to abandon it)\n",
               isatty(STDERR_FILENO) ? "\r\033[K" : "", frameNumber);
}

// "frame 12: memory after render: peak RSS ..." (stage: "" for the line after the whole frame).
void reportMemory(int frameNumber, const char* stage) {
  std::fprintf(stderr, "frame %d: memory%s: %s\n", frameNumber, stage, formatMemoryUsage(currentMemoryUsage()).c_str());
}

// NotWritten: the frame rendered but its file could not be written (disk full, directory gone):
// the next frames would fail the same way, so the run stops.
enum class FrameOutcome { Written, Failed, NotWritten, Abandoned };

// Renders and writes one frame. `seconds` receives the render time (also for a failed frame).
FrameOutcome renderOneFrame(Renderer& renderer, FrameBuilder& builder, const RenderOptions& o, const std::string& pattern,
                            int frameNumber, int index, int count, const SequenceProgress& sequence, double& seconds) {
  const Shot& shot = builder.shot();
  Frame frame = builder.build(frameNumber);
  if (o.reportMemory) reportMemory(frameNumber, " after buildFrame");
  ProgressReporter reporter(frameNumber, index, count, sequence, o.quiet);
  RenderStats stats;
  Film film;
  try {
    film = renderer.render(
        frame, &stats,
        [&](const RenderProgress& p) {
          if (stopRequested()) announceStopAfterFrame(frameNumber);
          reporter.update(p);
        },
        &abandonRequested());
  } catch (const RenderCancelled&) {
    reporter.finish();
    std::fprintf(stderr, "frame %d: abandoned after a second interrupt; not written\n", frameNumber);
    return FrameOutcome::Abandoned;
  }
  reporter.finish();
  seconds = stats.seconds;
  if (o.reportMemory) reportMemory(frameNumber, " after render");

  const RenderSettings& s = frame.settings;
  const double nonFiniteFraction = double(stats.nonFiniteSamples) / double(std::max<uint64_t>(1, stats.cameraPaths));
  if (nonFiniteFraction > kMaxNonFiniteFraction) {
    std::fprintf(stderr, "lacrima: frame %d FAILED: %llu of %llu samples were NaN/Inf (limit %.4f%%); not written\n",
                 frameNumber, (unsigned long long)stats.nonFiniteSamples, (unsigned long long)stats.cameraPaths,
                 100.0 * kMaxNonFiniteFraction);
    return FrameOutcome::Failed;
  }
  // Signals only set flags, so an interrupt cannot cut these writes short: they complete (and
  // rename their temporary file into place) before the loop looks at the flags again.
  const std::filesystem::path exrPath = expandFramePattern(pattern, frameNumber);
  std::string previewNote;
  try {
    writeExr(exrPath, film, metadataFor(shot, frame, stats), s.floatOutput);
    if (o.preview) {
      const std::filesystem::path pngPath = previewPathFor(exrPath);
      writePreviewPng(pngPath, film, previewOcioConfig(shot));
      previewNote = " + " + pngPath.filename().string();
    }
  } catch (const InputError& e) {
    std::fprintf(stderr, "lacrima: frame %d rendered but NOT written: %s\n", frameNumber, e.what());
    return FrameOutcome::NotWritten;
  }
  // Under adaptive sampling spp is each pixel's maximum: the mean says what the frame took.
  const std::string spp = s.adaptive.enabled
                              ? fmt::format("{} spp max, {:.1f} mean", s.samplesPerPixel,
                                            double(stats.cameraPaths) / (double(s.filmWidth()) * s.filmHeight()))
                              : fmt::format("{} spp", s.samplesPerPixel);
  // Inside the parentheses after the scene update: the denoiser's time, where the focus went.
  std::string notes = s.denoise ? fmt::format(", denoised in {:.1f} s", stats.denoiseSeconds) : "";
  if (frame.camera.focusOnSurface && frame.camera.lensRadius > 0.0f)
    notes += fmt::format(", focused at {:.4f} m", stats.focusDistance);
  // An update names what it replaced: the geometries a bead's birth or a drop's fall changed.
  const std::string sceneUpdate =
      stats.sceneUpdate == SceneUpdate::Update
          ? fmt::format("update, {} {} attached, {} detached,", stats.sceneGeometriesAttached,
                        stats.sceneGeometriesAttached == 1 ? "geometry" : "geometries", stats.sceneGeometriesDetached)
          : sceneUpdateName(stats.sceneUpdate);
  const std::string size = s.region.empty() ? fmt::format("{}x{}", s.width, s.height)
                                            : fmt::format("{}x{} at ({}, {}) of {}x{}", s.region.width,
                                                          s.region.height, s.region.x, s.region.y, s.width, s.height);
  std::fprintf(stderr, "frame %d: %s, %s, %s (scene %s %.3f s%s), %srays/s, %llu NaN/Inf samples discarded -> %s%s\n",
               frameNumber, size.c_str(), spp.c_str(), formatDuration(stats.seconds).c_str(),
               sceneUpdate.c_str(), stats.sceneUpdateSeconds, notes.c_str(),
               formatRate(stats.rays / std::max(stats.seconds, 1e-9)).c_str(),
               (unsigned long long)stats.nonFiniteSamples, exrPath.string().c_str(), previewNote.c_str());
  return FrameOutcome::Written;
}

// What happened to the frames of this run, in the order they were given.
struct SequenceTally {
  std::vector<int> complete;  // on disk when the run ends: skipped or rendered
  std::vector<int> failed;
  int rendered = 0, skipped = 0;
  std::optional<int> notWritten;  // the frame whose file could not be written; the run stopped there
  double renderSeconds = 0;  // of every frame rendered (or failed) in this run

  int framesDone() const { return int(complete.size() + failed.size()); }
  double meanFrameSeconds() const {
    const int attempts = rendered + int(failed.size());
    return attempts > 0 ? renderSeconds / attempts : 0.0;
  }
};

std::vector<int> framesNotDone(const std::vector<int>& frames, const SequenceTally& tally) {
  std::vector<int> left;
  for (int f : frames)
    if (std::find(tally.complete.begin(), tally.complete.end(), f) == tally.complete.end() &&
        std::find(tally.failed.begin(), tally.failed.end(), f) == tally.failed.end())
      left.push_back(f);
  return left;
}

void printSummary(const std::vector<int>& frames, const SequenceTally& tally, double wallSeconds) {
  const size_t notRendered = framesNotDone(frames, tally).size();
  std::fprintf(stderr, "lacrima: %zu frames: %d rendered, %d skipped, %zu failed%s in %s\n", frames.size(),
               tally.rendered, tally.skipped, tally.failed.size(),
               notRendered > 0 ? fmt::format(", {} not rendered", notRendered).c_str() : "",
               formatDuration(wallSeconds).c_str());
}

// why: what stopped the run, and what to do before resuming ("stopped by an interrupt.").
void printStopHint(const std::vector<int>& frames, const SequenceTally& tally, const char* why) {
  std::vector<int> complete = tally.complete;
  std::sort(complete.begin(), complete.end());
  std::fprintf(stderr,
               "lacrima: %s Frames complete: %s; not rendered: %s.\n"
               "lacrima: run the same command with --resume to render the rest.\n",
               why, formatFrameList(complete).c_str(), formatFrameList(framesNotDone(frames, tally)).c_str());
}

// --performance ASSET=FILE, each checked for its '=' and the file.
std::vector<PerformanceOverride> performanceOverrides(const RenderOptions& o) {
  std::vector<PerformanceOverride> takes;
  for (const std::string& option : o.performances) {
    const size_t equals = option.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == option.size())
      throw InputError(fmt::format("--performance {}: expected ASSET=FILE, such as face=track/performance.csv", option));
    takes.push_back({option.substr(0, equals), option.substr(equals + 1), o.performanceFps});
  }
  return takes;
}

}  // namespace

int runRender(const RenderOptions& o) {
  try {
    const auto start = std::chrono::steady_clock::now();
    // --threads caps the loading too; the shot's own render.threads applies from its frames on.
    Shot shot = withThreadCap(o.threads.value_or(0), [&] { return loadShot(o.shotPath, performanceOverrides(o)); });
    const std::vector<int> frames = selectShotFrames(o.frames, shot);
    const std::string pattern = resolveOutputPattern(o, shot, frames.size());
    checkPreviewConfig(o, shot);
    printShotWarnings(shot);
    // Once, before any frame is checked or built (a bad --region is reported after the shot's
    // own problems and warnings, as ever).
    applyOverrides(o, shot.render);
    installInterruptHandlers();

    SequenceTally tally;
    if (o.resume) tally.complete = framesAlreadyComplete(o, shot, pattern, frames);
    tally.skipped = int(tally.complete.size());
    const std::vector<int> toRender = framesNotDone(frames, tally);
    if (!toRender.empty())
      checkOutputDirectories(outputDirectories(pattern, toRender),
                             estimatedFrameBytes(renderSettingsAt(shot, toRender.front()), o.preview), toRender.size());
    Renderer renderer;  // keeps the Embree scene from frame to frame (refit when the topology stays)
    // Keeps the shot's simulations from frame to frame (each frame continues the one before).
    std::unique_ptr<FrameBuilder> builder;
    if (!toRender.empty())
      builder = withThreadCap(shot.render.threads, [&] { return std::make_unique<FrameBuilder>(shot); });
    for (size_t i = 0; i < toRender.size() && !stopRequested(); ++i) {
      const int frameNumber = toRender[i];
      const int index = int(std::find(frames.begin(), frames.end(), frameNumber) - frames.begin());
      const SequenceProgress sequence{tally.framesDone(), int(frames.size()), int(toRender.size() - i - 1),
                                      tally.meanFrameSeconds()};
      double seconds = 0;
      const FrameOutcome outcome = withThreadCap(shot.render.threads, [&] {
        return renderOneFrame(renderer, *builder, o, pattern, frameNumber, index, int(frames.size()), sequence, seconds);
      });
      if (outcome == FrameOutcome::Abandoned) break;
      if (outcome == FrameOutcome::NotWritten) {
        tally.notWritten = frameNumber;
        break;
      }
      tally.renderSeconds += seconds;
      releaseFreeHeapMemory();  // what this frame freed, before the next frame's allocations
      if (o.reportMemory) reportMemory(frameNumber, "");
      if (outcome == FrameOutcome::Written) {
        tally.complete.push_back(frameNumber);
        ++tally.rendered;
      } else {
        tally.failed.push_back(frameNumber);
      }
    }
    printSummary(frames, tally, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (o.reportMemory) std::fprintf(stderr, "lacrima: memory: %s\n", formatMemoryUsage(currentMemoryUsage()).c_str());

    // An interrupt that came after the last frame stopped nothing: the run is simply complete.
    if (stopRequested() && !framesNotDone(frames, tally).empty()) {
      printStopHint(frames, tally, "stopped by an interrupt.");
      return kExitInterrupted;
    }
    if (tally.notWritten) {
      const std::string why = fmt::format("stopped: frame {} could not be written (make room or fix the output first).",
                                          *tally.notWritten);
      printStopHint(frames, tally, why.c_str());
      return kExitRenderFailure;
    }
    if (!tally.failed.empty()) {
      std::fprintf(stderr, "lacrima: %zu of %zu frames failed\n", tally.failed.size(), frames.size());
      return kExitRenderFailure;
    }
    return kExitOk;
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
