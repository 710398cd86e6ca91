#pragma once
// Surface anchors resolved: where a tear or a detail sits on a part of an asset (read by
// read/surface_anchor_reader.hpp, checked by load/surface_anchor_check.hpp) as a surface point, once
// the assets are final (after any refinement of their meshes).
#include <optional>
#include <string>
#include <vector>

#include "lacrima/scenes/shot_model.hpp"
#include "read/shot_checker.hpp"

namespace lacrima::shotfile {

// The anchor's surface point, with its position at the shot's first frame as the reference.
// A point is snapped to the nearest surface point of the part (asset posed at the first frame).
ShotSurfacePoint resolveSurfaceAnchor(const Shot& shot, size_t asset, const std::string& part,
                                      const ShotSurfaceAnchor& anchor);

// Per triangle of `mesh`: whether its three corners lie within some region's radius of the
// region's resolved centre (centerPoint.reference).
std::vector<bool> trianglesWithinRegions(const TriangleMesh& mesh, const std::vector<ShotSkinRegion>& regions);

}  // namespace lacrima::shotfile
