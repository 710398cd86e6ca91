// Light groups; see light_groups.hpp.
#include "lacrima/renderer/light_groups.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "lacrima/renderer/frame.hpp"

namespace lacrima {

namespace {

int groupNamed(LightGroups& groups, const std::string& name) {
  const auto at = std::find(groups.names.begin(), groups.names.end(), name);
  if (at != groups.names.end()) return int(at - groups.names.begin());
  groups.names.push_back(name);
  return int(groups.names.size()) - 1;
}

}  // namespace

LightGroups lightGroupsOf(const Frame& frame) {
  LightGroups groups;
  for (size_t i = 0; i < frame.lights.size(); ++i)
    groups.ofLight.push_back(
        groupNamed(groups, frame.lights[i].group.empty() ? fmt::format("light{}", i) : frame.lights[i].group));
  groups.environment = groupNamed(groups, "environment");
  const bool emits = std::any_of(frame.materials.begin(), frame.materials.end(),
                                 [](const Material& m) { return (m.emission > 0.0f).any(); });
  if (emits) groups.emission = groupNamed(groups, "emission");
  return groups;
}

std::string lightGroupLayer(const std::string& name) { return "lightgroup_" + name; }

}  // namespace lacrima
