#pragma once
// Subdivision of the skin under the details that ask for it (a detail's "subdivision",
// docs/shot-format.md "details"): fine wrinkles need more vertices than a face mesh has, but
// only where the wrinkles are.
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

// For every asset with details whose subdivisionLevels > 0: a copy of its glTF asset in which,
// detail after detail (file order), the primitives of the detail's part are refined around the
// detail (region: see detailRegionTriangles), replacing ShotAsset::gltf; the asset's rig, when it
// has one, is rebuilt on the refined asset with its configuration. Run before surface points are
// resolved: they index the refined triangles.
void refineDetailRegions(Shot& shot);

// The detail's region on one neutral primitive in world space (`world`, welded by `weldMap`):
// the triangles with a corner within 1.25 max(extent) of `center` in the tangent plane of
// `normal` and within max(extent) of it along the normal (the region test of buildFrame's
// displacement, with a margin), grown by one ring of triangles.
std::vector<bool> detailRegionTriangles(const TriangleMesh& world, const std::vector<uint32_t>& weldMap,
                                        const Vec3& center, const Vec3& normal, float maxExtent);

}  // namespace lacrima::shotfile
