// Step, linear, Catmull-Rom and monotone cubic keyframe interpolation.
#include "lacrima/base/animation_curve.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

void requireValidKeys(const std::vector<ScalarKey>& keys) {
  if (keys.empty()) throw InputError("animation curve has no keys");
  for (size_t i = 0; i < keys.size(); ++i) {
    if (!std::isfinite(keys[i].time) || !std::isfinite(keys[i].value))
      throw InputError(fmt::format("animation curve key {} is not finite (time {}, value {})", i, keys[i].time, keys[i].value));
    if (i > 0 && !(keys[i].time > keys[i - 1].time))
      throw InputError(fmt::format("animation curve key {} at time {} is not after key {} at time {}", i, keys[i].time,
                                   i - 1, keys[i - 1].time));
  }
}

float secant(const std::vector<ScalarKey>& k, size_t i) {
  return (k[i + 1].value - k[i].value) / (k[i + 1].time - k[i].time);
}

// Catmull & Rom 1974 tangents, for non-uniform key times: the slope between the neighbours,
// m_i = (v_{i+1} - v_{i-1}) / (t_{i+1} - t_{i-1}); one-sided at the ends.
std::vector<float> catmullRomTangents(const std::vector<ScalarKey>& k) {
  std::vector<float> m(k.size(), 0.0f);
  if (k.size() < 2) return m;
  m.front() = secant(k, 0);
  m.back() = secant(k, k.size() - 2);
  for (size_t i = 1; i + 1 < k.size(); ++i) m[i] = (k[i + 1].value - k[i - 1].value) / (k[i + 1].time - k[i - 1].time);
  return m;
}

// Fritsch & Carlson 1980: start from averaged secants (zero where the data turns), then shrink
// each interval's pair of tangents into the circle alpha^2 + beta^2 <= 9, which keeps the cubic
// monotone wherever the data is.
std::vector<float> fritschCarlsonTangents(const std::vector<ScalarKey>& k) {
  std::vector<float> m(k.size(), 0.0f);
  if (k.size() < 2) return m;
  std::vector<float> delta(k.size() - 1);
  for (size_t i = 0; i + 1 < k.size(); ++i) delta[i] = secant(k, i);
  m.front() = delta.front();
  m.back() = delta.back();
  for (size_t i = 1; i + 1 < k.size(); ++i)
    m[i] = delta[i - 1] * delta[i] <= 0.0f ? 0.0f : 0.5f * (delta[i - 1] + delta[i]);
  for (size_t i = 0; i < delta.size(); ++i) {
    if (delta[i] == 0.0f) {
      m[i] = m[i + 1] = 0.0f;  // flat data: a flat segment
      continue;
    }
    const float alpha = m[i] / delta[i], beta = m[i + 1] / delta[i];
    const float r2 = alpha * alpha + beta * beta;
    if (r2 > 9.0f) {
      const float tau = 3.0f / std::sqrt(r2);
      m[i] = tau * alpha * delta[i];
      m[i + 1] = tau * beta * delta[i];
    }
  }
  return m;
}

}  // namespace

ScalarCurve::ScalarCurve(std::vector<ScalarKey> keys, Interpolation interpolation)
    : keys_(std::move(keys)), interpolation_(interpolation) {
  requireValidKeys(keys_);
  if (interpolation_ == Interpolation::CatmullRom) tangents_ = catmullRomTangents(keys_);
  if (interpolation_ == Interpolation::MonotoneCubic) tangents_ = fritschCarlsonTangents(keys_);
}

float ScalarCurve::hermite(size_t i, float t) const {
  // A hold (equal keys, flat at both ends) is the key's value exactly: the basis below sums to it
  // only up to rounding, and a held value that differs in its last bit between shutter open and
  // close would motion-blur a still mesh.
  if (keys_[i].value == keys_[i + 1].value && tangents_[i] == 0.0f && tangents_[i + 1] == 0.0f) return keys_[i].value;
  // Cubic Hermite basis on [t_i, t_{i+1}] with key slopes m_i (Fritsch & Carlson 1980; Catmull & Rom 1974 use it too).
  const float h = keys_[i + 1].time - keys_[i].time;
  const float s = (t - keys_[i].time) / h, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * keys_[i].value + (s3 - 2 * s2 + s) * h * tangents_[i] +
         (-2 * s3 + 3 * s2) * keys_[i + 1].value + (s3 - s2) * h * tangents_[i + 1];
}

float ScalarCurve::evaluate(float t) const {
  if (!std::isfinite(t)) throw InputError(fmt::format("animation curve evaluated at a non-finite time ({})", t));
  // Hold outside the keys: an animation starts and ends at rest on its first and last key.
  if (t <= keys_.front().time) return keys_.front().value;
  if (t >= keys_.back().time) return keys_.back().value;
  const auto after = std::upper_bound(keys_.begin(), keys_.end(), t, [](float x, const ScalarKey& k) { return x < k.time; });
  const size_t i = size_t(after - keys_.begin()) - 1;  // keys_[i].time <= t < keys_[i + 1].time
  switch (interpolation_) {
    case Interpolation::Step: return keys_[i].value;
    case Interpolation::Linear: {
      const float s = (t - keys_[i].time) / (keys_[i + 1].time - keys_[i].time);
      return (1.0f - s) * keys_[i].value + s * keys_[i + 1].value;
    }
    case Interpolation::CatmullRom:
    case Interpolation::MonotoneCubic: return hermite(i, t);
  }
  return keys_[i].value;  // unreachable: every enumerator returns above
}

Vec3Curve::Vec3Curve(const std::vector<Vec3Key>& keys, Interpolation interpolation) {
  for (int c = 0; c < 3; ++c) {
    std::vector<ScalarKey> component;
    for (const Vec3Key& k : keys) component.push_back({k.time, k.value[c]});
    components_.emplace_back(std::move(component), interpolation);
  }
}

Vec3 Vec3Curve::evaluate(float t) const {
  return Vec3(components_[0].evaluate(t), components_[1].evaluate(t), components_[2].evaluate(t));
}

}  // namespace lacrima
