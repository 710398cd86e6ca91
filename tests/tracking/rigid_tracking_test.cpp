// Rigid tracking (lacrima/tracking): the pinhole camera and depth frames, the synthetic depth
// sensor (z-buffer and Nguyen et al. 2012's axial noise), point-plane ICP recovering a known head
// motion of the ICT face from its rendered depth, and Weise et al.'s adaptive pose filter.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/base/hash.hpp"
#include "lacrima/mesh/shapes.hpp"
#include "lacrima/tracking/depth_sensor.hpp"
#include "lacrima/tracking/pose_filter.hpp"
#include "lacrima/tracking/rigid_icp.hpp"
#include "tracking/tracking_support.hpp"

namespace lacrima::tracking {
namespace rigid_tracking_test {

constexpr double kDegree = std::numbers::pi / 180.0;

TEST(PinholeCamera, ProjectsAndBackProjects) {
  const PinholeCamera camera;
  const Vec3d p(0.05, -0.03, 0.7);
  const Eigen::Vector2d pixel = camera.project(p);
  EXPECT_LT((camera.backProject(pixel.x(), pixel.y(), 0.7) - p).norm(), 1e-12);
  EXPECT_NEAR(camera.project(Vec3d(0, 0, 1)).x(), camera.cx, 1e-12) << "the optical axis through the principal point";
}

TEST(DepthSensor, RasterisesASphereAndAPlane) {
  PinholeCamera camera;
  camera.width = 160, camera.height = 120, camera.fx = camera.fy = 130, camera.cx = 80, camera.cy = 60;
  // A sphere of 5 cm radius 60 cm away, on the optical axis.
  const TriangleMesh sphere = makeEllipsoid(Vec3(0, 0, 0.6f), Mat3(Mat3::Identity() * 0.05f), 96, 192);
  const DepthFrame frame = rasterizeDepth(sphere, camera);
  EXPECT_NEAR(frame.depth(80, 60), 0.55, 2e-4) << "the nearest point of the sphere";
  EXPECT_EQ(frame.depth(5, 5), 0.0f) << "no measurement off the sphere";
  const auto n = frame.normal(80, 60);
  ASSERT_TRUE(n);
  const Vec3d expected = (*frame.point(80, 60) - Vec3d(0, 0, 0.6)).normalized();
  EXPECT_LT((*n - expected).norm(), 0.01) << "the sphere's normal, facing the camera";
  EXPECT_FALSE(frame.normal(5, 5));
}

TEST(DepthSensor, TheNoiseHasTheAxialModelsDeviation) {
  PinholeCamera camera;
  camera.width = 200, camera.height = 200;
  DepthFrame frame(camera);
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) frame.setDepth(x, y, 1.5f);
  addSensorNoise(frame, 1.0, 42);
  double sum = 0.0, squares = 0.0;
  for (float z : frame.depths()) sum += z - 1.5, squares += (z - 1.5) * (z - 1.5);
  const double n = double(frame.depths().size()), mean = sum / n, sigma = std::sqrt(squares / n - mean * mean);
  // sigma_z(1.5 m) = 0.0012 + 0.0019 * 1.1^2 = 3.50 mm.
  EXPECT_NEAR(sigma, kinectAxialNoise(1.5), 0.03 * kinectAxialNoise(1.5));
  EXPECT_NEAR(mean, 0.0, 4.0 * kinectAxialNoise(1.5) / std::sqrt(n));
  DepthFrame again(camera);
  for (int y = 0; y < 200; ++y)
    for (int x = 0; x < 200; ++x) again.setDepth(x, y, 1.5f);
  addSensorNoise(again, 1.0, 42);
  EXPECT_EQ(again.depths(), frame.depths()) << "the same seed, the same noise";
}

// The ICT face's skin (M_Face), its points and normals, and the points of its upper part (above
// the nose tip's height), the region Weise et al. track rigidly.
struct FaceModel {
  TriangleMesh skin;
  std::vector<Vec3d> upperPoints, upperNormals;
};

const FaceModel& ictFace() {
  static const FaceModel model = [] {
    const GltfAsset asset = loadGltfAsset(std::string(LACRIMA_SOURCE_DIR) + "/scenes/assets/ict-face/ict_face.glb");
    FaceModel m;
    for (const GltfPrimitive& p : asset.primitives)
      if (p.part == "M_Face") m.skin = p.mesh;
    const Landmark& noseTip = asset.landmarks.at(30);  // iBUG 68: 30 is the tip of the nose
    const float noseHeight = asset.primitives.at(size_t(noseTip.primitive)).mesh.positions.at(noseTip.vertex).y();
    for (size_t v = 0; v < m.skin.positions.size(); ++v)
      if (m.skin.positions[v].y() > noseHeight) {
        m.upperPoints.push_back(m.skin.positions[v].cast<double>());
        m.upperNormals.push_back(m.skin.normals[v].cast<double>());
      }
    return m;
  }();
  return model;
}

using test::headPose;

DepthFrame renderDepth(const Eigen::Isometry3d& pose, double noise, uint64_t seed) {
  TriangleMesh mesh = ictFace().skin;
  transformMesh(mesh, Affine3(pose.cast<float>().matrix()));
  DepthFrame frame = rasterizeDepth(mesh, PinholeCamera{});
  addSensorNoise(frame, noise, seed);
  return frame;
}

double angleBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) { return test::degreesBetween(a, b); }

