// Renders must be bitwise identical whatever the thread count, and repeatable; a region of a frame
// renders the frame's pixels.
#include <gtest/gtest.h>

#include <cstring>

#include "lacrima/base/error.hpp"
#include "lacrima/mesh/shapes.hpp"
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

// A render region (a crop window) renders the frame's own pixels: every pixel's samples and camera
// ray are the whole frame's, so the region is the frame's crop bitwise, beauty and AOVs.
TEST(RenderRegion, ARegionsPixelsAreTheWholeFramesBitwise) {
  Frame frame = smallMixedScene();
  const Film whole = renderFrame(frame);
  frame.settings.region = PixelRegion{17, 12, 11, 7};  // the floor, the drop and the skin's ellipsoid
  const Film region = renderFrame(frame);
  ASSERT_EQ(region.width, 11);
  ASSERT_EQ(region.height, 7);
  EXPECT_EQ(region.originX, 17);
  EXPECT_EQ(region.originY, 12);
  EXPECT_EQ(region.frameWidth, frame.settings.width);
  EXPECT_EQ(region.frameHeight, frame.settings.height);
  const auto cropOf = [&](const std::vector<float>& plane, int channels) {
    std::vector<float> crop;
    for (int y = 12; y < 19; ++y)
      for (int x = 17; x < 28; ++x)
        for (int c = 0; c < channels; ++c) crop.push_back(plane[whole.pixelIndex(x, y) * size_t(channels) + c]);
    return crop;
  };
  EXPECT_TRUE(bitwiseEqual(region.rgba, cropOf(whole.rgba, 4)));
  EXPECT_TRUE(bitwiseEqual(region.albedo, cropOf(whole.albedo, 3)));
  EXPECT_TRUE(bitwiseEqual(region.normal, cropOf(whole.normal, 3)));
  EXPECT_TRUE(bitwiseEqual(region.depth, cropOf(whole.depth, 1)));
  // Another place gives other pixels (the region is not one colour).
  frame.settings.region = PixelRegion{18, 12, 11, 7};
  EXPECT_FALSE(bitwiseEqual(region.rgba, renderFrame(frame).rgba));
}

TEST(RenderRegion, ARegionOutsideTheFrameIsBadInput) {
  Frame frame = smallMixedScene();
  frame.settings.region = PixelRegion{frame.settings.width - 4, 0, 5, 2};
  EXPECT_THROW(renderFrame(frame), InputError);
  frame.settings.region = PixelRegion{-1, 0, 5, 2};
  EXPECT_THROW(renderFrame(frame), InputError);
}

}  // namespace determinism_test
}  // namespace lacrima
