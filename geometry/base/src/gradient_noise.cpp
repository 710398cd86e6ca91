// Perlin's gradient noise; see gradient_noise.hpp.
#include "lacrima/base/gradient_noise.hpp"

#include <algorithm>
#include <cmath>

#include "lacrima/base/hash.hpp"

namespace lacrima {

namespace {

// Perlin 2002: the twelve directions from the centre of a cube to its edges' midpoints.
constexpr float kGradients[12][3] = {{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1},
                                     {1, 0, -1}, {-1, 0, -1}, {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};

float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }

// The lattice point's gradient dotted with the offset (x, y, z) from it.
float ramp(int64_t i, int64_t j, int64_t k, uint64_t seed, float x, float y, float z) {
  uint64_t h = hashCombine(seed, uint64_t(i));
  h = hashCombine(h, uint64_t(j));
  h = hashCombine(h, uint64_t(k));
  const float* g = kGradients[h % 12];
  return g[0] * x + g[1] * y + g[2] * z;
}

float lerp(float t, float a, float b) { return a + t * (b - a); }

}  // namespace

float gradientNoise(const Vec3& p, uint64_t seed) {
  const float fx = std::floor(p.x()), fy = std::floor(p.y()), fz = std::floor(p.z());
  const int64_t i = int64_t(fx), j = int64_t(fy), k = int64_t(fz);
  const float x = p.x() - fx, y = p.y() - fy, z = p.z() - fz;
  const float u = fade(x), v = fade(y), w = fade(z);
  const float x00 = lerp(u, ramp(i, j, k, seed, x, y, z), ramp(i + 1, j, k, seed, x - 1, y, z));
  const float x10 = lerp(u, ramp(i, j + 1, k, seed, x, y - 1, z), ramp(i + 1, j + 1, k, seed, x - 1, y - 1, z));
  const float x01 = lerp(u, ramp(i, j, k + 1, seed, x, y, z - 1), ramp(i + 1, j, k + 1, seed, x - 1, y, z - 1));
  const float x11 =
      lerp(u, ramp(i, j + 1, k + 1, seed, x, y - 1, z - 1), ramp(i + 1, j + 1, k + 1, seed, x - 1, y - 1, z - 1));
  // Edge gradients have length sqrt(2): the bound is then sqrt(2) sqrt(3) / 2 ~ 1.22, reached only
  // in rare corners; clamped so callers can rely on [-1, 1].
  return std::clamp(lerp(w, lerp(v, x00, x10), lerp(v, x01, x11)), -1.0f, 1.0f);
}

float fractalGradientNoise(const Vec3& p, int octaves, uint64_t seed) {
  float sum = 0.0f, amplitude = 1.0f, amplitudes = 0.0f, frequency = 1.0f;
  for (int octave = 0; octave < octaves; ++octave) {
    sum += amplitude * gradientNoise(frequency * p, hashCombine(seed, uint64_t(octave)));
    amplitudes += amplitude;
    amplitude *= 0.5f;
    frequency *= 2.0f;
  }
  return amplitudes > 0.0f ? sum / amplitudes : 0.0f;
}

}  // namespace lacrima
