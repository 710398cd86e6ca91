// The adaptive temporal filter; see pose_filter.hpp.
#include "lacrima/tracking/pose_filter.hpp"

#include <algorithm>
#include <cmath>

namespace lacrima::tracking {

Eigen::VectorXd AdaptiveWindowFilter::add(const Eigen::VectorXd& raw) {
  history_.push_front(raw);
  if (int(history_.size()) > window_ + 1) history_.pop_back();
  double variation = 0.0;
  for (size_t l = 1; l < history_.size(); ++l) variation = std::max(variation, (history_[0] - history_[l]).norm());
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(raw.size());
  double weights = 0.0;
  for (size_t j = 0; j < history_.size(); ++j) {
    const double w = std::exp(-double(j) * h_ * variation);
    sum += w * history_[j];
    weights += w;
  }
  return sum / weights;
}

PoseFilter::PoseFilter(const PoseFilterParams& params)
    : translation_(params.window, params.translationH), rotation_(params.window, params.rotationH) {}

Eigen::Isometry3d PoseFilter::add(const Eigen::Isometry3d& raw) {
  Eigen::Quaterniond q(raw.linear());
  if (q.coeffs().dot(last_.coeffs()) < 0.0) q.coeffs() = -q.coeffs();  // the same hemisphere as the last
  last_ = q;
  const Eigen::VectorXd t = translation_.add(raw.translation());
  const Eigen::VectorXd r = rotation_.add(q.coeffs());
  Eigen::Isometry3d filtered = Eigen::Isometry3d::Identity();
  filtered.linear() = Eigen::Quaterniond(r[3], r[0], r[1], r[2]).normalized().toRotationMatrix();
  filtered.translation() = t;
  return filtered;
}

}  // namespace lacrima::tracking
