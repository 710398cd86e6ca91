#pragma once
// What the tracking tests share: the ICT face's skin as a blendshape model, a camera pose for it,
// and a synthetic capture of it (depth with a Kinect's noise, 68 landmarks with pixel noise).
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "lacrima/tracking/blendshape_fit.hpp"
#include "lacrima/tracking/synthetic_capture.hpp"

namespace lacrima::test {

inline const tracking::BlendshapeModel& ictModel() {
  static const tracking::BlendshapeModel model =
      tracking::blendshapeModelOf(loadGltfAsset(std::string(LACRIMA_SOURCE_DIR) + "/scenes/assets/ict-face/ict_face.glb"), "M_Face");
  return model;
}

// Model (glTF: +y up, the face looking along +z) to camera space: the face `distance` metres in
// front of the camera, turned by (pitch, yaw, roll) degrees about its own origin and moved by `shift`.
inline Eigen::Isometry3d headPose(double distance, const Vec3d& degrees = Vec3d::Zero(), const Vec3d& shift = Vec3d::Zero()) {
  constexpr double kDegree = std::numbers::pi / 180.0;
  Eigen::Isometry3d facing = Eigen::Isometry3d::Identity();
  facing.linear() = Vec3d(1, -1, -1).asDiagonal();  // y down, z away: the face looks at the camera
  facing.translation() = Vec3d(0, 0, distance);
  Eigen::Isometry3d turn = Eigen::Isometry3d::Identity();
  turn.linear() = (Eigen::AngleAxisd(degrees.z() * kDegree, Vec3d::UnitZ()) * Eigen::AngleAxisd(degrees.y() * kDegree, Vec3d::UnitY()) *
                   Eigen::AngleAxisd(degrees.x() * kDegree, Vec3d::UnitX()))
                      .toRotationMatrix();
  turn.translation() = shift;
  return facing * turn;
}

struct Capture {
  tracking::DepthFrame depth;
  std::vector<Eigen::Vector2d> landmarks;  // NaN where the landmark is not on the skin
};

// The face at `weights` and `pose` seen by the default camera: depth with `noise` x a Kinect's
// noise, landmarks with uniform noise of +-`landmarkNoise` pixels; `seed` draws both.
inline Capture capture(const tracking::BlendshapeModel& model, const Eigen::VectorXd& weights, const Eigen::Isometry3d& pose,
                       double noise, double landmarkNoise, uint64_t seed) {
  return Capture{tracking::captureDepth(model, weights, pose, tracking::PinholeCamera{}, noise, seed),
                 tracking::projectLandmarks(model, weights, pose, tracking::PinholeCamera{}, landmarkNoise, seed)};
}

// The root mean square distance between the model's vertices at two weight vectors, millimetres.
inline double vertexRmsMm(const tracking::BlendshapeModel& model, const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const std::vector<Vec3d> p = model.positions(a), q = model.positions(b);
  double squared = 0.0;
  for (size_t v = 0; v < p.size(); ++v) squared += (p[v] - q[v]).squaredNorm();
  return 1e3 * std::sqrt(squared / double(p.size()));
}

inline double degreesBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear() * b.linear().transpose()).angle() * 180.0 / std::numbers::pi;
}

}  // namespace lacrima::test
