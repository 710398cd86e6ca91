#pragma once
// A shot's flesh volumes (ShotFlesh, docs/shot-format.md "flesh") resolved at load: the skin patch
// of their regions on the first frame's pose, the tetrahedral volume under it, and the skin
// vertices embedded in it. Simulated frame by frame by frame/flesh_frame.hpp.
#include <filesystem>
#include <vector>

#include "lacrima/scenes/shot_model.hpp"
#include "resolve/shedding_tear_resolve.hpp"  // SheddingTearProblem: a problem at a JSON pointer

namespace lacrima::shotfile {

using FleshProblem = SheddingTearProblem;

// Where flesh volumes are filed (flesh_volume_cache.hpp): $XDG_CACHE_HOME/lacrima/flesh, else
// ~/.cache/lacrima/flesh; empty (not filed) when neither is set.
std::filesystem::path fleshCacheDirectory();

// Builds (or reads from the cache) each flesh volume of the shot, on the assets
// as loaded (before any refinement of their skin: the volume's boundary is the asset's own
// tessellation, and the simulation poses that asset); the problems found (regions on different
// primitives, no skin in them, a volume TetGen cannot mesh).
std::vector<FleshProblem> resolveFleshVolumes(Shot& shot);

// After the skin is final (refined under details and along tear trails): embeds each vertex of the
// flesh's primitive that lies in (or on) its volume, on the first frame's pose.
void embedFleshSkins(Shot& shot);

}  // namespace lacrima::shotfile
