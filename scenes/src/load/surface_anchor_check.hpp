#pragma once
// Checking a landmark, vertex or uv surface anchor (read/surface_anchor_reader.hpp) against the
// part of the loaded asset it lies on.
#include <string>

#include "lacrima/io/gltf_asset.hpp"
#include "read/shot_checker.hpp"

namespace lacrima::shotfile {

// Checks the anchor `value` against `part` of `gltf`. Reports (at `pointer`) a landmark the asset
// does not have or that is not on the part, a vertex out of range, a uv no triangle of the part
// covers, and a vertex or uv anchor on a part made of several primitives (the index would be
// ambiguous). False when it reported.
bool checkSurfaceAnchor(Checker& c, const Json& value, const std::string& pointer, const GltfAsset& gltf,
                        const std::string& part);

}  // namespace lacrima::shotfile
