// Depth frames; see depth_frame.hpp.
#include "lacrima/tracking/depth_frame.hpp"

#include <algorithm>
#include <cmath>

namespace lacrima::tracking {

std::optional<Vec3d> DepthFrame::point(int x, int y) const {
  if (!inside(x, y)) return std::nullopt;
  const float z = depth(x, y);
  if (!(z > 0.0f)) return std::nullopt;
  return camera_.backProject(x + 0.5, y + 0.5, z);
}

std::optional<Vec3d> DepthFrame::pointAt(double u, double v, double maxJump) const {
  const int x0 = int(std::floor(u - 0.5)), y0 = int(std::floor(v - 0.5));
  const double fx = u - 0.5 - x0, fy = v - 0.5 - y0;
  if (!inside(x0, y0) || !inside(x0 + 1, y0 + 1)) return std::nullopt;
  const float z00 = depth(x0, y0), z10 = depth(x0 + 1, y0), z01 = depth(x0, y0 + 1), z11 = depth(x0 + 1, y0 + 1);
  if (!(z00 > 0.0f && z10 > 0.0f && z01 > 0.0f && z11 > 0.0f)) return std::nullopt;
  if (std::max({z00, z10, z01, z11}) - std::min({z00, z10, z01, z11}) > maxJump) return std::nullopt;
  const double z = (1 - fy) * ((1 - fx) * z00 + fx * z10) + fy * ((1 - fx) * z01 + fx * z11);
  return camera_.backProject(u, v, z);
}

std::optional<Vec3d> DepthFrame::normal(int x, int y, double maxJump, int step) const {
  const auto centre = point(x, y);
  const auto left = point(x - step, y), right = point(x + step, y), up = point(x, y - step), down = point(x, y + step);
  if (!centre || !left || !right || !up || !down) return std::nullopt;
  for (const Vec3d* p : {&*left, &*right, &*up, &*down})
    if (std::abs(p->z() - centre->z()) > maxJump) return std::nullopt;
  // x grows right and y down: (down - up) x (right - left) points back towards the camera.
  const Vec3d n = (*down - *up).cross(*right - *left);
  if (n.squaredNorm() == 0.0) return std::nullopt;
  return n.normalized();
}

}  // namespace lacrima::tracking
