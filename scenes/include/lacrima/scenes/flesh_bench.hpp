#pragma once
// What a shot's simulated flesh costs a frame at a chosen resolution, for `lacrima bench --flesh`
// (a measurement, not a test).
#include <vector>

#include "lacrima/scenes/shot_model.hpp"

namespace lacrima {

struct FleshFrameCost {
  int frame = 0;
  double seconds = 0.0;  // wall seconds to simulate the frame (its substeps) after the one before
};

struct FleshBenchResult {
  double tetSize = 0.0;
  size_t nodes = 0, tetrahedra = 0, freeNodes = 0;
  double volumeSeconds = 0.0;  // TetGen, or reading the filed volume
  std::vector<FleshFrameCost> frames;
  long steps = 0, newtonIterations = 0, conjugateGradientIterations = 0;
};

// The shot's first flesh (shot.flesh[0], resolved by loadShot) with its volume rebuilt at `tetSize`
// (filed as volumes are), simulated from the shot's first frame through `lastFrame`, whole frames
// in order, without filing states (so every step is simulated). Throws InputError when the shot
// has no flesh or the volume cannot be built.
FleshBenchResult measureFleshFrames(const Shot& shot, double tetSize, int lastFrame);

}  // namespace lacrima
