#pragma once
// How hard the skin holds a liquid tear's contact line, from place to place (ShotLiquidTear's
// "pinning"; LiquidPathSample::pinning in the simulation).
#include <vector>

#include "lacrima/mesh/mesh.hpp"

namespace lacrima::shotfile {

// The patches' noise is stretched by this and clamped to [-1, 1] (gradient noise clusters around 0
// with a standard deviation near 0.2): most of the skin holds clearly harder or clearly softer, as
// a patchwork of oily, dry and hairy skin does, instead of nearly the same everywhere.
inline constexpr float kPinningContrast = 3.0f;
inline constexpr int kPinningOctaves = 2;

// Per vertex of the skin as posed on the shot's first frame: the factor maxFactor^v, v = a
// two-octave gradient noise (gradient_noise.hpp) of the position over patchSize, stretched by
// kPinningContrast and clamped to [-1, 1]; so factors from 1 / maxFactor to maxFactor, in patches
// about patchSize across that ride with the skin as it deforms. maxFactor >= 1, patchSize > 0.
std::vector<float> skinPinning(const TriangleMesh& skinAtFirstFrame, double maxFactor, double patchSize);

}  // namespace lacrima::shotfile
