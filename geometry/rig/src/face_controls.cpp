// Animator controls: b(w) and j(w) of Bao et al. 2019 eq. 2.
#include "lacrima/rig/face_controls.hpp"

#include <cmath>
#include <set>

#include <fmt/format.h>

#include "lacrima/base/error.hpp"
#include "lacrima/base/name_suggestion.hpp"

namespace lacrima {

namespace {

constexpr size_t kRigidChannels = 6;  // rx ry rz tx ty tz
constexpr size_t kEyeChannels = 3;    // rx ry rz: an eye only turns

size_t indexOrThrow(const std::string& what, const std::string& name, const std::vector<std::string>& valid) {
  for (size_t i = 0; i < valid.size(); ++i)
    if (valid[i] == name) return i;
  throw InputError(unknownNameMessage(what, name, valid));
}

void requireValidRange(const FaceControl& c) {
  if (!std::isfinite(c.min) || !std::isfinite(c.max) || c.min > c.max)
    throw InputError(fmt::format("face control '{}' has an invalid range [{}, {}]", c.name, c.min, c.max));
}

RigidJoint jointFromChannels(const std::vector<float>& channels, size_t first) {
  RigidJoint j;
  j.eulerDegrees = Vec3(channels[first], channels[first + 1], channels[first + 2]);
  j.translation = Vec3(channels[first + 3], channels[first + 4], channels[first + 5]);
  return j;
}

}  // namespace

std::vector<std::string> FaceControls::jointChannelNames(const std::vector<std::string>& eyeNames) {
  std::vector<std::string> names;
  for (const char* joint : {"head", "jaw"})
    for (const char* channel : {"rx", "ry", "rz", "tx", "ty", "tz"}) names.push_back(fmt::format("{}.{}", joint, channel));
  for (const std::string& eye : eyeNames)
    for (const char* channel : {"rx", "ry", "rz"}) names.push_back(fmt::format("eye.{}.{}", eye, channel));
  return names;
}

FaceControls::FaceControls(std::vector<std::string> targetNames, std::vector<std::string> eyeNames,
                           std::vector<FaceControl> controls)
    : targetNames_(std::move(targetNames)), eyeNames_(std::move(eyeNames)), controls_(std::move(controls)) {
  const std::vector<std::string> channels = jointChannelNames(eyeNames_);
  std::set<std::string> seen;
  for (const FaceControl& c : controls_) {
    if (!seen.insert(c.name).second) throw InputError(fmt::format("face control '{}' is defined twice", c.name));
    requireValidRange(c);
    std::vector<ResolvedMapping>& b = blendshapeMaps_.emplace_back();
    for (const ControlMapping& m : c.blendshapes)
      b.push_back({indexOrThrow(fmt::format("blendshape in control '{}':", c.name), m.name, targetNames_), m.gain});
    std::vector<ResolvedMapping>& j = jointMaps_.emplace_back();
    for (const ControlMapping& m : c.joints)
      j.push_back({indexOrThrow(fmt::format("joint channel in control '{}':", c.name), m.name, channels), m.gain});
  }
}

FaceControls::FaceControls(const FaceRig& rig, std::vector<FaceControl> controls)
    : FaceControls(rig.targetNames(), [&] {
        std::vector<std::string> eyes;
        for (const EyeballSpec& e : rig.config().eyes) eyes.push_back(e.name);
        return eyes;
      }(), std::move(controls)) {}

FacePose FaceControls::evaluate(const std::map<std::string, float>& values) const {
  std::vector<std::string> controlNames;
  for (const FaceControl& c : controls_) controlNames.push_back(c.name);
  std::vector<float> clampedValues(controls_.size());
  for (size_t i = 0; i < controls_.size(); ++i) clampedValues[i] = std::clamp(0.0f, controls_[i].min, controls_[i].max);
  for (const auto& [name, value] : values) {
    const size_t i = indexOrThrow("face control", name, controlNames);
    if (!std::isfinite(value)) throw InputError(fmt::format("face control '{}' is not finite ({})", name, value));
    clampedValues[i] = std::clamp(value, controls_[i].min, controls_[i].max);
  }

  // Bao et al. 2019 eq. 2: b(w) and j(w), here linear maps of the clamped controls, summed.
  FacePose pose;
  pose.blendshapeWeights.assign(targetNames_.size(), 0.0f);
  std::vector<float> channels(2 * kRigidChannels + kEyeChannels * eyeNames_.size(), 0.0f);
  for (size_t i = 0; i < controls_.size(); ++i) {
    for (const ResolvedMapping& m : blendshapeMaps_[i]) pose.blendshapeWeights[m.index] += m.gain * clampedValues[i];
    for (const ResolvedMapping& m : jointMaps_[i]) channels[m.index] += m.gain * clampedValues[i];
  }
  // Sculpted targets are only valid between neutral and full strength.
  for (float& w : pose.blendshapeWeights) w = clamp01(w);
  pose.head = jointFromChannels(channels, 0);
  pose.jaw = jointFromChannels(channels, kRigidChannels);
  for (size_t e = 0; e < eyeNames_.size(); ++e) {
    const size_t first = 2 * kRigidChannels + kEyeChannels * e;
    pose.eyeEulerDegrees.emplace_back(channels[first], channels[first + 1], channels[first + 2]);
  }
  return pose;
}

}  // namespace lacrima
