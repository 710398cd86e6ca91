#pragma once
// Animator controls over a face rig: Bao et al. 2019 eq. 2, x(w) = T(j(w))(n + B b(w)).
// Each control is a slider with a range; it maps linearly to blendshape weights b and joint
// parameters j. This file computes b(w) and j(w); FaceRig evaluates x.
#include <map>
#include <string>
#include <vector>

#include "lacrima/rig/face_rig.hpp"

namespace lacrima {

// output += gain * (control value clamped to its range)
struct ControlMapping {
  std::string name;  // a blendshape name, or a joint channel (see FaceControls::jointChannelNames)
  float gain = 1.0f;
};

struct FaceControl {
  std::string name;
  float min = 0.0f;
  float max = 1.0f;
  std::vector<ControlMapping> blendshapes;
  std::vector<ControlMapping> joints;
};

class FaceControls {
 public:
  // Validates every name once so evaluation cannot fail on a typo made in a rig file. Throws
  // InputError for an unknown blendshape or joint channel (naming the closest valid one), a
  // duplicate control name, or a range that is not finite with min <= max.
  FaceControls(std::vector<std::string> targetNames, std::vector<std::string> eyeNames, std::vector<FaceControl> controls);
  FaceControls(const FaceRig& rig, std::vector<FaceControl> controls);

  // b(w) and j(w): each given control clamped to its range, contributions summed, blendshape
  // weights then clamped to [0, 1]. Controls not given are at 0 clamped to their range. Throws
  // InputError for an unknown control name (with the closest one) or a non-finite value.
  FacePose evaluate(const std::map<std::string, float>& values) const;

  const std::vector<FaceControl>& controls() const { return controls_; }

  // "head.rx", "head.ry", "head.rz" (Euler degrees), "head.tx", "head.ty", "head.tz" (metres),
  // the same for "jaw.", then "eye.<name>.rx/ry/rz" for each eye, in this order.
  static std::vector<std::string> jointChannelNames(const std::vector<std::string>& eyeNames);

 private:
  struct ResolvedMapping {
    size_t index;
    float gain;
  };
  std::vector<std::string> targetNames_;
  std::vector<std::string> eyeNames_;
  std::vector<FaceControl> controls_;
  std::vector<std::vector<ResolvedMapping>> blendshapeMaps_;  // per control
  std::vector<std::vector<ResolvedMapping>> jointMaps_;       // per control, into jointChannelNames
};

}  // namespace lacrima
