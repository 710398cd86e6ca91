// The parts of a glTF asset; see asset_parts.hpp.
#include "asset_parts.hpp"

#include <algorithm>

namespace lacrima::shotfile {

std::vector<std::string> partNames(const GltfAsset& gltf) {
  std::vector<std::string> parts;
  for (const GltfPrimitive& p : gltf.primitives)
    if (!p.part.empty() && std::find(parts.begin(), parts.end(), p.part) == parts.end()) parts.push_back(p.part);
  return parts;
}

bool hasPart(const GltfAsset& gltf, const std::string& part) {
  return std::any_of(gltf.primitives.begin(), gltf.primitives.end(),
                     [&](const GltfPrimitive& p) { return !p.part.empty() && p.part == part; });
}

std::vector<size_t> primitivesOfPart(const GltfAsset& gltf, const std::string& part) {
  std::vector<size_t> found;
  for (size_t i = 0; i < gltf.primitives.size(); ++i)
    if (gltf.primitives[i].part == part) found.push_back(i);
  return found;
}

}  // namespace lacrima::shotfile
