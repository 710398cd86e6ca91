#pragma once
// `lacrima render --resume`: is a frame already on disk, complete and rendered with the settings
// of this run? Anything less (missing, truncated, corrupt, other resolution, spp, seed...) means
// the frame is rendered again.
#include <filesystem>
#include <string>

#include "lacrima/renderer/frame.hpp"

namespace lacrima::cli {

// Empty when `exr` exists and is a complete frame of `expected` (settings with frameNumber set):
// it opens, has the resolution and the R,G,B,A channels (half, or float for floatOutput), its
// lacrima:frame, lacrima:spp, lacrima:seed (and lacrima:maxDepth, when present) match, and every
// pixel of every channel reads back. Otherwise the reason, for a message.
std::string whyFrameMustBeRendered(const std::filesystem::path& exr, const RenderSettings& expected);

}  // namespace lacrima::cli
