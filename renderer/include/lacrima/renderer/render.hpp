#pragma once
// Rendering one Frame into a Film: Embree scene, path tracing in parallel tiles.
#include <functional>

#include "lacrima/renderer/film.hpp"
#include "lacrima/renderer/frame.hpp"

namespace lacrima {

struct RenderProgress {
  int tilesDone = 0;
  int tilesTotal = 0;
  double elapsedSeconds = 0.0;
  uint64_t raysSoFar = 0;
};
using ProgressCallback = std::function<void(const RenderProgress&)>;

// Renders frame.settings.samplesPerPixel samples per pixel. The result is bitwise identical
// for any thread count. Throws InputError for frames that cannot be rendered (bad mesh data).
Film renderFrame(const Frame& frame, RenderStats* stats = nullptr, const ProgressCallback& progress = {});

}  // namespace lacrima
