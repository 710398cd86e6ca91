#pragma once
// Rendering one Frame into a Film: Embree scene, path tracing in parallel tiles.
#include <functional>
#include <memory>

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

  // As renderFrame. `frame` need only live for the duration of the call.
  Film render(const Frame& frame, RenderStats* stats = nullptr, const ProgressCallback& progress = {});

 private:
  SceneUpdate updateScene(const Frame& frame);

  std::unique_ptr<EmbreeScene> scene_;  // null before the first frame
};

// Renders frame.settings.samplesPerPixel samples per pixel (a Renderer used once). The result
// is bitwise identical for any thread count. Throws InputError for frames that cannot be
// rendered (bad mesh data).
Film renderFrame(const Frame& frame, RenderStats* stats = nullptr, const ProgressCallback& progress = {});

}  // namespace lacrima
