#pragma once
// Camera rays and the matrices recorded in EXR headers.
#include "lacrima/geometry/math.hpp"
#include "lacrima/renderer/frame.hpp"

namespace lacrima {

struct Ray {
  Vec3 origin;
  Vec3 direction;  // unit
};

// A primary ray through film position (filmX, filmY) in pixels (0..width, 0..height, y down),
// with lens sample lensU in [0,1)^2 (ignored for a pinhole).
Ray generateCameraRay(const Camera& camera, int width, int height, float filmX, float filmY, const Vec2& lensU);

// Inverse of camera.cameraToWorld.
Mat4 worldToCameraMatrix(const Camera& camera);

// Perspective projection to normalised device coordinates as pbrt writes it: x, y in [0,1]
// (x right, y down over the image), z = (d - near) / (far - near)-like depth with near = 1 cm,
// far = 1 km.
Mat4 worldToNdcMatrix(const Camera& camera, int width, int height);

}  // namespace lacrima
