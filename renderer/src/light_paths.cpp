// Light-path AOVs; see light_paths.hpp.
#include "lacrima/renderer/light_paths.hpp"

namespace lacrima {

const std::string& lightPathName(LightPath pass) {
  static const std::array<std::string, kLightPathCount> names = {
      "diffuse_direct",        "diffuse_indirect", "specular_direct", "specular_indirect", "transmission_direct",
      "transmission_indirect", "subsurface",       "emission",        "environment"};
  return names[size_t(pass)];
}

const std::array<LightPath, kLightPathCount>& allLightPaths() {
  static const std::array<LightPath, kLightPathCount> passes = {
      LightPath::DiffuseDirect,      LightPath::DiffuseIndirect,      LightPath::SpecularDirect,
      LightPath::SpecularIndirect,   LightPath::TransmissionDirect,   LightPath::TransmissionIndirect,
      LightPath::Subsurface,         LightPath::Emission,             LightPath::Environment};
  return passes;
}

}  // namespace lacrima
