#pragma once
// Where the head is in the first frame: the face's inner landmarks (17-67 of the 68) found in the image and lifted to
// 3D by the depth under them, matched to the model's landmark vertices by the rotation and
// translation of least squares (Kabsch 1976, via the SVD of the cross-covariance). ICP then
// refines it (rigid_icp.hpp).
#include <optional>
#include <vector>

#include "lacrima/tracking/blendshape_fit.hpp"

namespace lacrima::tracking {

// The model (neutral, or at `weights`) to camera pose from the landmarks seen with depth; nothing
// when fewer than six landmarks have a depth.
std::optional<Eigen::Isometry3d> poseFromLandmarks(const BlendshapeModel& model, const DepthFrame& frame,
                                                   const std::vector<Eigen::Vector2d>& landmarks,
                                                   const Eigen::VectorXd& weights = {});

}  // namespace lacrima::tracking
