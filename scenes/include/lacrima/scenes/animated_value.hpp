#pragma once
// Values of a shot that may change over the shot's frames: a constant, or keys at frame numbers
// interpolated by an animation curve. Fractional frames are valid times (motion blur samples
// the shutter interval around a frame).
#include <memory>

#include "lacrima/base/animation_curve.hpp"
#include "lacrima/base/math.hpp"

namespace lacrima {

struct AnimatedFloat {
  float constant = 0.0f;
  std::shared_ptr<const ScalarCurve> curve;  // keys in frames; null when constant

  bool animated() const { return curve != nullptr; }
  float at(double frame) const { return curve ? curve->evaluate(float(frame)) : constant; }
};

struct AnimatedVec3 {
  Vec3 constant = Vec3::Zero();
  std::shared_ptr<const Vec3Curve> curve;  // keys in frames; null when constant

  bool animated() const { return curve != nullptr; }
  Vec3 at(double frame) const { return curve ? curve->evaluate(float(frame)) : constant; }
};

}  // namespace lacrima
