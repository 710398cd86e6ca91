#pragma once
// The shot's eyes and lashes at one frame: built on the posed (shutter-open, and with motion blur
// shutter-close) eyeball shells and lash cards.
#include <vector>

#include "lacrima/renderer/frame.hpp"
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

// Adds each eye's cornea, sclera, iris and pupil and its lashes to the frame (names
// "<asset>/<part>/cornea", ..., "<asset>/<part>/lashes"). closeAssets: null without motion blur;
// an asset's entry there is empty when it does not move.
void addEyes(const Shot& shot, const std::vector<std::vector<TriangleMesh>>& openAssets,
             const std::vector<std::vector<TriangleMesh>>* closeAssets, Frame& frame);

}  // namespace lacrima::shotfile
