// The procedural iris; see iris_pattern.hpp for the layers and their sources.
#include "lacrima/materials/iris_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "lacrima/face/eye.hpp"
#include "lacrima/base/hash.hpp"

namespace lacrima {

namespace {

constexpr uint64_t kIrisSeed = 0x69726973ULL;  // "iris": decorrelates from other hashed streams

// Independent noise streams of one pattern.
enum Stream : uint64_t { kFibres = 1, kFineFibres, kCollarette, kCrypts };

// Where a point of the iris is: around it (0 to 1 from `right` towards `up`) and across it (0 at
// the pupil margin, 1 at the root).
struct IrisPoint {
  float around = 0.0f;
  float across = 0.0f;
};

IrisPoint irisPointAt(const Vec2& uv) {
  const float x = 2.0f * (uv.x() - 0.5f), y = -2.0f * (uv.y() - 0.5f);
  const float radius = std::sqrt(x * x + y * y);
  float around = std::atan2(y, x) * kInv2Pi;
  if (around < 0.0f) around += 1.0f;
  const float across = (radius - kIrisUvPupilRadius) / (1.0f - kIrisUvPupilRadius);
  return {around, std::clamp(across, 0.0f, 1.0f)};
}

float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

float latticeValue(uint64_t stream, int64_t i, int64_t j) {
  return uint64ToUnitFloat(hashCombine(hashCombine(stream, uint64_t(i)), uint64_t(j)));
}

// Value noise in [0, 1) on a lattice of unit cells, periodic in x with `period` cells (the iris
// closes on itself), smooth (quintic fade) between the lattice values.
float periodicValueNoise(uint64_t stream, float x, float y, int period) {
  const float fx = std::floor(x), fy = std::floor(y);
  const int64_t i = int64_t(fx), j = int64_t(fy);
  const auto fade = [](float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); };
  const float tx = fade(x - fx), ty = fade(y - fy);
  const auto wrap = [period](int64_t k) { return ((k % period) + period) % period; };
  const float v00 = latticeValue(stream, wrap(i), j), v10 = latticeValue(stream, wrap(i + 1), j);
  const float v01 = latticeValue(stream, wrap(i), j + 1), v11 = latticeValue(stream, wrap(i + 1), j + 1);
  return (v00 + tx * (v10 - v00)) + ty * ((v01 + tx * (v11 - v01)) - (v00 + tx * (v10 - v00)));
}

// Fibres: many cells around, few across, so the noise streaks radially.
float fibresAt(uint64_t seed, const IrisPoint& p) {
  constexpr int kCoarse = 96, kFine = 224;
  return 0.6f * periodicValueNoise(hashCombine(seed, kFibres), p.around * kCoarse, p.across * 3.0f, kCoarse) +
         0.4f * periodicValueNoise(hashCombine(seed, kFineFibres), p.around * kFine, p.across * 7.0f, kFine);
}

// The collarette's distance across from the pupil margin: about a third of the way, wavy.
float collaretteAt(uint64_t seed, float around) {
  constexpr int kWaves = 14;
  return 0.30f + 0.10f * (periodicValueNoise(hashCombine(seed, kCollarette), around * kWaves, 0.5f, kWaves) - 0.5f);
}

// How far a point lies inside a crypt (0 outside, 1 at its centre): crypts sit in the cells of a
// lattice of 28 around by 6 across, at most one per cell, about 40 % of the cells just outside the
// collarette holding one, a narrow ellipse elongated across (along the fibres).
float cryptAt(uint64_t seed, const IrisPoint& p, float collarette) {
  constexpr int kAround = 28;
  constexpr float kAcross = 6.0f;
  const uint64_t stream = hashCombine(seed, kCrypts);
  const float x = p.around * kAround, y = p.across * kAcross;
  float deepest = 0.0f;
  for (int di = -1; di <= 1; ++di)
    for (int dj = -1; dj <= 1; ++dj) {
      const int64_t i = int64_t(std::floor(x)) + di, j = int64_t(std::floor(y)) + dj;
      const int64_t wrapped = ((i % kAround) + kAround) % kAround;
      const uint64_t cell = hashCombine(hashCombine(stream, uint64_t(wrapped)), uint64_t(j));
      if (uint64ToUnitFloat(hashCombine(cell, 0)) > 0.4f) continue;  // no crypt in this cell
      const float cx = float(i) + 0.2f + 0.6f * uint64ToUnitFloat(hashCombine(cell, 1));
      const float cy = float(j) + 0.2f + 0.6f * uint64ToUnitFloat(hashCombine(cell, 2));
      const float centreAcross = cy / kAcross;
      if (centreAcross < collarette + 0.03f || centreAcross > 0.6f) continue;
      const float size = 0.5f + 0.5f * uint64ToUnitFloat(hashCombine(cell, 3));
      const float ex = (x - cx) / (0.16f * size), ey = (y - cy) / (0.8f * size);
      deepest = std::max(deepest, 1.0f - smoothstep(0.5f, 1.0f, std::sqrt(ex * ex + ey * ey)));
    }
  return deepest;
}

Color mix(const Color& a, const Color& b, float t) { return a + t * (b - a); }

}  // namespace

