// The synthetic capture of a face model; see synthetic_capture.hpp.
#include "lacrima/tracking/synthetic_capture.hpp"

#include <limits>

#include "lacrima/geometry/sampler.hpp"
#include "lacrima/tracking/depth_sensor.hpp"

namespace lacrima::tracking {

DepthFrame captureDepth(const BlendshapeModel& model, const Eigen::VectorXd& weights, const Eigen::Isometry3d& pose,
                        const PinholeCamera& camera, double noise, uint64_t seed) {
  TriangleMesh mesh = model.shape(weights);
  transformMesh(mesh, Affine3(pose.cast<float>().matrix()));
  DepthFrame frame = rasterizeDepth(mesh, camera);
  addSensorNoise(frame, noise, seed);
  return frame;
}

std::vector<Eigen::Vector2d> projectLandmarks(const BlendshapeModel& model, const Eigen::VectorXd& weights,
                                              const Eigen::Isometry3d& pose, const PinholeCamera& camera, double noise,
                                              uint64_t seed) {
  const std::vector<Vec3d> p = model.positions(weights);
  std::vector<Eigen::Vector2d> out(68, Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN()));
  for (size_t l = 0; l < 68 && l < model.landmarkVertices.size(); ++l) {
    const int v = model.landmarkVertices[l];
    if (v < 0) continue;
    const Eigen::Vector2d jitter(double(uint64ToUnitFloat(hashCombine(hashCombine(seed, l), 1))) - 0.5,
                                 double(uint64ToUnitFloat(hashCombine(hashCombine(seed, l), 2))) - 0.5);
    out[l] = camera.project(pose * p[size_t(v)]) + 2.0 * noise * jitter;
  }
  return out;
}

}  // namespace lacrima::tracking
