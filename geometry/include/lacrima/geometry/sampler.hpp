#pragma once
// Deterministic random numbers: a sample value is a pure function of
// (seed, frame, pixel, sample index, dimension), so images do not depend on thread count.
#include <cstdint>

#include "lacrima/geometry/math.hpp"

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

// The random stream of one pixel sample. Each call consumes one dimension.
class PixelSampler {
 public:
  PixelSampler(uint64_t seed, int frame, int pixelX, int pixelY, int sampleIndex)
      : key_(hashCombine(hashCombine(hashCombine(hashCombine(mix64(seed), uint64_t(uint32_t(frame))),
                                                 uint64_t(uint32_t(pixelX))),
                                     uint64_t(uint32_t(pixelY))),
                         uint64_t(uint32_t(sampleIndex)))) {}

  float get1D() { return uint64ToUnitFloat(hashCombine(key_, dimension_++)); }
  Vec2 get2D() {
    const float a = get1D();
    return Vec2(a, get1D());
  }
  uint32_t dimension() const { return dimension_; }

 private:
  uint64_t key_;
  uint32_t dimension_ = 0;
};

}  // namespace lacrima
