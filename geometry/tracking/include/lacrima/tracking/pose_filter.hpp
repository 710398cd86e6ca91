#pragma once
// The temporal filter of the rigid pose of Weise, Bouaziz, Li & Pauly 2011 (section 3, "Rigid
// Tracking"; in the spirit of Roberts 1959's exponentially weighted moving average): translation
// and rotation (as a quaternion) are filtered apart, each as a vector t over a window of the k
// latest frames,
//   t^_i = sum_{j=0..k} w_j t_{i-j} / sum_j w_j,   w_j = exp(-j H max_{l=1..k} |t_i - t_{i-l}|),
// so a still head (small variation in the window) is averaged over the whole window and a fast
// motion (large variation) is followed with little lag. H is a constant per quantity set from the
// noise of a still pose; Weise et al. use k = 5.
#include <deque>

#include "lacrima/base/math.hpp"

namespace lacrima::tracking {

// One filtered vector quantity.
class AdaptiveWindowFilter {
 public:
  AdaptiveWindowFilter(int window, double h) : window_(window), h_(h) {}
  // The filtered value after adding this frame's raw value.
  Eigen::VectorXd add(const Eigen::VectorXd& raw);

 private:
  int window_;
  double h_;
  std::deque<Eigen::VectorXd> history_;  // newest first: t_i, t_{i-1}, ..., t_{i-k}
};

struct PoseFilterParams {
  int window = 5;              // k, frames (Weise et al.'s)
  // H per metre: a still head whose tracking jitters by ~0.2 mm varies by ~1 mm over the window,
  // e^{-0.2} a step back (averaged over the whole window); a head moving 5 mm a frame varies by
  // 25 mm, e^{-5} a step back (followed with a lag of ~0.03 mm).
  double translationH = 200;
  // H per unit of quaternion difference (|dq| is about half the angle in radians): 0.1 degrees of
  // jitter vary by ~0.003, e^{-0.2} a step back; a turn of 2 degrees a frame by ~0.09, e^{-5}.
  double rotationH = 60;
};

class PoseFilter {
 public:
  explicit PoseFilter(const PoseFilterParams& params = {});
  // The filtered pose after adding this frame's raw pose.
  Eigen::Isometry3d add(const Eigen::Isometry3d& raw);

 private:
  AdaptiveWindowFilter translation_, rotation_;
  Eigen::Quaterniond last_ = Eigen::Quaterniond::Identity();  // sign reference: q and -q are one rotation
};

}  // namespace lacrima::tracking
