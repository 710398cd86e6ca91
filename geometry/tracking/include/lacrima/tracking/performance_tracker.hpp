#pragma once
// The tracker of Weise, Bouaziz, Li & Pauly 2011 frame by frame (section 3): the face as
// reconstructed in the previous frame is aligned rigidly to the new depth map over its upper part
// (rigid_icp.hpp), the pose filtered (pose_filter.hpp), then the blendshape weights fitted at that
// pose (blendshape_fit.hpp) with the animation prior over the previous frames' weights when one is
// given (animation_prior.hpp).
#include <optional>
#include <vector>

#include "lacrima/tracking/blendshape_fit.hpp"
#include "lacrima/tracking/pose_filter.hpp"
#include "lacrima/tracking/rigid_icp.hpp"

namespace lacrima::tracking {

struct TrackerParams {
  RigidIcpParams rigid;
  PoseFilterParams filter;
  bool filterPose = true;
  BlendshapeFitParams fit;
  // The rigidly tracked region: the model's vertices above this height (model space, metres);
  // for the ICT face, the nose tip's (landmark 30).
  double upperFaceAbove = 0.0;
};

struct TrackedFrame {
  Eigen::Isometry3d rawPose = Eigen::Isometry3d::Identity();  // ICP's
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();     // filtered (or ICP's without the filter)
  Eigen::VectorXd weights;
  RigidIcpResult rigid;
  BlendshapeFitResult fit;
  // Wall-clock seconds of the two stages (the rigid one with the pose filter), for benchmarks.
  double rigidSeconds = 0.0, fitSeconds = 0.0;
};

class PerformanceTracker {
 public:
  // `prior` may be null (no animation prior); it must outlive the tracker.
  PerformanceTracker(const BlendshapeModel& model, const AnimationPrior* prior, const TrackerParams& params,
                     const Eigen::Isometry3d& initialPose);

  // Tracks the next frame: its depth map and 68 landmarks in pixels (empty, or NaN where unseen).
  TrackedFrame track(const DepthFrame& frame, const std::vector<Eigen::Vector2d>& landmarks);

 private:
  const BlendshapeModel& model_;
  const AnimationPrior* prior_;
  TrackerParams params_;
  PoseFilter filter_;
  Eigen::Isometry3d pose_;           // the last frame's (unfiltered: ICP continues from it)
  WeightSequence history_;           // fitted weights, newest first (the neutral face before the first)
  size_t tracked_ = 0;               // frames tracked so far
  std::vector<size_t> upperVertices_;
};

// The ICT face's upper-face height: its landmark 30's (the nose tip's) y in model space.
double noseTipHeight(const BlendshapeModel& model);

}  // namespace lacrima::tracking
