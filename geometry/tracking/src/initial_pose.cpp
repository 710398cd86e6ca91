// The first frame's head pose from landmarks; see initial_pose.hpp.
#include "lacrima/tracking/initial_pose.hpp"

#include <Eigen/SVD>

#include <cmath>

namespace lacrima::tracking {

std::optional<Eigen::Isometry3d> poseFromLandmarks(const BlendshapeModel& model, const DepthFrame& frame,
                                                   const std::vector<Eigen::Vector2d>& landmarks,
                                                   const Eigen::VectorXd& weights) {
  const std::vector<Vec3d> vertices = model.positions(weights.size() == model.targetCount() ? weights
                                                                                        : Eigen::VectorXd::Zero(model.targetCount()));
  std::vector<Vec3d> from, to;
  // Landmarks 0-16 trace the jaw's outline: on a turned head they sit on the silhouette, where the
  // depth under them is the background's or the neck's. The inner 51 (brows, nose, eyes, mouth) do not.
  for (size_t l = 17; l < landmarks.size() && l < model.landmarkVertices.size(); ++l) {
    const int v = model.landmarkVertices[l];
    if (v < 0 || !landmarks[l].allFinite()) continue;
    const auto q = frame.point(int(std::floor(landmarks[l].x())), int(std::floor(landmarks[l].y())));
    if (!q) continue;
    from.push_back(vertices[size_t(v)]);
    to.push_back(*q);
  }
  if (from.size() < 6) return std::nullopt;
  Vec3d fromMean = Vec3d::Zero(), toMean = Vec3d::Zero();
  for (size_t i = 0; i < from.size(); ++i) fromMean += from[i] / double(from.size()), toMean += to[i] / double(from.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < from.size(); ++i) covariance += (to[i] - toMean) * (from[i] - fromMean).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;  // a rotation, not a reflection
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = svd.matrixU() * d * svd.matrixV().transpose();
  pose.translation() = toMean - pose.linear() * fromMean;
  return pose;
}

}  // namespace lacrima::tracking
