// Thin-lens / pinhole camera (pbrt-v4 PerspectiveCamera, section 5.2.3 "The Thin Lens Model").
#include "lacrima/renderer/camera.hpp"

#include "lacrima/materials/sampling.hpp"

namespace lacrima {

static float tanHalfFov(const Camera& camera) { return std::tan(0.5f * camera.verticalFovRadians); }

Affine3 cameraToWorldAt(const Camera& camera, float time) {
  if (!camera.cameraToWorldAtClose) return camera.cameraToWorld;
  const Affine3& open = camera.cameraToWorld;
  const Affine3& close = *camera.cameraToWorldAtClose;
  const Eigen::Quaternionf rotation =
      Eigen::Quaternionf(open.rotation()).slerp(time, Eigen::Quaternionf(close.rotation()));
  Affine3 m = Affine3::Identity();
  m.linear() = rotation.toRotationMatrix();
  m.translation() = (1.0f - time) * open.translation() + time * close.translation();
  return m;
}

Ray generateCameraRay(const Camera& camera, int width, int height, float filmX, float filmY, const Vec2& lensU,
                      float time) {
  const float aspect = float(width) / float(height);
  const float t = tanHalfFov(camera);
  // Point on the z = -1 image plane in camera space (y up, so the film's y is flipped).
  const Vec3 onPlane((2.0f * filmX / float(width) - 1.0f) * t * aspect, (1.0f - 2.0f * filmY / float(height)) * t, -1.0f);
  Vec3 origin = Vec3::Zero();
  Vec3 direction = onPlane.normalized();
  if (camera.lensRadius > 0.0f) {
    // Thin lens: every ray through the lens aims at the point the pinhole ray meets on the focus plane.
    const Vec3 focusPoint = onPlane * camera.focusDistance;
    const Vec2 lens = camera.lensRadius * sampleUniformDiskConcentric(lensU);
    origin = Vec3(lens.x(), lens.y(), 0.0f);
    direction = (focusPoint - origin).normalized();
  }
  const Affine3 m = cameraToWorldAt(camera, time);
  return Ray{m * origin, (m.linear() * direction).normalized(), time};
}

Mat4 worldToCameraMatrix(const Camera& camera) { return camera.cameraToWorld.inverse(Eigen::Affine).matrix(); }

Mat4 worldToNdcMatrix(const Camera& camera, int width, int height) {
  const float nearZ = 0.01f, farZ = 1000.0f;
  const float t = tanHalfFov(camera);
  const float aspect = float(width) / float(height);
  // Camera space looks down -Z; depth d = -z. x_ndc = 0.5 + 0.5 * x / (d t aspect), y_ndc = 0.5 - 0.5 * y / (d t).
  Mat4 projection = Mat4::Zero();
  projection(0, 0) = 0.5f / (t * aspect);
  projection(0, 2) = -0.5f;
  projection(1, 1) = -0.5f / t;
  projection(1, 2) = -0.5f;
  projection(2, 2) = -farZ / (farZ - nearZ);
  projection(2, 3) = -farZ * nearZ / (farZ - nearZ);
  projection(3, 2) = -1.0f;
  return projection * worldToCameraMatrix(camera);
}

}  // namespace lacrima
