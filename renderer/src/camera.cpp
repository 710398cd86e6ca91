// Thin-lens / pinhole camera (pbrt-v4 PerspectiveCamera, section 5.2.3 "The Thin Lens Model").
#include "lacrima/renderer/camera.hpp"

#include "lacrima/materials/sampling.hpp"

namespace lacrima {

static float tanHalfFov(const Camera& camera) { return std::tan(0.5f * camera.verticalFovRadians); }

namespace {

// Shoemake 1985: slerp between the two rotations, translation linear.
Affine3 interpolatePlacement(const Affine3& open, const Affine3& close, const Eigen::Quaternionf& rotationAtOpen,
                             const Eigen::Quaternionf& rotationAtClose, float time) {
  Affine3 m = Affine3::Identity();
  m.linear() = rotationAtOpen.slerp(time, rotationAtClose).toRotationMatrix();
  m.translation() = (1.0f - time) * open.translation() + time * close.translation();
  return m;
}

}  // namespace

Affine3 cameraToWorldAt(const Camera& camera, float time) {
  if (!camera.cameraToWorldAtClose) return camera.cameraToWorld;
  const Affine3& open = camera.cameraToWorld;
  const Affine3& close = *camera.cameraToWorldAtClose;
  return interpolatePlacement(open, close, Eigen::Quaternionf(open.rotation()), Eigen::Quaternionf(close.rotation()),
                              time);
}

CameraRays::CameraRays(const Camera& camera, int width, int height)
    : camera_(camera),
      width_(float(width)),
      height_(float(height)),
      tanHalfFov_(tanHalfFov(camera)),
      aspect_(float(width) / float(height)) {
  if (camera.cameraToWorldAtClose) {
    rotationAtOpen_ = Eigen::Quaternionf(camera.cameraToWorld.rotation());
    rotationAtClose_ = Eigen::Quaternionf(camera.cameraToWorldAtClose->rotation());
  }
}

Affine3 CameraRays::cameraToWorldAt(float time) const {
  if (!camera_.cameraToWorldAtClose) return camera_.cameraToWorld;
  return interpolatePlacement(camera_.cameraToWorld, *camera_.cameraToWorldAtClose, rotationAtOpen_,
                              rotationAtClose_, time);
}

Ray CameraRays::generate(float filmX, float filmY, const Vec2& lensU, float time) const {
  const float t = tanHalfFov_;
  // Point on the z = -1 image plane in camera space (y up, so the film's y is flipped).
  const Vec3 onPlane((2.0f * filmX / width_ - 1.0f) * t * aspect_, (1.0f - 2.0f * filmY / height_) * t, -1.0f);
  Vec3 origin = Vec3::Zero();
  Vec3 direction = onPlane.normalized();
  if (camera_.lensRadius > 0.0f) {
    // Thin lens: every ray through the lens aims at the point the pinhole ray meets on the focus plane.
    const Vec3 focusPoint = onPlane * camera_.focusDistance;
    const Vec2 lens = camera_.lensRadius * sampleUniformDiskConcentric(lensU);
    origin = Vec3(lens.x(), lens.y(), 0.0f);
    direction = (focusPoint - origin).normalized();
  }
  const Affine3 m = cameraToWorldAt(time);
  return Ray{m * origin, (m.linear() * direction).normalized(), time};
}

Ray generateCameraRay(const Camera& camera, int width, int height, float filmX, float filmY, const Vec2& lensU,
                      float time) {
  return CameraRays(camera, width, height).generate(filmX, filmY, lensU, time);
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
