// Frame queries.
#include "lacrima/renderer/frame.hpp"

#include <algorithm>

namespace lacrima {

const char* causticsName(Caustics caustics) {
  switch (caustics) {
    case Caustics::Off: return "off";
    case Caustics::Straight: return "straight";
    case Caustics::Mnee: return "mnee";
  }
  return "?";
}

bool Frame::hasMotion() const {
  return camera.cameraToWorldAtClose.has_value() ||
         std::any_of(meshes.begin(), meshes.end(), [](const MeshInstance& m) { return m.moves(); }) ||
         std::any_of(spheres.begin(), spheres.end(), [](const Sphere& s) { return s.centerAtClose.has_value(); });
}

const std::vector<std::string>& aovNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = {"CryptoObject", "CryptoMaterial", "lightGroups", "lightPaths"};
    for (const LightPath pass : allLightPaths()) all.push_back(lightPathName(pass));
    return all;
  }();
  return names;
}

bool enableAov(RenderSettings& s, const std::string& name) {
  if (name == "CryptoObject") s.cryptomatte.objects = true;
  else if (name == "CryptoMaterial") s.cryptomatte.materials = true;
  else if (name == "lightGroups") s.lightGroups = true;
  else if (name == "lightPaths") s.lightPaths.addAll();
  else {
    const auto& passes = allLightPaths();
    const auto pass = std::find_if(passes.begin(), passes.end(), [&](LightPath p) { return lightPathName(p) == name; });
    if (pass == passes.end()) return false;
    s.lightPaths.add(*pass);
  }
  return true;
}

}  // namespace lacrima
