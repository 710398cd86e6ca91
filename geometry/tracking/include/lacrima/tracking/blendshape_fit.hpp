#pragma once
// The non-rigid stage of the tracker of Weise, Bouaziz, Li & Pauly 2011 (section 3.2): given
// the head's rigid pose, the blendshape weights x in [0, 1]^m that best explain the frame,
//   x* = argmin E_geo + E_im + E_prior (Weise et al.'s eq. 13),
// * E_geo = sum_i (n_i . (v_i(x) - v_i*))^2 / sigma_geo^2 (Weise et al.'s eq. 14): v_i(x) the model's
//   vertex i (neutral plus weighted deltas, B x), posed; n_i its normal; v_i* the measured surface
//   along v_i's ray (projective association, as the rigid stage);
// * E_im: Weise et al.'s image term is optical flow against the actor's texture; lacrima's uses 2D
//   facial landmarks instead (the 68-point layout, as a capture rig's or a phone's face tracker
//   gives them): sum_l |pi(v_l(x)) - u_l|^2 / sigma_im^2, pi the camera's projection.
// * E_prior = -ln p(x, X_n), the animation prior over x and the previous frames' weights
//   (animation_prior.hpp), when one is given.
// The data terms are Weise et al.'s sums of squares over sigma^2; minimised by Gauss-Newton with the bounds kept by projection: each step solves the normal
// equations over the weights not held at a bound by their gradient, then clamps to [0, 1].
#include <optional>
#include <string>
#include <vector>

#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/tracking/animation_prior.hpp"
#include "lacrima/tracking/depth_frame.hpp"

namespace lacrima::tracking {

// One primitive of a face asset as the tracker sees it: its neutral mesh, every morph target's
// deltas as the columns of B, and which of its vertices carry the 68 landmarks.
struct BlendshapeModel {
  TriangleMesh neutral;             // model space (the asset's)
  Eigen::MatrixXd deltas;           // 3 V x m: column k is target k's offset of every vertex
  std::vector<std::string> targetNames;
  std::vector<int> landmarkVertices;  // 68 entries: the vertex of landmark l, or -1 if not on this primitive

  std::vector<double> largestOffsets;  // per target, its largest vertex offset (metres)

  int targetCount() const { return int(deltas.cols()); }
  // Whether target k moves some vertex of this primitive by at least `minMotion` metres.
  bool observable(long k, double minMotion) const { return largestOffsets[size_t(k)] >= minMotion; }
  // The model's vertices at weights x (model space).
  std::vector<Vec3d> positions(const Eigen::VectorXd& weights) const;
  // The mesh at weights x, with smooth normals; or at vertex positions already computed.
  TriangleMesh shape(const Eigen::VectorXd& weights) const;
  TriangleMesh meshOf(const std::vector<Vec3d>& vertexPositions) const;
};

// The model of primitive `part` (e.g. "M_Face") of `asset`. Throws InputError if the asset has no
// such primitive.
BlendshapeModel blendshapeModelOf(const GltfAsset& asset, const std::string& part);

struct BlendshapeFitParams {
  int iterations = 6;
  double sigmaGeometry = 0.001;    // metres: the depth term's unit of error
  double sigmaLandmark = 1.0;      // pixels: the landmark term's unit of error (a detector's on a
                                   // sharp frame; raise it for a noisier one: lacrima track --landmark-sigma)
  double maxDistance = 0.01;       // metres between a vertex and its measured point
  double damping = 1e-3;           // added to the normal equations' diagonal (Levenberg's damping)
  double minTargetMotion = 1e-4;   // metres: targets moving no vertex this far are not fitted (the
                                   // ICT face's pupil targets move the eyes, not the skin)
};

struct BlendshapeFitResult {
  Eigen::VectorXd weights;
  int pairs = 0;                      // depth correspondences in the last iteration
  double rmsDistance = 0.0;           // their point-plane distance, metres
  double rmsLandmarkPixels = 0.0;     // landmark reprojection error, pixels (0 without landmarks)
};

// The prior term of a fit: the prior and the previous frames' weights (newest first).
struct PriorTerm {
  const AnimationPrior* prior = nullptr;
  WeightSequence previous;
};

// Fits the weights to a depth frame and (optionally) 68 landmarks in pixels (a landmark with a
// NaN coordinate is not seen), the model posed by `pose` (model to camera space), starting from
// `initial` (the previous frame's weights), with the animation prior when `prior.prior` is set.
BlendshapeFitResult fitBlendshapes(const BlendshapeModel& model, const DepthFrame& frame,
                                   const std::vector<Eigen::Vector2d>& landmarks, const Eigen::Isometry3d& pose,
                                   const Eigen::VectorXd& initial, const BlendshapeFitParams& params = {},
                                   const PriorTerm& prior = {});

}  // namespace lacrima::tracking
