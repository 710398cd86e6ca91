#pragma once
// The film: beauty and AOVs of one frame, float per channel, row 0 at the top.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima {

// A further layer of float channels, written after the standard ones (Cryptomatte's).
struct FilmLayer {
  std::vector<std::string> channels;  // full EXR names, e.g. "CryptoObject00.R"
  std::vector<float> data;            // channels.size() a pixel, interleaved
};

struct Film {
  int width = 0, height = 0;
  // The whole frame the film is part of, and the film's place in it (a render region; the EXR's
  // display and data windows): the film's pixel (x, y) is the frame's (originX + x, originY + y).
  int frameWidth = 0, frameHeight = 0;
  int originX = 0, originY = 0;
  std::vector<float> rgba;    // 4 per pixel, radiance average (alpha = coverage)
  std::vector<float> albedo;  // 3 per pixel, first-hit albedo average
  std::vector<float> normal;  // 3 per pixel, first-hit world shading normal average
  std::vector<float> depth;   // 1 per pixel, first-hit distance along the camera axis (inf = none)
  // 1 per pixel, the camera samples the pixel took: filled by adaptive sampling only (else empty).
  std::vector<float> sampleCount;
  // 3 per pixel, the denoised beauty RGB (denoiser.hpp): filled when denoising (else empty).
  std::vector<float> denoised;
  std::vector<FilmLayer> layers;
  // EXR header strings the render adds (the Cryptomatte types' names, hashes and manifests).
  std::map<std::string, std::string> attributes;

  Film() = default;
  Film(int w, int h)
      : width(w), height(h), frameWidth(w), frameHeight(h), rgba(size_t(w) * h * 4, 0.0f), albedo(size_t(w) * h * 3, 0.0f),
        normal(size_t(w) * h * 3, 0.0f), depth(size_t(w) * h, 0.0f) {}
  size_t pixelIndex(int x, int y) const { return size_t(y) * width + x; }
};

// How the Embree scene of a frame came to be: built from scratch (the first frame of a Renderer,
// or another thread count); the previous frame's scene with its vertices moved and its BVHs
// refitted (same meshes, triangles, spheres, lights and time steps: Refit); or the previous
// frame's scene with the geometries whose layout changed (a mesh added, removed or
// re-triangulated, a sphere starting to move, a light changing shape) replaced and the rest
// refitted (Update). Each renders the frame bitwise as a scene built for it alone.
enum class SceneUpdate : uint8_t { Build, Refit, Update };
inline const char* sceneUpdateName(SceneUpdate update) {
  return update == SceneUpdate::Build ? "build" : update == SceneUpdate::Refit ? "refit" : "update";
}

// Statistics of one rendered frame.
struct RenderStats {
  SceneUpdate sceneUpdate = SceneUpdate::Build;
  double sceneUpdateSeconds = 0.0;  // building or refitting the Embree scene (part of seconds)
  // Embree geometries the scene update attached (given new buffers and BVHs: every one for a
  // build) and detached (gone from the frame, or replaced because their layout changed).
  size_t sceneGeometriesAttached = 0, sceneGeometriesDetached = 0;
  double seconds = 0.0;
  // Path tracing alone: the wall time of the tiles, after the scene update, the light sampler and
  // the integrator's set-up (part of seconds). Rays per second are measured over it.
  double tracingSeconds = 0.0;
  uint64_t cameraPaths = 0;   // camera samples taken, all pixels together
  uint64_t rays = 0;          // intersect + occluded queries
  uint64_t nonFiniteSamples = 0;  // NaN/Inf path contributions discarded (never on the film)
  double denoiseSeconds = 0.0;    // the denoiser, after path tracing (part of seconds)
  float focusDistance = 0.0f;     // metres: the camera's, or where Camera::focusOnSurface put it
};

}  // namespace lacrima
