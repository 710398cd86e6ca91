#pragma once
// A face model captured by the synthetic depth sensor: its depth map (depth_sensor.hpp) and its 68
// landmarks projected, as a capture rig would give them, with stated noise. What `lacrima track
// --synthesize` writes and the tracking tests track.
#include <cstdint>
#include <vector>

#include "lacrima/tracking/blendshape_fit.hpp"

namespace lacrima::tracking {

// The model at `weights`, posed by `pose` (model to camera space), rasterised and given
// `noise` x a Kinect's axial noise drawn from `seed`.
DepthFrame captureDepth(const BlendshapeModel& model, const Eigen::VectorXd& weights, const Eigen::Isometry3d& pose,
                        const PinholeCamera& camera, double noise, uint64_t seed);

// The model's 68 landmarks at `weights` projected by the camera, each moved by a uniform number in
// [-noise, noise] pixels per axis drawn from `seed`; NaN where the landmark is not on the model.
std::vector<Eigen::Vector2d> projectLandmarks(const BlendshapeModel& model, const Eigen::VectorXd& weights,
                                              const Eigen::Isometry3d& pose, const PinholeCamera& camera, double noise,
                                              uint64_t seed);

}  // namespace lacrima::tracking
