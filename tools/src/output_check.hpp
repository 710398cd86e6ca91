#pragma once
// Before a render starts: can its frames be written where they go? A directory that cannot be
// created or written, or a disk without room for a frame, is an error before the first sample
// instead of a failure after the first frame's render time.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "lacrima/renderer/frame.hpp"

namespace lacrima::cli {

// An estimate of one frame's files: the EXR's channels (RGBA + albedo, normal, depth: 11) at
// half (or float) compressed about 2:1, plus the PNG preview. Heuristic, for the space check.
uint64_t estimatedFrameBytes(const RenderSettings& settings, bool preview);

// Throws InputError naming the directory when it cannot be created or written, or when it has
// less free space than one frame needs. Prints a warning when it cannot hold all `frameCount`.
// directories: the distinct directories the frames go to.
void checkOutputDirectories(const std::vector<std::filesystem::path>& directories, uint64_t frameBytes,
                            size_t frameCount);

// The message for `available` free bytes when frames of `frameBytes` are to be written; empty when
// one frame fits. Pure, for tests.
std::string spaceProblem(const std::filesystem::path& directory, uint64_t available, uint64_t frameBytes);

}  // namespace lacrima::cli
