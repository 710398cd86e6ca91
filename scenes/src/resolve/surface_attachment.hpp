#pragma once
// Shapes attached to an asset's surface (drops on the skin) follow the skin as the face moves.
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

// For every shape with an 'attach', finds the nearest point of the named part's surface to the
// shape's center at the shot's first frame (the face posed at that frame) and records it.
void resolveAttachments(Shot& shot);

// The nearest surface point of the asset's primitives of `part` to `target`, the asset posed at
// `frame` (world space).
ShotShape::Attachment nearestSurfacePoint(const Shot& shot, size_t asset, const std::string& part, const Vec3& target,
                                          double frame);

// Resolves the surface points of the shot's tears and details (see ShotTear, ShotDetail).
void resolveTearsAndDetails(Shot& shot);

// Interpolated vertex normal at the attachment (normalised; the geometric normal when the mesh
// has no normals or they cancel).
Vec3 attachedNormal(const std::vector<TriangleMesh>& posedPrimitives, const ShotShape::Attachment& attachment);

// Where an attachment's surface point is on the asset's posed primitives (world space, all
// primitives of the asset in order).
Vec3 attachedPoint(const std::vector<TriangleMesh>& posedPrimitives, const ShotShape::Attachment& attachment);

}  // namespace lacrima::shotfile
