#pragma once
// Which sampler dimension each decision of a path reads (PixelSampler::setDimension). The same
// decision of every sample of a pixel must read the same dimension for the stratification of
// the Sobol sampler to reach it: a light sample at the second bounce must not read the
// dimension another sample used for its BSDF lobe because its first bounce went below the skin.
// So the camera takes a fixed block and each bounce the next fixed block, whatever it uses.
#include <cstdint>

namespace lacrima::sample_dimensions {

// The camera ray (render.cpp): one 4D block, so that the point in the pixel and the point on the
// lens are stratified together (what a defocused pixel sees depends on both).
constexpr uint32_t kPixelAndLens = 0;  // 4D: pixel x, y (the filter footprint), lens u, v
constexpr uint32_t kTime = 4;          // 1D: the shutter time (motion blur)
constexpr uint32_t kCameraCount = 5;

// Offsets within one bounce's block (integrator.cpp). 4D blocks whose last dimension is unused
// keep the light choice and the point on it (and the BSDF lobe and direction) stratified together.
constexpr uint32_t kLight = 0;             // 4D: which light, the point on it
constexpr uint32_t kSubsurfaceChoice = 4;  // 1D: skin's specular lobes or a walk below them
constexpr uint32_t kExitLight = 5;         // 4D: the light sample at a walk's exit point
constexpr uint32_t kBsdf = 9;              // 4D: the BSDF lobe, the direction
constexpr uint32_t kRoulette = 13;         // 1D: Russian roulette
constexpr uint32_t kBounceCount = 14;

// The first dimension of bounce `depth`'s block (0 = the camera ray's hit).
constexpr uint32_t bounceBase(int depth) { return kCameraCount + uint32_t(depth) * kBounceCount; }

}  // namespace lacrima::sample_dimensions
