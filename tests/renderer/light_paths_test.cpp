// Light-path AOVs (lacrima/renderer/light_paths.hpp): a layer per pass, named as compositors
// expect; the passes add up to the beauty in every pixel; each pass is the light of its own kind
// (a convex diffuse ball in a furnace is all diffuse_direct and reflects its albedo; a skin ball's
// specular_direct and diffuse_direct are its lobes' own albedos; light through subsurface skin is
// subsurface); the layers do not depend on the thread count and leave the beauty as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/materials/skin.hpp"
#include "lacrima/renderer/camera.hpp"
#include "lacrima/renderer/environment.hpp"
#include "lacrima/renderer/light_paths.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace light_paths_test {

// A grey floor, a skin ball with subsurface, a water drop and a frosted (rough) glass ball in
// front of it, a glowing panel, a thin pane of water against the sky (light straight through it is
// transmission_direct), under a key light and a sky.
Frame everyKindOfLight() {
  Frame frame;
  frame.materials.push_back(Material{"grey", DiffuseParams{Color(0.6f, 0.6f, 0.6f)}, Color::Zero()});
  frame.materials.push_back(Material{"panel", DiffuseParams{Color(0.2f, 0.2f, 0.2f)}, Color(0.5f, 0.3f, 0.1f)});
  SkinParams skin;
  skin.subsurface = SubsurfaceParams{Color(0.05f, 0.03f, 0.02f), SubsurfaceMethod::RandomWalk};
  frame.materials.push_back(Material{"skin", skin, Color::Zero()});
  frame.materials.push_back(Material{"water", SmoothDielectricParams{}, Color::Zero()});
  RoughDielectricParams frosted;
  frosted.roughness = 0.4f;
  frame.materials.push_back(Material{"frosted", frosted, Color::Zero()});
  frame.meshes.push_back(test::largeFloor(0));
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(0.7f, 0.3f, -0.5f), Vec3(0.3f, 0, 0), Vec3(0, 0.3f, 0)), 1});
  MeshInstance pane{makeRectangle(Vec3(0.35f, 1.0f, 1.6f), Vec3(0.3f, 0, 0), Vec3(0, 0.2f, 0)), 3};
  pane.thinSheet = true;
  frame.meshes.push_back(pane);
  frame.spheres.push_back(Sphere{Vec3(-0.3f, 0.35f, 0), 0.35f, 2});
  frame.spheres.push_back(Sphere{Vec3(0.05f, 0.15f, 0.5f), 0.15f, 3});
  frame.spheres.push_back(Sphere{Vec3(0.45f, 0.2f, 0.3f), 0.2f, 4});
  AreaLight key;
  key.center = Vec3(-0.8f, 1.5f, 0.8f);
  key.edgeU = Vec3(0.5f, 0, 0);
  key.edgeV = Vec3(0, 0, 0.5f);  // emits downwards
  key.radiance = Color::Constant(6.0f);
  frame.lights = {key};
  frame.uniformBackground = Color(0.2f, 0.25f, 0.3f);
  frame.camera = test::lookAt(Vec3(0, 0.9f, 2.6f), Vec3(0, 0.25f, 0), 40.0f);
  frame.settings = test::smallSettings(40, 16, 8);
  frame.settings.lightPaths.addAll();
  return frame;
}

const FilmLayer& passLayer(const Film& film, LightPath pass) { return test::rgbLayer(film, lightPathName(pass)); }

double layerMean(const FilmLayer& layer, int channel) { return test::rgbLayerMean(layer, channel); }

// A film whose beauty is one pass's layer (for the statistical mean checks).
Film filmOfPass(const Film& film, LightPath pass) {
  Film out = film;
  const FilmLayer& layer = passLayer(film, pass);
  for (size_t p = 0; p < size_t(film.width) * film.height; ++p)
    for (size_t c = 0; c < 3; ++c) out.rgba[4 * p + c] = layer.data[3 * p + c];
  return out;
}

