#pragma once
// `lacrima render --resume`: is a frame already on disk, complete and rendered with the settings
// of this run? Anything less (missing, truncated, corrupt, other resolution, spp, seed...) means
// the frame is rendered again.
#include <filesystem>
#include <map>
#include <string>

#include "lacrima/renderer/frame.hpp"

namespace lacrima::cli {

// The settings besides resolution, spp and seed that change a frame's pixels, as the EXR header
// attributes `lacrima render` writes (lacrima:maxDepth, lacrima:sampler, lacrima:filter,
// lacrima:bounces, lacrima:caustics): --resume compares them.
std::map<std::string, std::string> pixelSettingsMetadata(const RenderSettings& s);

// Empty when `exr` exists and is a complete frame of `expected` (settings with frameNumber set):
// it opens, has the resolution and the R,G,B,A channels (half, or float for floatOutput), its
// lacrima:frame, lacrima:spp, lacrima:seed and those of pixelSettingsMetadata (each one the file
// has: older frames lack some) match, and every pixel of every channel reads back. Otherwise the
// reason, for a message.
std::string whyFrameMustBeRendered(const std::filesystem::path& exr, const RenderSettings& expected);

}  // namespace lacrima::cli
