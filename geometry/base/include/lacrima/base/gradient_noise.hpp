#pragma once
// Smooth pseudo-random fields on space: Perlin's gradient noise (Perlin 2002, "Improving noise",
// SIGGRAPH: a random gradient at each integer lattice point, its linear ramps blended with the
// quintic fade 6t^5 - 15t^4 + 10t^3 so the field is C2 across cell faces), with the gradients
// chosen from Perlin's twelve cube-edge directions by a hash of the lattice point and a seed
// instead of his permutation table, so a seed gives another field of the same statistics.
#include <cstdint>

#include "lacrima/base/math.hpp"

namespace lacrima {

// Gradient noise at p: 0 at every integer lattice point, smooth (C2) where not clamped, in
// [-1, 1], mean 0, about one bump per unit. A pure function of (p, seed).
float gradientNoise(const Vec3& p, uint64_t seed);

// `octaves` layers of gradientNoise, each at twice the frequency and half the amplitude of the one
// before (a different seed each), divided by the sum of the amplitudes: still in [-1, 1].
float fractalGradientNoise(const Vec3& p, int octaves, uint64_t seed);

}  // namespace lacrima
