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

// A 2D landmark detector's typical errors, beyond the per-frame jitter, for a synthetic capture
// that tests the tracker on what a capture rig's or a phone's face tracker gives:
// * the jaw line's 17 points (iBUG 0-16) slide along the contour: a contour has no corner to fix a
//   point along it, which is where detectors err most (Sagonas et al. 2016 score the 300-W
//   challenge with and without them for that reason); each wanders along the contour as a sine of
//   `contourDrift` pixels with its own period of 2-5 s and phase;
// * with `dropHidden`, landmarks the camera does not see (their skin turned away, or behind the
//   surface the depth map saw by more than 1 cm: the far eye's outer corner behind the nose of a
//   turned head) are missing (NaN), as a detector reports low confidence there; but the jaw line,
//   which detectors place on the face's outline whatever turns away.
struct LandmarkDetectorErrors {
  double jitter = 1.0;        // pixels: uniform in [-jitter, jitter] per axis, new each frame
  double contourDrift = 0.0;  // pixels
  bool dropHidden = false;
};

// The model's landmarks as such a detector reports them at time `seconds` of a take; `seed` is
// the take's (the jitter is drawn per frame from it and `frame`, the drift is the take's);
// `seen` (optional) is the frame's depth map, for the behind-the-surface test.
std::vector<Eigen::Vector2d> detectLandmarks(const BlendshapeModel& model, const Eigen::VectorXd& weights,
                                             const Eigen::Isometry3d& pose, const PinholeCamera& camera,
                                             const LandmarkDetectorErrors& errors, uint64_t seed, int frame,
                                             double seconds, const DepthFrame* seen = nullptr);

}  // namespace lacrima::tracking
