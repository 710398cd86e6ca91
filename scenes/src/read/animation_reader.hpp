#pragma once
// Reading animatable values of a shot file: a plain value, or
//   {"keys": [[frame, value], ...], "interpolation": "monotone"}
// with frames strictly increasing. Interpolations: "step", "linear", "smooth" (Catmull-Rom) and
// "monotone" (the default: smooth without overshoot, so weights keyed in [0, 1] stay there).
#include <optional>
#include <string>

#include "lacrima/scenes/animated_value.hpp"
#include "read/shot_checker.hpp"

namespace lacrima::shotfile {

// True when the value is written as keys (an object), so callers can tell still from animated.
bool isKeyed(const Json& v);

std::optional<AnimatedFloat> readAnimatedNumber(Checker& c, const Json& v, const std::string& pointer, Range range);
std::optional<AnimatedVec3> readAnimatedVec3(Checker& c, const Json& v, const std::string& pointer);

}  // namespace lacrima::shotfile
