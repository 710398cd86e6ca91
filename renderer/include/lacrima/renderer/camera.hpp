#pragma once
// Camera rays and the matrices recorded in EXR headers.
#include <limits>

#include "lacrima/base/math.hpp"
#include "lacrima/renderer/frame.hpp"

namespace lacrima {

struct Ray {
  Vec3 origin;
  Vec3 direction;  // unit
  float time = 0.0f;  // in the shutter interval, [0, 1]
  // Hits closer than this to the origin are ignored: a ray that goes on straight through a thin
  // sheet keeps its line and starts just past the sheet instead of at an offset origin.
  float tnear = 0.0f;
  // Hits farther than this are ignored: a query that only cares about a segment (a subsurface
  // probe's chord) lets Embree cull the rest.
  float tfar = std::numeric_limits<float>::infinity();
};

// The camera's placement at shutter time t: translation interpolated linearly, rotation by
// quaternion slerp (Shoemake 1985).
Affine3 cameraToWorldAt(const Camera& camera, float time);

// Primary rays of one camera and image size. What does not change from ray to ray is worked out
// once: the rotations at shutter open and close (Transform::rotation() is a polar decomposition,
// an SVD, which per camera ray was 5 % of a render of the default shot), the image plane's size.
class CameraRays {
 public:
  CameraRays(const Camera& camera, int width, int height);
  // The ray through film position (filmX, filmY) in pixels (0..width, 0..height, y down), with
  // lens sample lensU in [0,1)^2 (ignored for a pinhole), at shutter time `time`.
  Ray generate(float filmX, float filmY, const Vec2& lensU, float time = 0.0f) const;
  // The camera's placement at `time`, as cameraToWorldAt gives it.
  Affine3 cameraToWorldAt(float time) const;

 private:
  const Camera& camera_;
  float width_, height_, tanHalfFov_, aspect_;
  Eigen::Quaternionf rotationAtOpen_, rotationAtClose_;
};

// One ray, as CameraRays(camera, width, height).generate(...) gives it.
Ray generateCameraRay(const Camera& camera, int width, int height, float filmX, float filmY, const Vec2& lensU,
                      float time = 0.0f);

// Inverse of camera.cameraToWorld.
Mat4 worldToCameraMatrix(const Camera& camera);

// Perspective projection to normalised device coordinates as pbrt writes it: x, y in [0,1]
// (x right, y down over the image), z = (d - near) / (far - near)-like depth with near = 1 cm,
// far = 1 km.
Mat4 worldToNdcMatrix(const Camera& camera, int width, int height);

}  // namespace lacrima