IrisPattern::IrisPattern(uint64_t seed) : seed_(seed) {
  // Renderers build their patterns every frame: each seed's mean is computed once per process.
  static std::mutex mutex;
  static std::map<uint64_t, Color> normalisations;
  const std::lock_guard<std::mutex> lock(mutex);
  const auto known = normalisations.find(seed);
  if (known != normalisations.end()) {
    normalisation_ = known->second;
    return;
  }
  // The mean of the raw factors over the iris's area (uv area: the disc's annulus), on a polar
  // grid finer than the finest noise, weighted by radius.
  constexpr int kAcrossSteps = 32, kAroundSteps = 448;
  Color sum(0.0f, 0.0f, 0.0f);
  float weight = 0.0f;
  for (int a = 0; a < kAcrossSteps; ++a) {
    const float radius = kIrisUvPupilRadius + (1.0f - kIrisUvPupilRadius) * (float(a) + 0.5f) / float(kAcrossSteps);
    for (int b = 0; b < kAroundSteps; ++b) {
      const float phi = 2.0f * kPi * (float(b) + 0.5f) / float(kAroundSteps);
      sum += radius * rawFactorAt(Vec2(0.5f + 0.5f * radius * std::cos(phi), 0.5f - 0.5f * radius * std::sin(phi)));
      weight += radius;
    }
  }
  normalisation_ = weight / sum;
  normalisations.emplace(seed, normalisation_);
}

Color IrisPattern::factorAt(const Vec2& uv) const { return rawFactorAt(uv) * normalisation_; }

Color IrisPattern::rawFactorAt(const Vec2& uv) const {
  const uint64_t seed = hashCombine(kIrisSeed, seed_);
  const IrisPoint p = irisPointAt(uv);
  const float fibres = fibresAt(seed, p);
  const float collarette = collaretteAt(seed, p.around);
  // Stroma: fibres brighten and darken it; the pupillary zone inside the collarette is darker.
  Color factor = Color::Constant(0.4f + 1.2f * fibres);
  factor *= mix(Color(0.7f, 0.62f, 0.58f), Color(1.0f, 1.0f, 1.0f), smoothstep(collarette - 0.03f, collarette, p.across));
  // The collarette: a lighter, warmer ridge, itself broken by the fibres.
  const float ridge = std::exp(-std::pow((p.across - collarette) / 0.04f, 2.0f)) * (0.5f + 0.5f * fibres);
  factor *= mix(Color(1.0f, 1.0f, 1.0f), Color(2.2f, 1.9f, 1.3f), ridge);
  // Crypts: dark openings.
  factor *= mix(Color(1.0f, 1.0f, 1.0f), Color(0.35f, 0.32f, 0.3f), cryptAt(seed, p, collarette));
  // The pupillary ruff and the limbal ring.
  factor *= mix(Color(0.3f, 0.28f, 0.26f), Color(1.0f, 1.0f, 1.0f), smoothstep(0.0f, 0.05f, p.across));
  factor *= mix(Color(1.0f, 1.0f, 1.0f), Color(0.35f, 0.36f, 0.4f), smoothstep(0.8f, 1.0f, p.across));
  return factor;
}

}  // namespace lacrima
