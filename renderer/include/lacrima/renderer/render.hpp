#pragma once
// Rendering one Frame into a Film: Embree scene, path tracing in parallel tiles.
#include <atomic>
#include <functional>
#include <memory>
#include <stdexcept>

#include "lacrima/renderer/film.hpp"
#include "lacrima/renderer/frame.hpp"

namespace lacrima {

// Progress of one frame's path tracing, in camera samples (one per pixel sample): those taken,
// and those taken plus those still planned (adaptive sampling plans each pixel up to the maximum,
// then re-plans after every round, so the total shrinks as pixels converge).
struct RenderProgress {
  uint64_t samplesDone = 0;
  uint64_t samplesTotal = 0;
  double elapsedSeconds = 0.0;
  uint64_t raysSoFar = 0;
};
using ProgressCallback = std::function<void(const RenderProgress&)>;

// Thrown by Renderer::render / renderFrame when its cancel flag was set: the partial film is
// discarded.
struct RenderCancelled : std::runtime_error {
  RenderCancelled() : std::runtime_error("render cancelled") {}
};

class EmbreeScene;  // renderer/src/embree_scene.hpp

// Renders the frames of a shot one after another and keeps the Embree scene between them.
// A frame with the previous frame's geometry layout (same meshes with the same triangles, same
// spheres, lights and time steps, same thread count) moves the vertices and refits the BVH;
// any other frame builds the scene anew. RenderStats::sceneUpdate says which happened.
class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders frame.settings.samplesPerPixel samples per pixel (at most that many under adaptive
  // sampling, frame.settings.adaptive); bitwise identical for any thread
  // count. `frame` need only live for the duration of the call. Throws InputError for frames
  // that cannot be rendered (bad mesh data). `cancel` (optional) is polled before every tile,
  // so a signal handler can stop a long frame within about one tile's time; once it is true,
  // the remaining tiles are skipped and RenderCancelled is thrown.
  Film render(const Frame& frame, RenderStats* stats = nullptr, const ProgressCallback& progress = {},
              const std::atomic<bool>* cancel = nullptr);

 private:
  // Builds the scene for the first frame (or another thread count), else follows the previous
  // frame's; sets the stats' scene update fields.
  void updateScene(const Frame& frame, RenderStats& stats);

  std::unique_ptr<EmbreeScene> scene_;  // null before the first frame
};

// One frame with a Renderer used once (see Renderer::render).
Film renderFrame(const Frame& frame, RenderStats* stats = nullptr, const ProgressCallback& progress = {},
                 const std::atomic<bool>* cancel = nullptr);

}  // namespace lacrima
