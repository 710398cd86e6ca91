#pragma once
// Building blocks for small renderer test scenes: a look-at camera, small render settings, a
// large diffuse floor, and the statistical mean check shared by the analytic-scene tests.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "lacrima/renderer/frame.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/render_statistics.hpp"

namespace lacrima::test {

inline Camera lookAt(const Vec3& eye, const Vec3& target, float fovDegrees) {
  Camera camera;
  const Vec3 back = (eye - target).normalized();
  const Vec3 right = Vec3(0, 1, 0).cross(back).normalized();
  const Vec3 up = back.cross(right);
  camera.cameraToWorld.linear().col(0) = right;
  camera.cameraToWorld.linear().col(1) = up;
  camera.cameraToWorld.linear().col(2) = back;
  camera.cameraToWorld.translation() = eye;
  camera.verticalFovRadians = degreesToRadians(fovDegrees);
  return camera;
}

inline RenderSettings smallSettings(int size, int spp, int maxDepth) {
  RenderSettings s;
  s.width = size;
  s.height = size;
  s.samplesPerPixel = spp;
  s.maxDepth = maxDepth;
  s.seed = 7;
  return s;
}

// A 100 x 100 floor at y = 0 facing +y, with material `materialId`.
inline MeshInstance largeFloor(uint32_t materialId) {
  MeshInstance floor;
  floor.mesh.positions = {Vec3(-50, 0, -50), Vec3(50, 0, -50), Vec3(50, 0, 50), Vec3(-50, 0, 50)};
  floor.mesh.indices = {0, 2, 1, 0, 3, 2};
  floor.materialId = materialId;
  return floor;
}

// A grey diffuse ball on a grey floor under a 1 m square light 2 m up; the camera (vertical field
// of view `fovDegrees`) looks down at the ball's penumbra. Settings are the caller's.
inline Frame softShadowFrame(float fovDegrees) {
  Frame frame;
  frame.materials.push_back(Material{"grey", DiffuseParams{Color::Constant(0.5f)}, Color::Zero()});
  frame.meshes.push_back(largeFloor(0));
  frame.spheres.push_back(Sphere{Vec3(0, 0.7f, 0), 0.3f, 0});
  AreaLight light;
  light.center = Vec3(0, 2, 0);
  light.edgeU = Vec3(1, 0, 0);
  light.edgeV = Vec3(0, 0, 1);  // emits downwards
  light.radiance = Color::Constant(4.0f);
  frame.lights.push_back(light);
  frame.camera = lookAt(Vec3(0.6f, 1.6f, 1.2f), Vec3(0.3f, 0, 0.2f), fovDegrees);
  return frame;
}

// |mean - exact| < 5 standard errors + floor, for R, G and B: a biased estimator fails, noise does not.
inline void expectMean(const Film& film, double exact, double floor) {
  for (int c = 0; c < 3; ++c) {
    const MeanEstimate e = channelMean(film, c);
    EXPECT_NEAR(e.mean, exact, 5.0 * e.standardError + floor)
        << "channel " << c << ": mean " << e.mean << " +- " << e.standardError << " over " << e.count << " pixels";
  }
}

// The shared lighting and view of the small determinism scenes: a 1 m square light 2 m up,
// shining down, a dim blue background, the camera 3 m back, 48x32 at 4 spp, seed 3.
inline void addTopLightAndView(Frame& frame) {
  AreaLight light;
  light.center = Vec3(0, 2, 0);
  light.edgeU = Vec3(1, 0, 0);
  light.edgeV = Vec3(0, 0, 1);  // emits downwards (u x v = -y)
  light.radiance = Color::Constant(5.0f);
  frame.lights.push_back(light);
  frame.uniformBackground = Color(0.1f, 0.1f, 0.2f);
  frame.camera.cameraToWorld.translation() = Vec3(0, 0.5f, 3);
  frame.settings.width = 48;
  frame.settings.height = 32;
  frame.settings.samplesPerPixel = 4;
  frame.settings.seed = 3;
}

inline bool bitwiseEqual(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// Renders `frame` with 1 and 2 threads: the beauty must be bitwise the same (determinism).
inline void expectThreadCountIndependent(Frame frame) {
  frame.settings.threads = 1;
  const Film one = renderFrame(frame);
  frame.settings.threads = 2;
  const Film two = renderFrame(frame);
  EXPECT_TRUE(bitwiseEqual(one.rgba, two.rgba));
}

// A sphere light of radius r at height h above the origin whose radiance makes a floor of
// albedo `albedo` straight below it reflect radiance 1: a sphere light seen from a point below
// gives E = pi Le sin^2(alpha), sin(alpha) = r / h, so Le = 1 / (albedo sin^2).
inline AreaLight sphereLightGivingUnitFloor(float albedo, float radius, float height) {
  AreaLight light;
  light.shape = AreaLight::Shape::Sphere;
  light.center = Vec3(0, height, 0);
  light.radius = radius;
  const float sin2 = (radius / height) * (radius / height);
  light.radiance = Color::Constant(1.0f / (albedo * sin2));
  return light;
}

}  // namespace lacrima::test
