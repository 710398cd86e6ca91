#pragma once
// Keyframed animation curves: a value over time from keys, held constant outside the keys.
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima {

enum class Interpolation {
  Step,           // the value of the last key at or before t
  Linear,         // straight lines between keys
  CatmullRom,     // C1 cubic through the keys, tangents from the neighbours (may overshoot)
  MonotoneCubic,  // C1 cubic that never overshoots monotone data (Fritsch & Carlson 1980)
};

struct ScalarKey {
  float time = 0.0f;
  float value = 0.0f;
};

class ScalarCurve {
 public:
  // Throws InputError for no keys, non-finite times or values, or times not strictly increasing.
  ScalarCurve(std::vector<ScalarKey> keys, Interpolation interpolation);

  // The value at time t; before the first key the first value, after the last the last value.
  // Throws InputError for a non-finite t.
  float evaluate(float t) const;

  const std::vector<ScalarKey>& keys() const { return keys_; }
  Interpolation interpolation() const { return interpolation_; }

 private:
  float hermite(size_t segment, float t) const;

  std::vector<ScalarKey> keys_;
  Interpolation interpolation_;
  std::vector<float> tangents_;  // dv/dt at each key, for the cubic interpolations
};

struct Vec3Key {
  float time = 0.0f;
  Vec3 value = Vec3::Zero();
};

// A Vec3 curve, interpolated per component: all four interpolations are per-coordinate
// constructions, so this is the same curve as interpolating the vectors.
class Vec3Curve {
 public:
  Vec3Curve(const std::vector<Vec3Key>& keys, Interpolation interpolation);
  Vec3 evaluate(float t) const;

 private:
  std::vector<ScalarCurve> components_;
};

}  // namespace lacrima
