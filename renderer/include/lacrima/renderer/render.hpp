#pragma once
// Rendering one Frame into a Film: Embree scene, path tracing in parallel tiles.
#include <atomic>
#include <functional>
#include <stdexcept>

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

// Thrown by renderFrame when its cancel flag was set: the partial film is discarded.
struct RenderCancelled : std::runtime_error {
  RenderCancelled() : std::runtime_error("render cancelled") {}
};

// Renders frame.settings.samplesPerPixel samples per pixel. The result is bitwise identical
// for any thread count. Throws InputError for frames that cannot be rendered (bad mesh data).
// `cancel` (optional) is polled before every tile, so a signal handler can stop a long frame
// within about one tile's time; once it is true, the remaining tiles are skipped and
// RenderCancelled is thrown.
Film renderFrame(const Frame& frame, RenderStats* stats = nullptr, const ProgressCallback& progress = {},
                 const std::atomic<bool>* cancel = nullptr);

}  // namespace lacrima
