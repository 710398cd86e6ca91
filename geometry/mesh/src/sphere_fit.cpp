// Linear least-squares sphere fit.
#include "lacrima/mesh/sphere_fit.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>

#include "lacrima/base/error.hpp"

namespace lacrima {

FittedSphere fitSphere(const std::vector<Vec3>& points) {
  if (points.size() < 4) throw InputError(fmt::format("sphere fit needs at least 4 points, got {}", points.size()));
  // Working about the centroid keeps |p|^2 small, so the normal equations stay well conditioned
  // for an eyeball 12 mm across that sits 0.1 m from the asset origin.
  Vec3d centroid = Vec3d::Zero();
  for (const Vec3& p : points) centroid += p.cast<double>();
  centroid /= double(points.size());

  // Pratt 1987 (sphere case): |q|^2 = 2 c.q + k with q = p - centroid, k = r^2 - |c|^2.
  Eigen::MatrixXd a(points.size(), 4);
  Eigen::VectorXd b(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3d q = points[i].cast<double>() - centroid;
    a.row(Eigen::Index(i)) << 2.0 * q.x(), 2.0 * q.y(), 2.0 * q.z(), 1.0;
    b(Eigen::Index(i)) = q.squaredNorm();
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 4) throw InputError("sphere fit: the points are coplanar or collinear, no unique sphere");
  const Eigen::Vector4d x = qr.solve(b);
  const Vec3d center = x.head<3>();
  const double radiusSquared = x(3) + center.squaredNorm();
  FittedSphere sphere;
  sphere.center = (center + centroid).cast<float>();
  sphere.radius = float(std::sqrt(std::max(0.0, radiusSquared)));
  return sphere;
}

}  // namespace lacrima
