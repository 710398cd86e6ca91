// Point-plane ICP against a depth map; see rigid_icp.hpp.
#include "lacrima/tracking/rigid_icp.hpp"

#include "robust_cut.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lacrima::tracking {

namespace {

struct Pair {
  Vec3d p;  // the model point in camera space (current pose)
  Vec3d q;  // the measured point
  Vec3d n;  // the model's normal there (camera space)
};

std::vector<Pair> projectivePairs(const std::vector<Vec3d>& points, const std::vector<Vec3d>& normals,
                                  const DepthFrame& frame, const Eigen::Isometry3d& pose, const RigidIcpParams& params) {
  const double minCos = std::cos(params.maxNormalAngleDegrees * std::numbers::pi / 180.0);
  std::vector<Pair> pairs;
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3d p = pose * points[i];
    const Vec3d modelNormal = pose.linear() * normals[i];
    if (p.z() <= 0.0 || modelNormal.dot(p) >= 0.0) continue;  // behind the camera or facing away
    const Eigen::Vector2d pixel = frame.camera().project(p);
    const int x = int(std::floor(pixel.x())), y = int(std::floor(pixel.y()));
    const auto q = frame.pointAt(pixel.x(), pixel.y());
    if (!q || (*q - p).norm() > params.maxDistance) continue;
    const auto n = frame.normal(x, y, 0.01, 2);
    if (!n || n->dot(modelNormal) < minCos) continue;
    pairs.push_back({p, *q, modelNormal});
  }
  // Occluded model points (a cheek behind the nose, a lid's rim) pair with the surface in front of
  // them, centimetres away, and bias the pose: keep the pairs within three times the median
  // distance (at least `minRejectDistance`), the usual robust cut once the alignment is close.
  if (pairs.empty()) return pairs;
  std::vector<double> distances;
  for (const Pair& pair : pairs) distances.push_back((pair.q - pair.p).norm());
  const double cut = robustCut(std::move(distances), params.minRejectDistance);
  std::erase_if(pairs, [&](const Pair& pair) { return (pair.q - pair.p).norm() > cut; });
  return pairs;
}

}  // namespace

RigidIcpResult alignRigid(const std::vector<Vec3d>& points, const std::vector<Vec3d>& normals, const DepthFrame& frame,
                          const Eigen::Isometry3d& initial, const RigidIcpParams& params) {
  RigidIcpResult result;
  result.pose = initial;
  for (int iteration = 0; iteration < params.maxIterations; ++iteration) {
    const std::vector<Pair> pairs = projectivePairs(points, normals, frame, result.pose, params);
    result.iterations = iteration + 1;
    result.pairs = int(pairs.size());
    if (pairs.size() < 6) break;
    // Residual r = n . (p - q) + (p x n) . omega + n . t (Low 2004, eq. 9).
    Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
    double squared = 0.0;
    for (const Pair& pair : pairs) {
      Eigen::Matrix<double, 6, 1> row;
      row << pair.p.cross(pair.n), pair.n;
      const double r = pair.n.dot(pair.p - pair.q);
      normal += row * row.transpose();
      rhs -= row * r;
      squared += r * r;
    }
    result.rmsDistance = std::sqrt(squared / double(pairs.size()));
    const Eigen::Matrix<double, 6, 1> step = normal.ldlt().solve(rhs);
    const Vec3d omega = step.head<3>(), t = step.tail<3>();
    Eigen::Isometry3d update = Eigen::Isometry3d::Identity();
    if (omega.norm() > 0.0) update.linear() = Eigen::AngleAxisd(omega.norm(), omega.normalized()).toRotationMatrix();
    update.translation() = t;
    result.pose = update * result.pose;
    if (omega.norm() < params.convergedRotation && t.norm() < params.convergedTranslation) break;
  }
  return result;
}

}  // namespace lacrima::tracking