TEST(RigidIcp, RecoversAKnownHeadMotionFromTheFacesDepth) {
  const Eigen::Isometry3d previous = headPose(0.7, Vec3d::Zero(), Vec3d::Zero());
  const Eigen::Isometry3d current = headPose(0.7, Vec3d(3, 6, -2), Vec3d(0.01, -0.005, 0.01));
  for (const double noise : {0.0, 1.0}) {
    const DepthFrame frame = renderDepth(current, noise, 7);
    const RigidIcpResult r = alignRigid(ictFace().upperPoints, ictFace().upperNormals, frame, previous);
    const double angle = angleBetween(r.pose, current), shift = (r.pose.translation() - current.translation()).norm();
    std::printf("[ icp ] noise x%.0f: %d iterations, %d pairs, rms %.2f mm; off by %.3f degrees, %.2f mm\n", noise,
                r.iterations, r.pairs, 1e3 * r.rmsDistance, angle, 1e3 * shift);
    // Measured: 0.020 degrees and 0.04 mm without noise, 0.078 degrees and 0.09 mm with it.
    EXPECT_LT(angle, noise == 0.0 ? 0.05 : 0.25);
    EXPECT_LT(shift, noise == 0.0 ? 1e-4 : 3e-4);
    EXPECT_GT(r.pairs, 1000);
  }
}

// A uniform number in [-0.5, 0.5) from (frame, component).
double jitter(int frame, int component) {
  return double(uint64ToUnitFloat(hashCombine(uint64_t(frame), uint64_t(component)))) - 0.5;
}

TEST(PoseFilter, AStillPoseStaysPutAndItsJitterShrinks) {
  PoseFilter still;
  const Eigen::Isometry3d pose = headPose(0.7, Vec3d(1, 2, 3), Vec3d(0.01, 0.02, 0.0));
  for (int i = 0; i < 10; ++i) EXPECT_LT((still.add(pose).matrix() - pose.matrix()).norm(), 1e-12);
  // A still head tracked with jitter of 0.2 mm and 0.1 degrees (standard deviations) per frame.
  PoseFilter filter;
  double rawShift = 0.0, filteredShift = 0.0, rawAngle = 0.0, filteredAngle = 0.0;
  for (int i = 0; i < 400; ++i) {
    const Eigen::Isometry3d raw =
        headPose(0.7, 0.35 * Vec3d(jitter(i, 0), jitter(i, 1), jitter(i, 2)), 7e-4 * Vec3d(jitter(i, 3), jitter(i, 4), jitter(i, 5)));
    const Eigen::Isometry3d out = filter.add(raw);
    const Eigen::Isometry3d truth = headPose(0.7, Vec3d::Zero(), Vec3d::Zero());
    if (i < 10) continue;
    rawShift += (raw.translation() - truth.translation()).squaredNorm();
    filteredShift += (out.translation() - truth.translation()).squaredNorm();
    rawAngle += std::pow(angleBetween(raw, truth), 2), filteredAngle += std::pow(angleBetween(out, truth), 2);
  }
  std::printf("[ filter ] still head: jitter %.3f -> %.3f mm, %.3f -> %.3f degrees (rms)\n", 1e3 * std::sqrt(rawShift / 390),
              1e3 * std::sqrt(filteredShift / 390), std::sqrt(rawAngle / 390), std::sqrt(filteredAngle / 390));
  EXPECT_LT(filteredShift, 0.4 * rawShift) << "the translation's jitter at least 1.6x smaller";
  EXPECT_LT(filteredAngle, 0.4 * rawAngle) << "the rotation's too";
}

TEST(PoseFilter, AFastMotionIsFollowedWithLittleLag) {
  // A still head that starts turning 2 degrees and moving 5 mm a frame (60 degrees and 15 cm a
  // second at 30 Hz). Once the window has seen the motion, the filter follows it closely; in the
  // first frames of the motion the window's variation is still small and it lags (measured: at
  // most 1.8 mm and 0.7 degrees in the first five frames; 0.034 mm and 0.011 degrees after).
  PoseFilter filter;
  const PoseFilterParams defaults;
  double onsetShift = 0.0, onsetAngle = 0.0, worstShift = 0.0, worstAngle = 0.0;
  for (int i = -10; i < 30; ++i) {
    const int moved = std::max(i, 0);
    const Eigen::Isometry3d raw = headPose(0.7, Vec3d(0, 2.0 * moved, 0), Vec3d(0.005 * moved, 0, 0));
    const Eigen::Isometry3d out = filter.add(raw);
    const double shift = (out.translation() - raw.translation()).norm(), angle = angleBetween(out, raw);
    if (i > 0 && i <= defaults.window) onsetShift = std::max(onsetShift, shift), onsetAngle = std::max(onsetAngle, angle);
    if (i > defaults.window) worstShift = std::max(worstShift, shift), worstAngle = std::max(worstAngle, angle);
  }
  std::printf("[ filter ] fast motion: lag %.3f mm, %.3f degrees at its onset, then at most %.3f mm, %.3f degrees\n",
              1e3 * onsetShift, onsetAngle, 1e3 * worstShift, worstAngle);
  EXPECT_LT(worstShift, 0.25e-3) << "a twentieth of a frame's motion";
  EXPECT_LT(worstAngle, 0.1);
  EXPECT_LT(onsetShift, 2.5e-3) << "never more than half a frame's motion";
  EXPECT_LT(onsetAngle, 1.0);
}

}  // namespace rigid_tracking_test
}  // namespace lacrima::tracking
