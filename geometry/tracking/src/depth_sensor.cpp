// The synthetic depth sensor; see depth_sensor.hpp.
#include "lacrima/tracking/depth_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lacrima/base/hash.hpp"

namespace lacrima::tracking {

namespace {

// Twice the signed area of (a, b, c) in the image plane.
double edge(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// One triangle into the z-buffer: depth interpolated perspective-correctly (1/z is linear in the
// image plane).
void rasterizeTriangle(const Vec3d (&p)[3], const PinholeCamera& camera, DepthFrame& frame) {
  const Eigen::Vector2d s[3] = {camera.project(p[0]), camera.project(p[1]), camera.project(p[2])};
  const double area = edge(s[0], s[1], s[2]);
  if (std::abs(area) < 1e-12) return;
  const int x0 = std::max(0, int(std::floor(std::min({s[0].x(), s[1].x(), s[2].x()}))));
  const int x1 = std::min(camera.width - 1, int(std::ceil(std::max({s[0].x(), s[1].x(), s[2].x()}))));
  const int y0 = std::max(0, int(std::floor(std::min({s[0].y(), s[1].y(), s[2].y()}))));
  const int y1 = std::min(camera.height - 1, int(std::ceil(std::max({s[0].y(), s[1].y(), s[2].y()}))));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2d c(x + 0.5, y + 0.5);
      const double w0 = edge(s[1], s[2], c) / area, w1 = edge(s[2], s[0], c) / area, w2 = edge(s[0], s[1], c) / area;
      if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
      const double z = 1.0 / (w0 / p[0].z() + w1 / p[1].z() + w2 / p[2].z());
      const float current = frame.depth(x, y);
      if (current == 0.0f || z < current) frame.setDepth(x, y, float(z));
    }
}

}  // namespace

DepthFrame rasterizeDepth(const TriangleMesh& mesh, const PinholeCamera& camera, double nearPlane) {
  DepthFrame frame(camera);
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    Vec3d p[3];
    bool inFront = true;
    for (int k = 0; k < 3; ++k) {
      p[k] = mesh.positions[mesh.indices[3 * t + k]].cast<double>();
      inFront = inFront && p[k].z() > nearPlane;
    }
    if (inFront) rasterizeTriangle(p, camera, frame);
  }
  return frame;
}

double kinectAxialNoise(double depth, double scale) {
  return scale * (0.0012 + 0.0019 * (depth - 0.4) * (depth - 0.4));
}

void addSensorNoise(DepthFrame& frame, double scale, uint64_t seed) {
  if (scale <= 0.0) return;
  const PinholeCamera& camera = frame.camera();
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const float z = frame.depth(x, y);
      if (!(z > 0.0f)) continue;
      // A standard normal number by Box-Muller from two hashed uniforms of (seed, pixel).
      const uint64_t key = hashCombine(seed, uint64_t(y) * uint64_t(camera.width) + uint64_t(x));
      const double u1 = (double(uint64ToUnitFloat(hashCombine(key, 1))) + 0x1p-25), u2 = double(uint64ToUnitFloat(hashCombine(key, 2)));
      const double normal = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
      frame.setDepth(x, y, float(z + normal * kinectAxialNoise(z, scale)));
    }
}

}  // namespace lacrima::tracking
