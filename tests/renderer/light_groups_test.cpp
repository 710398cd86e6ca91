// Light groups (lacrima/renderer/light_groups.hpp): a layer per group, named; the groups add up
// to the beauty in every pixel; a group is its lights' light (doubling a light doubles its group
// and leaves the others); the layers do not depend on the thread count and leave the beauty as it
// was.
#include <gtest/gtest.h>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/renderer/light_groups.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace light_groups_test {

// A grey floor and a glowing panel under a key (named) and a fill (unnamed) light, with a sky.
Frame keyAndFill(float keyRadiance = 5.0f) {
  Frame frame;
  frame.materials.push_back(Material{"grey", DiffuseParams{Color(0.6f, 0.6f, 0.6f)}, Color::Zero()});
  frame.materials.push_back(Material{"panel", DiffuseParams{Color(0.2f, 0.2f, 0.2f)}, Color(0.5f, 0.3f, 0.1f)});
  frame.meshes.push_back(test::largeFloor(0));
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(0.6f, 0.3f, -0.5f), Vec3(0.3f, 0, 0), Vec3(0, 0.3f, 0)), 1});
  AreaLight key;
  key.center = Vec3(-0.8f, 1.5f, 0.5f);
  key.edgeU = Vec3(0.5f, 0, 0);
  key.edgeV = Vec3(0, 0, 0.5f);  // emits downwards
  key.radiance = Color::Constant(keyRadiance);
  key.group = "key";
  AreaLight fill = key;
  fill.center = Vec3(1.0f, 1.2f, 1.0f);
  fill.radiance = Color(1.0f, 1.2f, 1.5f);
  fill.group = "";
  frame.lights = {key, fill};
  frame.uniformBackground = Color(0.2f, 0.25f, 0.3f);
  frame.camera = test::lookAt(Vec3(0, 1.2f, 3), Vec3(0, 0.2f, 0), 40.0f);
  frame.settings = test::smallSettings(40, 16, 6);
  frame.settings.lightGroups = true;
  return frame;
}

const FilmLayer& layerNamed(const Film& film, const std::string& group) {
  return test::rgbLayer(film, lightGroupLayer(group));
}

double layerMean(const FilmLayer& layer, int channel) { return test::rgbLayerMean(layer, channel); }

TEST(LightGroups, EachGroupHasALayerAndTheyAddUpToTheBeauty) {
  const Frame frame = keyAndFill();
  const LightGroups groups = lightGroupsOf(frame);
  EXPECT_EQ(groups.names, (std::vector<std::string>{"key", "light1", "environment", "emission"}));
  const Film film = renderFrame(frame);
  ASSERT_EQ(film.layers.size(), 4u);
  EXPECT_EQ(film.layers[0].channels, (std::vector<std::string>{"lightgroup_key.R", "lightgroup_key.G", "lightgroup_key.B"}));
  double worst = 0.0;
  for (size_t p = 0; p < size_t(film.width) * film.height; ++p)
    for (int c = 0; c < 3; ++c) {
      double sum = 0.0;
      for (const FilmLayer& layer : film.layers) sum += layer.data[3 * p + size_t(c)];
      const double beauty = film.rgba[4 * p + size_t(c)];
      worst = std::max(worst, std::abs(sum - beauty) / std::max(1e-3, std::abs(beauty)));
    }
  EXPECT_LT(worst, 1e-5) << "the groups add up to the beauty (float rounding)";
  for (const char* group : {"key", "light1", "environment", "emission"})
    EXPECT_GT(layerMean(layerNamed(film, group), 0), 0.0) << group << " lights the picture";
}

TEST(LightGroups, AGroupIsItsLightsLight) {
  // Doubling the key doubles its group (in expectation: the light choice follows the power, so the
  // noise differs) and leaves the fill's.
  Frame frame = keyAndFill();
  frame.settings.samplesPerPixel = 64;
  const Film once = renderFrame(frame);
  Frame twiceFrame = keyAndFill(10.0f);
  twiceFrame.settings.samplesPerPixel = 64;
  const Film doubled = renderFrame(twiceFrame);
  const double key = layerMean(layerNamed(once, "key"), 1), keyDoubled = layerMean(layerNamed(doubled, "key"), 1);
  const double fill = layerMean(layerNamed(once, "light1"), 1), fillAfter = layerMean(layerNamed(doubled, "light1"), 1);
  std::printf("[ light groups ] key %.4f -> %.4f (x%.3f), fill %.4f -> %.4f\n", key, keyDoubled, keyDoubled / key, fill,
              fillAfter);
  EXPECT_NEAR(keyDoubled / key, 2.0, 0.06);
  EXPECT_NEAR(fillAfter / fill, 1.0, 0.06);
}

TEST(LightGroups, LightsSharingANameShareALayer) {
  Frame frame = keyAndFill();
  frame.lights[1].group = "key";
  frame.materials[1].emission = Color::Zero();
  EXPECT_EQ(lightGroupsOf(frame).names, (std::vector<std::string>{"key", "environment"}));
  EXPECT_EQ(renderFrame(frame).layers.size(), 2u);
}

TEST(LightGroups, TheLayersDoNotDependOnTheThreadsAndLeaveTheBeautyAsItWas) {
  Frame frame = keyAndFill();
  frame.settings.threads = 1;
  const Film one = renderFrame(frame);
  frame.settings.threads = 2;
  const Film two = renderFrame(frame);
  for (size_t l = 0; l < one.layers.size(); ++l) EXPECT_TRUE(test::bitwiseEqual(one.layers[l].data, two.layers[l].data));
  frame.settings.lightGroups = false;
  const Film plain = renderFrame(frame);
  EXPECT_TRUE(plain.layers.empty());
  EXPECT_TRUE(test::bitwiseEqual(plain.rgba, two.rgba));
}

}  // namespace light_groups_test
}  // namespace lacrima
