// Renders must be bitwise identical whatever the thread count, and repeatable.
#include <gtest/gtest.h>

#include <cstring>

#include "lacrima/geometry/shapes.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace determinism_test {

using test::bitwiseEqual;

Frame smallMixedScene() {
  Frame frame;
  frame.materials.push_back(Material{"floor", DiffuseParams{Color(0.6f, 0.5f, 0.4f)}, Color::Zero()});
  frame.materials.push_back(Material{"water", SmoothDielectricParams{}, Color::Zero()});
  frame.materials.push_back(Material{"skin", SkinParams{}, Color::Zero()});
  MeshInstance floor{makeRectangle(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 0, -4)), 0};
  frame.meshes.push_back(floor);
  frame.meshes.push_back(MeshInstance{makeEllipsoid(Vec3(0.4f, 0.3f, 0), Mat3(Vec3(0.3f, 0.2f, 0.2f).asDiagonal())), 2});
  frame.spheres.push_back(Sphere{Vec3(-0.4f, 0.35f, 0.2f), 0.35f, 1});
  test::addTopLightAndView(frame);
  return frame;
}

TEST(Determinism, OneAndTwoThreadsGiveBitwiseEqualFilms) {
  Frame frame = smallMixedScene();
  frame.settings.threads = 1;
  const Film one = renderFrame(frame);
  frame.settings.threads = 2;
  const Film two = renderFrame(frame);
  EXPECT_TRUE(bitwiseEqual(one.rgba, two.rgba));
  EXPECT_TRUE(bitwiseEqual(one.albedo, two.albedo));
  EXPECT_TRUE(bitwiseEqual(one.normal, two.normal));
  EXPECT_TRUE(bitwiseEqual(one.depth, two.depth));
}

TEST(Determinism, SeedAndFrameChangeTheNoise) {
  Frame frame = smallMixedScene();
  const Film base = renderFrame(frame);
  frame.settings.seed = 4;
  EXPECT_FALSE(bitwiseEqual(base.rgba, renderFrame(frame).rgba));
  frame.settings.seed = 3;
  frame.settings.frameNumber = 2;
  EXPECT_FALSE(bitwiseEqual(base.rgba, renderFrame(frame).rgba));
}

TEST(Determinism, RenderHasNoNonFiniteSamples) {
  RenderStats stats;
  renderFrame(smallMixedScene(), &stats);
  EXPECT_EQ(stats.nonFiniteSamples, 0u);
  EXPECT_GT(stats.rays, stats.cameraPaths);
}

}  // namespace determinism_test
}  // namespace lacrima
