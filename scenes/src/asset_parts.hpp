#pragma once
// The parts of a glTF asset (GltfPrimitive::part): what shots name to place things on a face.
#include <string>
#include <vector>

#include "lacrima/io/gltf_asset.hpp"

namespace lacrima::shotfile {

// The asset's part names, each once, in the order of their first primitive (unnamed parts left out).
std::vector<std::string> partNames(const GltfAsset& gltf);

bool hasPart(const GltfAsset& gltf, const std::string& part);

// The indices of the primitives that make up `part`.
std::vector<size_t> primitivesOfPart(const GltfAsset& gltf, const std::string& part);

}  // namespace lacrima::shotfile
