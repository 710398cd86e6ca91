#pragma once
// Flesh simulation states kept on disk, one per whole frame of the simulation, so that a frame
// rendered alone (a farm task, a re-render of one frame) continues from the nearest earlier state
// instead of simulating from the shot's first frame. A state is filed under a chain key: the key of
// the frame before combined with what drives this frame (the rig's pose of the volume), starting
// from a key of everything else the simulation depends on (the volume, material and settings). So a
// change anywhere up to a frame (rig, animation, settings) files that frame under another key, and
// a state found under a key is the state that simulation reaches there.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima::flesh {

struct FleshState {
  std::vector<Vec3d> positions, velocities;
};

// The next link of a chain key: `previous` combined with the values that drive the next frame.
uint64_t chainFleshStateKey(uint64_t previous, const std::vector<Vec3d>& drivingValues);

// The file of frame `frameIndex` (whole frames since the simulation's start) in `directory`.
std::filesystem::path fleshStateFile(const std::filesystem::path& directory, long frameIndex, uint64_t key);

// Written whole or not at all; throws std::runtime_error naming the file when it cannot be written.
void writeFleshState(const std::filesystem::path& file, const FleshState& state, uint64_t key);

// The state in `file` when it holds one of `nodes` nodes filed under `key` with finite values;
// nullopt when it is missing, another key's, truncated or corrupt.
std::optional<FleshState> readFleshState(const std::filesystem::path& file, uint64_t key, size_t nodes);

}  // namespace lacrima::flesh