double worstRecombination(const Film& film) {
  double worst = 0.0;
  for (size_t p = 0; p < size_t(film.width) * film.height; ++p)
    for (size_t c = 0; c < 3; ++c) {
      double sum = 0.0;
      for (const FilmLayer& layer : film.layers) sum += layer.data[3 * p + c];
      const double beauty = film.rgba[4 * p + c];
      worst = std::max(worst, std::abs(sum - beauty) / std::max(1e-3, std::abs(beauty)));
    }
  return worst;
}

TEST(LightPaths, EveryPassHasALayerAndTheyAddUpToTheBeauty) {
  const Film film = renderFrame(everyKindOfLight());
  ASSERT_EQ(film.layers.size(), kLightPathCount);
  EXPECT_EQ(film.layers[0].channels,
            (std::vector<std::string>{"diffuse_direct.R", "diffuse_direct.G", "diffuse_direct.B"}));
  EXPECT_EQ(film.layers.back().channels.front(), "environment.R");
  EXPECT_LT(worstRecombination(film), 1e-5) << "the passes add up to the beauty (float rounding)";
  for (const LightPath pass : allLightPaths()) {
    const double mean = layerMean(passLayer(film, pass), 1);
    std::printf("[ light paths ] %-22s %.5f\n", lightPathName(pass).c_str(), mean);
    EXPECT_GT(mean, 0.0) << lightPathName(pass) << " has light in this scene";
  }
}

TEST(LightPaths, AConvexDiffuseBallInAFurnaceIsAllDiffuseDirect) {
  // Every path from the ball escapes after one bounce: it reflects its albedo (the environment is
  // importance-sampled, so next-event estimates and hits by MIS both count), all of it direct.
  const float albedo = 0.6f;
  Frame frame;
  frame.materials.push_back(Material{"grey", DiffuseParams{Color::Constant(albedo)}, Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 1.0f, 0});
  frame.environment = std::make_shared<EnvironmentMap>(8, 4, std::vector<float>(8 * 4 * 3, 1.0f), 1.0f, 0.0f);
  frame.camera = test::lookAt(Vec3(0, 0, 2.5f), Vec3::Zero(), 20.0f);  // every pixel sees the ball
  frame.settings = test::smallSettings(16, 32, 20);
  frame.settings.lightPaths.addAll();
  const Film film = renderFrame(frame);
  test::expectMean(filmOfPass(film, LightPath::DiffuseDirect), albedo, 1e-4);
  for (const LightPath pass : allLightPaths())
    if (pass != LightPath::DiffuseDirect) {
      for (const float v : passLayer(film, pass).data) ASSERT_EQ(v, 0.0f) << lightPathName(pass);
    }
}

// The directional albedo of a lobe kind, integral of f_k(wo, wi) cos(wi) over the hemisphere
// (midpoint rule in cos(theta) and phi).
double lobeAlbedo(const Bsdf& bsdf, const Vec3& wo, Color BsdfLobes::*kind) {
  constexpr int kCos = 1500, kPhi = 512;
  double sum = 0.0;
  for (int i = 0; i < kCos; ++i) {
    const double mu = (i + 0.5) / kCos, sinTheta = std::sqrt(1.0 - mu * mu);
    for (int j = 0; j < kPhi; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j + 0.5) / kPhi;
      const Vec3 wi(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(mu));
      sum += double((bsdf.evalLobes(wo, wi).*kind)[1]) * mu;
    }
  }
  return sum * (2.0 * std::numbers::pi) / (double(kCos) * kPhi);
}

