#pragma once
// Surface anchors: where a tear or a detail sits on a part of an asset, written as a point near
// the skin, a facial landmark, a vertex or a texture coordinate (docs/shot-format.md "Surface
// anchors"), read with the shot, checked against the asset once it is loaded, and resolved to a
// surface point after the assets are final (after any refinement of their meshes).
#include <optional>
#include <string>
#include <vector>

#include "lacrima/scenes/shot_model.hpp"
#include "read/shot_checker.hpp"

namespace lacrima::shotfile {

// Reads an anchor as written: [x, y, z], {"landmark": i}, {"vertex": i} or {"uv": [u, v]}. Reports
// a value of none of these forms; the index or uv of the last three is taken as it is, to be checked
// against the asset by checkSurfaceAnchor.
std::optional<ShotSurfaceAnchor> readSurfaceAnchor(Checker& c, const Json& value, const std::string& pointer);

// Checks a landmark, vertex or uv anchor `value` (read by readSurfaceAnchor) against `part` of the
// loaded asset. Reports (at `pointer`) a landmark the asset does not have or that is not on the
// part, a vertex out of range, a uv no triangle of the part covers, and a vertex or uv anchor on a
// part made of several primitives (the index would be ambiguous). False when it reported.
bool checkSurfaceAnchor(Checker& c, const Json& value, const std::string& pointer, const GltfAsset& gltf,
                        const std::string& part);

// The anchor's surface point, with its position at the shot's first frame as the reference.
// A point is snapped to the nearest surface point of the part (asset posed at the first frame).
ShotSurfacePoint resolveSurfaceAnchor(const Shot& shot, size_t asset, const std::string& part,
                                      const ShotSurfaceAnchor& anchor);

// Per triangle of `mesh`: whether its three corners lie within some region's radius of the
// region's resolved centre (centerPoint.reference).
std::vector<bool> trianglesWithinRegions(const TriangleMesh& mesh, const std::vector<ShotSkinRegion>& regions);

}  // namespace lacrima::shotfile
