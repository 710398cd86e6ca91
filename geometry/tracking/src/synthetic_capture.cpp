// The synthetic capture of a face model; see synthetic_capture.hpp.
#include "lacrima/tracking/synthetic_capture.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "lacrima/base/hash.hpp"
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

namespace {

// A uniform number in [-1, 1) from (seed, a, b).
double signedUniform(uint64_t seed, uint64_t a, uint64_t b) {
  return 2.0 * double(uint64ToUnitFloat(hashCombine(hashCombine(seed, a), b))) - 1.0;
}

// The exact projections of the model's landmarks (NaN where one is not on the model), and their
// model-space vertices' normals turned by the pose.
struct ProjectedLandmarks {
  std::vector<Eigen::Vector2d> points;
  std::vector<Vec3d> cameraPoints, cameraNormals;
};

ProjectedLandmarks projectExactly(const BlendshapeModel& model, const Eigen::VectorXd& weights,
                                  const Eigen::Isometry3d& pose, const PinholeCamera& camera, bool withNormals) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ProjectedLandmarks out{std::vector<Eigen::Vector2d>(68, Eigen::Vector2d::Constant(nan)),
                         std::vector<Vec3d>(68, Vec3d::Constant(nan)), std::vector<Vec3d>(68, Vec3d::Constant(nan))};
  std::optional<TriangleMesh> shape;
  if (withNormals) shape = model.shape(weights);
  const std::vector<Vec3d> p = shape ? std::vector<Vec3d>() : model.positions(weights);
  for (size_t l = 0; l < 68 && l < model.landmarkVertices.size(); ++l) {
    const int v = model.landmarkVertices[l];
    if (v < 0) continue;
    const Vec3d position = shape ? Vec3d(shape->positions[size_t(v)].cast<double>()) : p[size_t(v)];
    out.cameraPoints[l] = pose * position;
    out.points[l] = camera.project(out.cameraPoints[l]);
    if (shape) out.cameraNormals[l] = pose.linear() * shape->normals[size_t(v)].cast<double>();
  }
  return out;
}

// Whether the camera sees landmark point `p` with normal `n` (camera space): its skin facing the
// camera, and not behind the surface the depth map measured there by more than 1 cm.
bool seenByCamera(const Vec3d& p, const Vec3d& n, const Eigen::Vector2d& pixel, const DepthFrame* seen) {
  if (n.dot(p) >= 0.0) return false;
  if (!seen) return true;
  const int x = int(std::floor(pixel.x())), y = int(std::floor(pixel.y()));
  const PinholeCamera& c = seen->camera();
  if (x < 0 || y < 0 || x >= c.width || y >= c.height) return false;
  const float z = seen->depth(x, y);
  return z <= 0.0f || p.z() <= double(z) + 0.01;
}

}  // namespace

std::vector<Eigen::Vector2d> projectLandmarks(const BlendshapeModel& model, const Eigen::VectorXd& weights,
                                              const Eigen::Isometry3d& pose, const PinholeCamera& camera, double noise,
                                              uint64_t seed) {
  std::vector<Eigen::Vector2d> out = projectExactly(model, weights, pose, camera, false).points;
  for (size_t l = 0; l < out.size(); ++l)
    out[l] += noise * Eigen::Vector2d(signedUniform(seed, l, 1), signedUniform(seed, l, 2));
  return out;
}

std::vector<Eigen::Vector2d> detectLandmarks(const BlendshapeModel& model, const Eigen::VectorXd& weights,
                                             const Eigen::Isometry3d& pose, const PinholeCamera& camera,
                                             const LandmarkDetectorErrors& errors, uint64_t seed, int frame,
                                             double seconds, const DepthFrame* seen) {
  const ProjectedLandmarks exact = projectExactly(model, weights, pose, camera, errors.dropHidden);
  std::vector<Eigen::Vector2d> out = exact.points;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (size_t l = 0; l < out.size(); ++l) {
    if (!out[l].allFinite()) continue;
    if (l <= 16 && errors.contourDrift > 0.0) {
      // Along the contour: towards the next point (the previous one at the chin's far end).
      const Eigen::Vector2d& a = exact.points[l == 16 ? 15 : l];
      const Eigen::Vector2d& b = exact.points[l == 16 ? 16 : l + 1];
      if (a.allFinite() && b.allFinite() && (b - a).norm() > 0.0) {
        const double period = 2.0 + 3.0 * (0.5 + 0.5 * signedUniform(seed, l, 3));
        const double phase = std::numbers::pi * signedUniform(seed, l, 4);
        out[l] += errors.contourDrift * std::sin(2.0 * std::numbers::pi * seconds / period + phase) * (b - a).normalized();
      }
    }
    const uint64_t frameSeed = hashCombine(seed, uint64_t(uint32_t(frame)));
    out[l] += errors.jitter * Eigen::Vector2d(signedUniform(frameSeed, l, 1), signedUniform(frameSeed, l, 2));
    // The jaw line is never hidden: a detector places it on the face's outline whatever turns away.
    if (errors.dropHidden && l > 16 && !seenByCamera(exact.cameraPoints[l], exact.cameraNormals[l], exact.points[l], seen))
      out[l] = Eigen::Vector2d::Constant(nan);
  }
  return out;
}

}  // namespace lacrima::tracking