TEST(LightPaths, ASkinBallsPassesAreItsLobesAlbedos) {
  // A narrow view of a skin ball's pole in a furnace: wo is within 6 degrees of the normal, the
  // ball is convex, so specular_direct is the specular lobes' albedo and diffuse_direct the base's.
  SkinParams skin;
  skin.albedo = Color::Constant(0.5f);
  Frame frame;
  frame.materials.push_back(Material{"skin", skin, Color::Zero()});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 1.0f, 0});
  frame.environment = std::make_shared<EnvironmentMap>(8, 4, std::vector<float>(8 * 4 * 3, 1.0f), 1.0f, 0.0f);
  frame.camera = test::lookAt(Vec3(0, 0, 4.0f), Vec3::Zero(), 3.0f);
  frame.settings = test::smallSettings(12, 256, 20);
  frame.settings.lightPaths.addAll();
  const Film film = renderFrame(frame);
  const SkinBsdf bsdf(skin);
  for (const auto& [pass, kind] : {std::pair{LightPath::SpecularDirect, &BsdfLobes::glossy},
                                   std::pair{LightPath::DiffuseDirect, &BsdfLobes::diffuse}}) {
    const double atPole = lobeAlbedo(bsdf, Vec3(0, 0, 1), kind);
    const double atEdge = lobeAlbedo(bsdf, Vec3(std::sin(0.1f), 0.0f, std::cos(0.1f)), kind);
    const test::MeanEstimate e = test::channelMean(filmOfPass(film, pass), 1);
    std::printf("[ light paths ] %s %.5f +- %.5f, lobe albedo %.5f..%.5f\n", lightPathName(pass).c_str(), e.mean,
                e.standardError, std::min(atPole, atEdge), std::max(atPole, atEdge));
    EXPECT_GT(e.mean, std::min(atPole, atEdge) - 5.0 * e.standardError - 1e-4) << lightPathName(pass);
    EXPECT_LT(e.mean, std::max(atPole, atEdge) + 5.0 * e.standardError + 1e-4) << lightPathName(pass);
  }
  EXPECT_EQ(layerMean(passLayer(film, LightPath::SpecularIndirect), 1), 0.0);
  EXPECT_EQ(layerMean(passLayer(film, LightPath::Subsurface), 1), 0.0);
}

TEST(LightPaths, LightThroughSubsurfaceSkinIsSubsurface) {
  Frame frame = everyKindOfLight();
  frame.spheres.resize(1);  // the skin ball alone on the floor
  const Film film = renderFrame(frame);
  EXPECT_LT(worstRecombination(film), 1e-5);
  // The ball's centre pixel: its base is the walk below, so no diffuse pass there.
  const FilmLayer& diffuse = passLayer(film, LightPath::DiffuseDirect);
  const FilmLayer& subsurface = passLayer(film, LightPath::Subsurface);
  const Vec3 centre = Vec3(-0.3f, 0.35f, 0);
  int ballPixels = 0;
  for (int y = 0; y < film.height; ++y)
    for (int x = 0; x < film.width; ++x) {
      // Pixels whose camera ray meets the ball's middle (within half its radius of the centre line).
      const Ray ray = CameraRays(frame.camera, film.width, film.height).generate(x + 0.5f, y + 0.5f, Vec2(0.5f, 0.5f), 0.0f);
      const Vec3 toCentre = centre - ray.origin;
      const float miss = (toCentre - toCentre.dot(ray.direction) * ray.direction).norm();
      if (miss > 0.17f) continue;
      ++ballPixels;
      const size_t p = film.pixelIndex(x, y);
      EXPECT_EQ(diffuse.data[3 * p], 0.0f) << "pixel " << x << ", " << y;
      EXPECT_GT(subsurface.data[3 * p], 0.0f) << "pixel " << x << ", " << y;
    }
  EXPECT_GT(ballPixels, 10);
}

TEST(LightPaths, TheLayersDoNotDependOnTheThreadsAndLeaveTheBeautyAsItWas) {
  Frame frame = everyKindOfLight();
  frame.settings.threads = 1;
  const Film one = renderFrame(frame);
  frame.settings.threads = 2;
  const Film two = renderFrame(frame);
  for (size_t l = 0; l < one.layers.size(); ++l) EXPECT_TRUE(test::bitwiseEqual(one.layers[l].data, two.layers[l].data));
  // One pass asked alone is the same layer.
  frame.settings.lightPaths = LightPathSet{};
  frame.settings.lightPaths.add(LightPath::SpecularDirect);
  const Film alone = renderFrame(frame);
  ASSERT_EQ(alone.layers.size(), 1u);
  EXPECT_TRUE(test::bitwiseEqual(alone.layers[0].data, passLayer(two, LightPath::SpecularDirect).data));
  frame.settings.lightPaths = LightPathSet{};
  const Film plain = renderFrame(frame);
  EXPECT_TRUE(plain.layers.empty());
  EXPECT_TRUE(test::bitwiseEqual(plain.rgba, two.rgba));
}

}  // namespace light_paths_test
}  // namespace lacrima
