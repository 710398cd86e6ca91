#pragma once
// Shapes attached to an asset's surface (drops on the skin) follow the skin as the face moves.
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

// For every shape with an 'attach', finds the nearest point of the named part's surface to the
// shape's center at the shot's first frame (the face posed at that frame) and records it.
void resolveAttachments(Shot& shot);

// Where an attachment's surface point is on the asset's posed primitives (world space, all
// primitives of the asset in order).
Vec3 attachedPoint(const std::vector<TriangleMesh>& posedPrimitives, const ShotShape::Attachment& attachment);

}  // namespace lacrima::shotfile
