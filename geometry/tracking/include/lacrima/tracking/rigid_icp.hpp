#pragma once
// Rigid tracking of the head (Weise, Bouaziz, Li & Pauly 2011, section 3, "Rigid Tracking"): the
// face model of the previous frame aligned to the current depth map by ICP with point-plane
// constraints, over the face's stable upper part only (the mouth and jaw deform most).
// * Correspondences by projection (Blais & Levine 1995): a model point is projected into the depth
//   map and paired with the measured surface along its ray (the depth interpolated there); pairs further apart than `maxDistance`
//   or whose normals differ by more than `maxNormalAngleDegrees` are dropped, and so are pairs
//   further apart than three times the median pair (occluded model points).
// * Each iteration minimises sum_i (n_i . (R p_i + t - q_i))^2, n_i the model's normal at p_i
//   (Weise et al.'s eq. 10 measures point-plane distances along the model's normals: a depth sensor's
//   normals are noisy), linearised in the rotation (Low 2004: the 6 x 6 normal equations in (omega, t)), and applies
//   the step as an exact rotation.
#include <vector>

#include "lacrima/tracking/depth_frame.hpp"

namespace lacrima::tracking {

struct RigidIcpParams {
  int maxIterations = 20;
  double maxDistance = 0.02;           // metres between paired points
  double minRejectDistance = 0.002;    // metres: pairs beyond max(this, 3 x the median) are dropped
  double maxNormalAngleDegrees = 60.0;
  double convergedRotation = 1e-5;     // radians: stop when a step turns less than this...
  double convergedTranslation = 1e-6;  // ... and moves less than this (metres)
};

struct RigidIcpResult {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // model space to camera space
  int iterations = 0;
  int pairs = 0;             // correspondences in the last iteration
  double rmsDistance = 0.0;  // point-plane distance over the last iteration's pairs, metres
};

// Aligns model points (with their normals, model space) to `frame`, starting from `initial`.
RigidIcpResult alignRigid(const std::vector<Vec3d>& points, const std::vector<Vec3d>& normals, const DepthFrame& frame,
                          const Eigen::Isometry3d& initial, const RigidIcpParams& params = {});

}  // namespace lacrima::tracking
