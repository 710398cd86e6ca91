#include "shot_geometry.hpp"

#include "lacrima/mesh/shapes.hpp"

namespace lacrima::shotfile {

Mat3 eulerXyzDegrees(const Vec3& degrees) {
  using Eigen::AngleAxisf;
  return (AngleAxisf(degreesToRadians(degrees.z()), Vec3::UnitZ()) *
          AngleAxisf(degreesToRadians(degrees.y()), Vec3::UnitY()) *
          AngleAxisf(degreesToRadians(degrees.x()), Vec3::UnitX()))
      .toRotationMatrix();
}

Mat3 axisAngleDegrees(const Vec3& axis, float degrees) {
  return Eigen::AngleAxisf(degreesToRadians(degrees), axis.normalized()).toRotationMatrix();
}

bool parallel(const Vec3& a, const Vec3& b) {
  const float na = a.norm(), nb = b.norm();
  if (!(na > 0.0f) || !(nb > 0.0f)) return true;
  return a.cross(b).norm() <= 1e-6f * na * nb;
}

std::optional<Affine3> lookAtCameraToWorld(const Vec3& position, const Vec3& target, const Vec3& up) {
  const Vec3 view = target - position;
  if (!(view.norm() > 0.0f) || parallel(view, up)) return std::nullopt;
  const Vec3 forward = view.normalized();
  const Vec3 right = forward.cross(up).normalized();
  const Vec3 trueUp = right.cross(forward);
  Affine3 m = Affine3::Identity();
  m.linear().col(0) = right;
  m.linear().col(1) = trueUp;
  m.linear().col(2) = -forward;
  m.translation() = position;
  return m;
}

RectangleEdges rectangleFacing(const Vec3& normal, const Vec3& up, const Vec2& size) {
  const Vec3 n = normal.normalized();
  const Vec3 u = !parallel(n, up) ? up : !parallel(n, Vec3(0, 0, -1)) ? Vec3(0, 0, -1) : Vec3(0, 1, 0);
  const Vec3 right = n.cross(u).normalized();
  const Vec3 inPlaneUp = right.cross(n);
  // right x (-inPlaneUp) = n (right, inPlaneUp, -n is a right-handed frame).
  return {right * size.x(), -inPlaneUp * size.y()};
}

TriangleMesh shapeTriangles(const ShotShape& shape, const Vec3& center) {
  switch (shape.type) {
    case ShotShape::Type::Sphere:
      return makeEllipsoid(center, Mat3(shape.radius * Mat3::Identity()));
    case ShotShape::Type::Ellipsoid:
      return makeEllipsoid(center, Mat3(shape.rotation * shape.radii.asDiagonal()));
    case ShotShape::Type::Rectangle:
      break;
  }
  return makeRectangle(center, shape.edgeU, shape.edgeV);
}

}  // namespace lacrima::shotfile
