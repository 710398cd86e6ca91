// Frame queries.
#include "lacrima/renderer/frame.hpp"

#include <algorithm>

namespace lacrima {

bool Frame::hasMotion() const {
  return camera.cameraToWorldAtClose.has_value() ||
         std::any_of(meshes.begin(), meshes.end(), [](const MeshInstance& m) { return m.moves(); }) ||
         std::any_of(spheres.begin(), spheres.end(), [](const Sphere& s) { return s.centerAtClose.has_value(); });
}

const std::vector<std::string>& aovNames() {
  static const std::vector<std::string> names = {"CryptoObject", "CryptoMaterial", "lightGroups"};
  return names;
}

bool enableAov(RenderSettings& s, const std::string& name) {
  if (name == "CryptoObject") s.cryptomatte.objects = true;
  else if (name == "CryptoMaterial") s.cryptomatte.materials = true;
  else if (name == "lightGroups") s.lightGroups = true;
  else return false;
  return true;
}

}  // namespace lacrima
