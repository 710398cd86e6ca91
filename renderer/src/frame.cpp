// Frame queries.
#include "lacrima/renderer/frame.hpp"

#include <algorithm>

namespace lacrima {

bool Frame::hasMotion() const {
  return camera.cameraToWorldAtClose.has_value() ||
         std::any_of(meshes.begin(), meshes.end(), [](const MeshInstance& m) { return m.moves(); }) ||
         std::any_of(spheres.begin(), spheres.end(), [](const Sphere& s) { return s.centerAtClose.has_value(); });
}

}  // namespace lacrima
