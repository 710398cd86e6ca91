// `lacrima export`: the geometry of a shot's frames (posed face, shapes, tears) as one glTF
// binary or OBJ file per frame, exactly what the frame builder gives the renderer, for other tools.
#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "frame_selection.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/shot.hpp"
#include "memory_usage.hpp"
#include "mesh_export.hpp"
#include "thread_cap.hpp"

namespace lacrima::cli {

namespace {

// The output pattern: --out, or the shot's render output with the format's extension
// (renders/shot.####.exr -> renders/shot.####.glb).
std::string exportPattern(const ExportOptions& o, const Shot& shot, size_t frameCount) {
  const std::string extension = "." + o.format;
  std::string pattern = o.outputPattern;
  if (pattern.empty()) pattern = std::filesystem::path(shot.outputPattern).replace_extension(extension).string();
  requireFrameField(pattern, frameCount, "exported");
  if (lowerExtension(expandFramePattern(pattern, 1)) != extension)
    throw InputError(fmt::format("output '{}': --format {} writes {} files, the name must end in {}", pattern,
                                 o.format, extension, extension));
  return pattern;
}

void exportFrame(const ExportOptions& o, FrameBuilder& builder, const std::string& pattern, int frameNumber) {
  const ExportScene scene = collectExportScene(builder.build(frameNumber));
  const std::filesystem::path path = expandFramePattern(pattern, frameNumber);
  if (o.format == "obj") {
    writeObj(path, scene);
  } else {
    writeGlb(path, scene);
  }
  const std::string mtlNote = o.format == "obj" ? " + " + mtlPathFor(path).filename().string() : "";
  std::fprintf(stderr, "frame %d: %zu meshes, %zu triangles -> %s%s\n", frameNumber, scene.meshes.size(),
               scene.triangleCount(), path.string().c_str(), mtlNote.c_str());
}

// Loads the shot and writes every selected frame (InputError for bad input or an unwritable output).
int exportFrames(const ExportOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const Shot shot = loadShot(o.shotPath);
  const std::vector<int> frames = selectShotFrames(o.frames, shot);
  const std::string pattern = exportPattern(o, shot, frames.size());
  printShotWarnings(shot);
  FrameBuilder builder(shot);  // the frames in order: each continues the simulations of the one before
  for (int frameNumber : frames) {
    exportFrame(o, builder, pattern, frameNumber);
    releaseFreeHeapMemory();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr, "lacrima: %zu frame%s exported as %s in %.2f s\n", frames.size(),
               frames.size() == 1 ? "" : "s", o.format.c_str(), seconds);
  return kExitOk;
}

}  // namespace

int runExport(const ExportOptions& o) {
  try {
    // --threads caps the loading and every frame's geometry (thread_cap.hpp).
    return withThreadCap(o.threads, [&] { return exportFrames(o); });
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
