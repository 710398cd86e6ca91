// The tracker frame by frame; see performance_tracker.hpp.
#include "lacrima/tracking/performance_tracker.hpp"

#include <chrono>
#include <stdexcept>

namespace lacrima::tracking {

PerformanceTracker::PerformanceTracker(const BlendshapeModel& model, const AnimationPrior* prior,
                                       const TrackerParams& params, const Eigen::Isometry3d& initialPose)
    : model_(model), prior_(prior), params_(params), filter_(params.filter), pose_(initialPose) {
  history_.push_back(Eigen::VectorXd::Zero(model.targetCount()));
  for (size_t v = 0; v < model.neutral.positions.size(); ++v)
    if (model.neutral.positions[v].y() > params.upperFaceAbove) upperVertices_.push_back(v);
}

TrackedFrame PerformanceTracker::track(const DepthFrame& frame, const std::vector<Eigen::Vector2d>& landmarks) {
  TrackedFrame out;
  const auto seconds = [](auto since) { return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count(); };
  const auto rigidStart = std::chrono::steady_clock::now();
  // Rigid: the previous frame's reconstruction, its upper face, against the new depth.
  const TriangleMesh previous = model_.shape(history_.front());
  std::vector<Vec3d> points, normals;
  for (size_t v : upperVertices_) {
    points.push_back(previous.positions[v].cast<double>());
    normals.push_back(previous.normals[v].cast<double>());
  }
  out.rigid = alignRigid(points, normals, frame, pose_, params_.rigid);
  pose_ = out.rigid.pose;
  out.rawPose = pose_;
  out.pose = params_.filterPose ? filter_.add(pose_) : pose_;
  out.rigidSeconds = seconds(rigidStart);
  const auto fitStart = std::chrono::steady_clock::now();
  // Non-rigid, at the filtered pose, from the previous weights.
  // The first frame has no past: its window is the frame itself held (a still face), and it is
  // fitted from the neutral face, so with more iterations.
  const bool first = tracked_ == 0;
  PriorTerm prior;
  if (prior_) {
    prior.prior = prior_;
    if (!first)
      prior.previous.assign(history_.begin(), history_.begin() + long(std::min<size_t>(history_.size(), size_t(prior_->previousFrames()))));
  }
  BlendshapeFitParams fit = params_.fit;
  if (first) fit.iterations *= 3;
  out.fit = fitBlendshapes(model_, frame, landmarks, out.pose, history_.front(), fit, prior);
  out.fitSeconds = seconds(fitStart);
  ++tracked_;
  out.weights = out.fit.weights;
  if (first) history_.clear();  // the neutral start was no frame
  history_.insert(history_.begin(), out.weights);
  if (history_.size() > 8) history_.pop_back();
  return out;
}

double noseTipHeight(const BlendshapeModel& model) {
  const int vertex = model.landmarkVertices.at(30);
  if (vertex < 0) throw std::invalid_argument("noseTipHeight: the model has no landmark 30 (the nose tip)");
  return double(model.neutral.positions[size_t(vertex)].y());
}

}  // namespace lacrima::tracking
