#pragma once
// A depth map from a pinhole camera, as a depth sensor (or lacrima's Z AOV) gives it. Camera space
// is the computer-vision convention: x right, y down, z along the optical axis; a pixel (u, v)
// has its centre at (u + 0.5, v + 0.5). Depth is z in metres; 0 means no measurement.
#include <optional>
#include <vector>

#include "lacrima/base/math.hpp"

namespace lacrima::tracking {

struct PinholeCamera {
  int width = 640, height = 480;
  double fx = 525.0, fy = 525.0;  // focal lengths in pixels (a 640x480 depth camera about 63 degrees wide)
  double cx = 320.0, cy = 240.0;  // principal point in pixels

  // The image point of camera-space point p (z > 0).
  Eigen::Vector2d project(const Vec3d& p) const { return {fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy}; }
  // The camera-space point at image point (u, v) and depth z.
  Vec3d backProject(double u, double v, double z) const { return {(u - cx) * z / fx, (v - cy) * z / fy, z}; }
};

class DepthFrame {
 public:
  explicit DepthFrame(const PinholeCamera& camera)
      : camera_(camera), depth_(size_t(camera.width) * size_t(camera.height), 0.0f) {}

  const PinholeCamera& camera() const { return camera_; }
  float depth(int x, int y) const { return depth_[index(x, y)]; }
  void setDepth(int x, int y, float z) { depth_[index(x, y)] = z; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < camera_.width && y < camera_.height; }
  const std::vector<float>& depths() const { return depth_; }

  // The measured point at pixel (x, y) (its centre), or nothing where there is no measurement.
  std::optional<Vec3d> point(int x, int y) const;
  // The measured surface at image point (u, v) (pixel centres at half integers): the depth
  // interpolated bilinearly between the four nearest pixel centres, back-projected along (u, v)'s
  // ray; nothing where one of them is missing or they differ by more than `maxJump` metres.
  std::optional<Vec3d> pointAt(double u, double v, double maxJump = 0.01) const;
  // The surface normal at pixel (x, y), facing the camera (n.z < 0): the cross product of central
  // differences of the points `step` pixels away (a longer step averages a noisy sensor's depth);
  // nothing where one is missing or the depth jumps by more than `maxJump` metres (a silhouette).
  std::optional<Vec3d> normal(int x, int y, double maxJump = 0.01, int step = 1) const;

 private:
  size_t index(int x, int y) const { return size_t(y) * size_t(camera_.width) + size_t(x); }
  PinholeCamera camera_;
  std::vector<float> depth_;
};

}  // namespace lacrima::tracking
