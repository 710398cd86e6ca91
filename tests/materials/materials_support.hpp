#pragma once
// Helpers shared by the materials tests: a deterministic random stream and direction helpers.
#include <cmath>
#include <cstdint>

#include "lacrima/base/math.hpp"
#include "lacrima/base/hash.hpp"

namespace lacrima::test {

// Deterministic stream: value k is a pure function of (seed, k) (renderer/sampler.hpp hashing).
class TestRng {
 public:
  explicit TestRng(uint64_t seed) : key_(mix64(seed)) {}
  float uniform() { return uint64ToUnitFloat(hashCombine(key_, counter_++)); }
  Vec2 uniform2() {
    const float a = uniform();
    return Vec2(a, uniform());
  }
  // Uniform direction on the unit sphere (Archimedes: z uniform in [-1, 1]).
  Vec3 sphere() {
    const float z = 1.0f - 2.0f * uniform();
    const float phi = 2.0f * kPi * uniform();
    const float r = safeSqrt(1.0f - z * z);
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
  }

 private:
  uint64_t key_;
  uint64_t counter_ = 0;
};

// Unit direction with the given cos(theta) to the z axis and azimuth phi.
inline Vec3 directionFromCosPhi(double cosTheta, double phi) {
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return Vec3(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta));
}

inline double relativeError(double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale == 0.0 ? 0.0 : std::abs(a - b) / scale;
}

}  // namespace lacrima::test
