// Evaluation of glTF 2.0 animation channels (spec 3.11, interpolation formulas in Appendix C).
// Arithmetic is in double: key times are floats, but a time in seconds of a long shot is not.
#include "lacrima/io/gltf_animation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "lacrima/base/error.hpp"

namespace lacrima {

namespace {

// Where a time falls among the keys: between key k and k + 1 at fraction u in [0, 1), or held
// at a single key (u = 0, next = key) before the first and after the last key.
struct KeySpan {
  size_t key = 0;
  size_t next = 0;
  double u = 0.0;
  double duration = 0.0;  // t_{k+1} - t_k, the tangent scale of Appendix C
};

KeySpan locate(const std::vector<float>& times, double seconds) {
  // Spec 3.11.3: before the first key and after the last, the value is clamped (held).
  if (seconds <= times.front()) return {0, 0, 0.0, 0.0};
  if (seconds >= times.back()) return {times.size() - 1, times.size() - 1, 0.0, 0.0};
  const size_t next = size_t(std::upper_bound(times.begin(), times.end(), seconds) - times.begin());
  const double t0 = times[next - 1], t1 = times[next];
  return {next - 1, next, (seconds - t0) / (t1 - t0), t1 - t0};
}

// Which of the three values a CUBICSPLINE key stores (Appendix C, in the file's order).
enum class KeyPart { InTangent = 0, Value = 1, OutTangent = 2 };

const float* keyData(const GltfAnimationChannel& c, size_t key, KeyPart part) {
  if (c.interpolation != GltfInterpolation::CubicSpline) return &c.values[key * c.valueSize];
  return &c.values[(3 * key + size_t(part)) * c.valueSize];
}

std::vector<double> keyValue(const GltfAnimationChannel& c, size_t key) {
  const float* p = keyData(c, key, KeyPart::Value);
  return std::vector<double>(p, p + c.valueSize);
}

std::vector<double> lerp(const GltfAnimationChannel& c, const KeySpan& s) {
  const float* a = keyData(c, s.key, KeyPart::Value);
  const float* b = keyData(c, s.next, KeyPart::Value);
  std::vector<double> out(c.valueSize);
  for (size_t i = 0; i < c.valueSize; ++i) out[i] = (1.0 - s.u) * a[i] + s.u * b[i];
  return out;
}

// Appendix C "Spherical Linear Interpolation": a = acos|q_k . q_k+1| along the shorter arc.
std::vector<double> slerp(const GltfAnimationChannel& c, const KeySpan& s) {
  const Eigen::Map<const Eigen::Vector4f> a(keyData(c, s.key, KeyPart::Value));
  const Eigen::Map<const Eigen::Vector4f> b(keyData(c, s.next, KeyPart::Value));
  const Eigen::Vector4d qa = a.cast<double>().normalized(), qb = b.cast<double>().normalized();
  const double dot = qa.dot(qb);
  const double sign = dot < 0.0 ? -1.0 : 1.0;
  const double angle = std::acos(std::min(1.0, std::abs(dot)));
  Eigen::Vector4d q;
  if (angle < 1e-6) {  // sin(angle) ~ 0: the arc is a straight line to double precision
    q = (1.0 - s.u) * qa + s.u * sign * qb;
  } else {
    const double sinAngle = std::sin(angle);
    q = std::sin(angle * (1.0 - s.u)) / sinAngle * qa + sign * std::sin(angle * s.u) / sinAngle * qb;
  }
  return {q[0], q[1], q[2], q[3]};
}

// Appendix C "Cubic Spline Interpolation": Hermite basis on u with tangents times t_{k+1} - t_k.
std::vector<double> cubicSpline(const GltfAnimationChannel& c, const KeySpan& s) {
  const float* v0 = keyData(c, s.key, KeyPart::Value);
  const float* b0 = keyData(c, s.key, KeyPart::OutTangent);
  const float* v1 = keyData(c, s.next, KeyPart::Value);
  const float* a1 = keyData(c, s.next, KeyPart::InTangent);
  const double u = s.u, u2 = u * u, u3 = u2 * u;
  const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
  std::vector<double> out(c.valueSize);
  for (size_t i = 0; i < c.valueSize; ++i)
    out[i] = h00 * v0[i] + s.duration * h10 * b0[i] + h01 * v1[i] + s.duration * h11 * a1[i];
  return out;
}

std::vector<double> interpolate(const GltfAnimationChannel& c, const KeySpan& s) {
  if (s.key == s.next) return keyValue(c, s.key);
  switch (c.interpolation) {
    case GltfInterpolation::Step: return keyValue(c, s.key);  // Appendix C: hold until the next key
    case GltfInterpolation::Linear: return c.path == GltfAnimationPath::Rotation ? slerp(c, s) : lerp(c, s);
    case GltfInterpolation::CubicSpline: return cubicSpline(c, s);
  }
  return keyValue(c, s.key);
}

void normalizeQuaternion(std::vector<double>& q) {
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (norm > 0.0)
    for (double& x : q) x /= norm;
}

Vec3 toVec3(const std::vector<float>& v) { return Vec3(v[0], v[1], v[2]); }

}  // namespace

float GltfAnimation::duration() const {
  float last = 0.0f;
  for (const GltfAnimationChannel& c : channels)
    if (!c.times.empty()) last = std::max(last, c.times.back());
  return last;
}

Affine3 NodeTrs::matrix() const {
  Affine3 m = Affine3::Identity();
  m.translate(translation);
  m.rotate(rotation.normalized());
  m.scale(scale);
  return m;
}

const char* gltfAnimationPathName(GltfAnimationPath path) {
  switch (path) {
    case GltfAnimationPath::Translation: return "translation";
    case GltfAnimationPath::Rotation: return "rotation";
    case GltfAnimationPath::Scale: return "scale";
    case GltfAnimationPath::Weights: return "weights";
  }
  return "unknown";
}

const char* gltfInterpolationName(GltfInterpolation interpolation) {
  switch (interpolation) {
    case GltfInterpolation::Step: return "STEP";
    case GltfInterpolation::Linear: return "LINEAR";
    case GltfInterpolation::CubicSpline: return "CUBICSPLINE";
  }
  return "unknown";
}

const GltfAnimationChannel* findChannel(const GltfAnimation& animation, int node, GltfAnimationPath path) {
  for (const GltfAnimationChannel& c : animation.channels)
    if (c.node == node && c.path == path) return &c;
  return nullptr;
}

std::vector<float> evaluateChannel(const GltfAnimationChannel& channel, double seconds) {
  if (!std::isfinite(seconds)) throw InputError(fmt::format("animation time {} is not finite", seconds));
  std::vector<double> value = interpolate(channel, locate(channel.times, seconds));
  // Spec 3.11.3: rotations are unit quaternions; the cubic spline and float keys drift off them.
  if (channel.path == GltfAnimationPath::Rotation) normalizeQuaternion(value);
  return std::vector<float>(value.begin(), value.end());
}

std::vector<float> evaluateMorphWeights(const GltfAnimation& animation, int node, double seconds, size_t targetCount) {
  const GltfAnimationChannel* channel = findChannel(animation, node, GltfAnimationPath::Weights);
  if (!channel) return std::vector<float>(targetCount, 0.0f);
  if (channel->valueSize != targetCount)
    throw std::invalid_argument(fmt::format("evaluateMorphWeights: the weights channel of node {} animates {} targets, "
                                            "asked for {}", node, channel->valueSize, targetCount));
  return evaluateChannel(*channel, seconds);
}

NodeTrs evaluateNodeTransform(const GltfAnimation& animation, int node, double seconds, const NodeTrs& rest) {
  NodeTrs out = rest;
  if (const auto* c = findChannel(animation, node, GltfAnimationPath::Translation))
    out.translation = toVec3(evaluateChannel(*c, seconds));
  if (const auto* c = findChannel(animation, node, GltfAnimationPath::Scale)) out.scale = toVec3(evaluateChannel(*c, seconds));
  if (const auto* c = findChannel(animation, node, GltfAnimationPath::Rotation)) {
    const std::vector<float> q = evaluateChannel(*c, seconds);
    out.rotation = Eigen::Quaternionf(q[3], q[0], q[1], q[2]);  // glTF stores x y z w, Eigen's constructor takes w first
  }
  return out;
}

}  // namespace lacrima
