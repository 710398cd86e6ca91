// Motion blur: objects and the camera move linearly between shutter open and close and every
// camera ray carries a time. A self-emitting black sphere (radiance 1 where it is seen, 0
// elsewhere) makes the image sum proportional to the sphere's projected area, which motion
// must not change: blur redistributes energy, it does not create or lose any.
#include <gtest/gtest.h>

#include <cstring>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace motion_blur_test {

constexpr int kSize = 48;
constexpr int kSpp = 128;
const Vec3 kOpen(-0.4f, 0.0f, 0.0f), kClose(0.4f, 0.0f, 0.0f);
constexpr float kRadius = 0.15f;

Frame emitterScene() {
  Frame frame;
  frame.materials.push_back(Material{"glow", DiffuseParams{Color::Zero()}, Color::Ones()});
  frame.camera = test::lookAt(Vec3(0, 0, 10), Vec3::Zero(), 12.0f);
  frame.settings = test::smallSettings(kSize, kSpp, 2);
  return frame;
}

Frame sphereScene(const Vec3& open, std::optional<Vec3> close) {
  Frame frame = emitterScene();
  Sphere sphere(open, kRadius, 0);
  sphere.centerAtClose = close;
  frame.spheres.push_back(sphere);
  return frame;
}

Frame meshScene(const Vec3& open, const Vec3& close) {
  Frame frame = emitterScene();
  MeshInstance mesh(makeEllipsoid(open, kRadius * Mat3::Identity()), 0);
  if (open != close)
    for (const Vec3& p : mesh.mesh.positions) mesh.positionsAtClose.push_back(p + (close - open));
  frame.meshes.push_back(mesh);
  return frame;
}

double imageSum(const Film& film) {
  double sum = 0.0;
  for (size_t p = 0; p < film.rgba.size(); p += 4) sum += film.rgba[p];
  return sum;
}

// Standard error of imageSum: each pixel is the mean of kSpp hit-or-miss samples of value 1,
// so its variance is v (1 - v) / kSpp.
double imageSumError(const Film& film) {
  double variance = 0.0;
  for (size_t p = 0; p < film.rgba.size(); p += 4) variance += film.rgba[p] * (1.0 - film.rgba[p]) / kSpp;
  return std::sqrt(variance);
}

// Within 5 standard errors of both renders, plus 0.3% for the perspective change of the
// projected area along the path.
void expectSameEnergy(const Film& blurred, double expectedSum, double expectedError) {
  const double tolerance = 5.0 * std::hypot(imageSumError(blurred), expectedError) + 3e-3 * expectedSum;
  EXPECT_NEAR(imageSum(blurred), expectedSum, tolerance);
}

// Columns in which any pixel sees the emitter: the streak's length in pixels.
int litColumns(const Film& film) {
  int columns = 0;
  for (int x = 0; x < film.width; ++x) {
    bool lit = false;
    for (int y = 0; y < film.height; ++y) lit = lit || film.rgba[4 * (size_t(y) * film.width + x)] > 0.0f;
    columns += lit;
  }
  return columns;
}

// The static sphere's image sum (and its standard error), averaged over positions along the
// path (perspective makes the projected area depend slightly on the position).
std::pair<double, double> staticSumAlongPath(const std::function<Frame(const Vec3&)>& sceneAt) {
  double sum = 0.0, variance = 0.0;
  constexpr int kPositions = 5;
  for (int i = 0; i < kPositions; ++i) {
    const float t = (i + 0.5f) / kPositions;
    const Film film = renderFrame(sceneAt((1.0f - t) * kOpen + t * kClose));
    sum += imageSum(film);
    variance += imageSumError(film) * imageSumError(film);
  }
  return {sum / kPositions, std::sqrt(variance) / kPositions};
}

TEST(MotionBlur, MovingSphereKeepsItsEnergyAndStreaks) {
  const Film still = renderFrame(sphereScene(Vec3::Zero(), std::nullopt));
  const Film blurred = renderFrame(sphereScene(kOpen, kClose));
  const auto [expected, error] = staticSumAlongPath([](const Vec3& c) { return sphereScene(c, std::nullopt); });
  expectSameEnergy(blurred, expected, error);
  // The sphere covers ~0.3 / 2.1 of the width; its streak ~1.1 / 2.1.
  EXPECT_LT(litColumns(still), kSize / 5);
  EXPECT_GT(litColumns(blurred), kSize / 2);
}

TEST(MotionBlur, DeformingMeshKeepsItsEnergyAndStreaks) {
  const Film blurred = renderFrame(meshScene(kOpen, kClose));
  const auto [expected, error] = staticSumAlongPath([](const Vec3& c) { return meshScene(c, c); });
  expectSameEnergy(blurred, expected, error);
  EXPECT_GT(litColumns(blurred), kSize / 2);
}

TEST(MotionBlur, MovingCameraBlursAStillSphere) {
  Frame frame = sphereScene(Vec3::Zero(), std::nullopt);
  Affine3 close = frame.camera.cameraToWorld;
  close.translation() += Vec3(0.8f, 0, 0);
  frame.camera.cameraToWorldAtClose = close;
  const Film blurred = renderFrame(frame);
  const Film still = renderFrame(sphereScene(Vec3::Zero(), std::nullopt));
  expectSameEnergy(blurred, imageSum(still), imageSumError(still));
  EXPECT_GT(litColumns(blurred), kSize / 2);
}

// Motion blur on for something that does not move: the same picture within noise (a time
// sample is drawn, so the noise differs), and a truly still frame draws no time sample at all.
TEST(MotionBlur, StillObjectWithShutterOpenRendersTheSameWithinNoise) {
  const Film off = renderFrame(sphereScene(Vec3::Zero(), std::nullopt));
  const Film on = renderFrame(sphereScene(Vec3::Zero(), Vec3::Zero()));
  EXPECT_FALSE(sphereScene(Vec3::Zero(), std::nullopt).hasMotion());
  EXPECT_TRUE(sphereScene(Vec3::Zero(), Vec3::Zero()).hasMotion());
  const test::MeanEstimate a = test::channelMean(off, 0), b = test::channelMean(on, 0);
  EXPECT_NEAR(a.mean, b.mean, 5.0 * std::hypot(a.standardError, b.standardError));
}

TEST(MotionBlur, OneAndTwoThreadsGiveBitwiseEqualFilms) {
  Frame frame = sphereScene(kOpen, kClose);
  test::expectThreadCountIndependent(frame);
}

}  // namespace motion_blur_test
}  // namespace lacrima
