#pragma once
// Hashes for deterministic pseudo-random values: each value a pure function of its key (seed,
// pixel, particle, pore...), so results depend neither on thread count nor on evaluation order.
// The renderer's per-pixel sampler (renderer/sampler.hpp) is built on these.
#include <cstdint>

namespace lacrima {

// 64-bit finaliser of SplitMix64 (Steele et al., "Fast splittable pseudorandom number
// generators", OOPSLA 2014); a strong bijective mixer.
inline uint64_t mix64(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

inline uint64_t hashCombine(uint64_t seed, uint64_t value) {
  return mix64(seed ^ (value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2)));
}

// Top 24 bits to a float in [0, 1).
inline float uint64ToUnitFloat(uint64_t x) { return float(x >> 40) * 0x1p-24f; }

}  // namespace lacrima
