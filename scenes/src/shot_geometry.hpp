#pragma once
// Small geometric constructions of the shot format: rotations, look-at frames, rectangles.
#include <optional>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/scenes/shot_model.hpp"

namespace lacrima::shotfile {

// Euler angles in degrees, applied about X first, then Y, then Z (fixed world axes):
// R = Rz * Ry * Rx.
Mat3 eulerXyzDegrees(const Vec3& degrees);
// Rotation by `degrees` about `axis` (any non-zero length), right-handed.
Mat3 axisAngleDegrees(const Vec3& axis, float degrees);

// The camera-to-world transform of a camera at `position` looking at `target` (camera looks down
// -Z with +Y up, as glTF). nullopt when target == position or up is parallel to the view.
std::optional<Affine3> lookAtCameraToWorld(const Vec3& position, const Vec3& target, const Vec3& up);

// True when a and b are (numerically) parallel or one of them is zero.
bool parallel(const Vec3& a, const Vec3& b);

// Edges of a width x height rectangle that faces `normal` (normalize(edgeU x edgeV) == normal):
// edgeU runs along normal x up ("right"), edgeV along the in-plane up reversed. When `up` is
// parallel to `normal`, world -Z is used as up instead (so floors and ceilings need no 'up').
struct RectangleEdges {
  Vec3 edgeU, edgeV;
};
RectangleEdges rectangleFacing(const Vec3& normal, const Vec3& up, const Vec2& size);

// A shape's triangles with its centre at `center`: an ellipsoid's (and a sphere's, tessellated as
// an ellipsoid: the renderer traces spheres analytically, the SPH colliders need triangles) or a
// rectangle's two.
TriangleMesh shapeTriangles(const ShotShape& shape, const Vec3& center);

}  // namespace lacrima::shotfile
