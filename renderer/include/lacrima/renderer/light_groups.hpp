#pragma once
// Light groups: the beauty split by where its light came from, one layer a group, so that a
// compositor regrades the key light alone. Every area light belongs to the group its `group`
// names (lights sharing a name share a layer; without a name, a group of its own, "light<i>");
// the environment (or the uniform background) is the group "environment", and light emitted by
// emissive materials the group "emission" (when a material emits). Each camera sample's radiance
// is split by the light each contribution came from, next-event or hit, at any depth, so the
// groups add up to the beauty sample by sample (to float rounding).
#include <string>
#include <vector>

namespace lacrima {

struct Frame;

struct LightGroups {
  std::vector<std::string> names;  // in order of first appearance: lights, environment, emission
  std::vector<int> ofLight;        // per area light, its group
  int environment = -1;
  int emission = -1;               // -1 when no material emits

  size_t size() const { return names.size(); }
  // The group of a light sample or hit: an area light's, or the environment's for -1.
  int ofSource(int lightIndex) const { return lightIndex >= 0 ? ofLight[size_t(lightIndex)] : environment; }
};

LightGroups lightGroupsOf(const Frame& frame);

// The EXR layer name of a group: "lightgroup_<name>".
std::string lightGroupLayer(const std::string& name);

}  // namespace lacrima
