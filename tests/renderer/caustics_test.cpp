// Caustics by manifold next-event estimation (Caustics::Mnee, mnee_direct_light.cpp): a water
// drop (radius 1 cm) over a white diffuse floor under a small sphere light straight above
// focuses the light into a bright spot in the middle of its shadow. MNEE must find it, and agree
// with brute-force path tracing (Caustics::Off, where only BSDF-sampled paths that happen to
// refract into the light see it) within a few standard errors. The camera sees about 1 mm of
// floor under the drop's centre (4 x 4 pixels), low and from the side, past the drop.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/renderer/environment.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace caustics_test {

constexpr float kAlbedo = 0.5f;
constexpr float kDropRadius = 0.01f;
constexpr float kLightRadius = 0.1f;
constexpr float kLightHeight = 1.0f;
// Drop centre heights. 1.5 cm (5 mm gap): the floor lies inside the drop's paraxial focal
// distance (1.98 radii from the centre for n = 1.337), a bright focused spot. 3 cm (2 cm gap):
// beyond it, where every floor point near the axis is reached by a single refracted path
// from each light point (MNEE finds one solution per seed, see docs/shot-format.md).
constexpr float kFocusHeight = 0.015f;
constexpr float kSingleSolutionHeight = 0.03f;

enum class DropShape { Sphere, Mesh };

struct DropScene {
  float dropHeight = kSingleSolutionHeight;
  DropShape shape = DropShape::Sphere;
  bool environment = false;  // a sky with a bright zenith cap instead of the sphere light
};

// A 64 x 32 latitude-longitude sky: the top row (5.6 degrees around the zenith) 200, the rest 0.1.
std::shared_ptr<const EnvironmentMap> zenithSky() {
  constexpr int kW = 64, kH = 32;
  std::vector<float> rgb(size_t(kW) * kH * 3, 0.1f);
  for (int i = 0; i < kW * 3; ++i) rgb[i] = 200.0f;
  return std::make_shared<EnvironmentMap>(kW, kH, std::move(rgb), 1.0f, 0.0f);
}

// maxDepth 3: floor, drop, drop, light. Longer paths (internal reflections) are BSDF-sampled
// alike in every mode and would only add noise to the comparison.
Frame dropOverFloor(const DropScene& scene, Caustics caustics, int spp, uint64_t seed, int size = 4) {
  Frame frame;
  frame.materials.push_back(Material{"floor", DiffuseParams{Color::Constant(kAlbedo)}, Color::Zero()});
  frame.materials.push_back(Material{"water", SmoothDielectricParams{kTearIor, Color::Ones()}, Color::Zero()});
  frame.meshes.push_back(test::largeFloor(0));
  const Vec3 center(0, scene.dropHeight, 0);
  if (scene.shape == DropShape::Sphere) frame.spheres.push_back(Sphere{center, kDropRadius, 1});
  else frame.meshes.push_back(MeshInstance{makeEllipsoid(center, Mat3::Identity() * kDropRadius, 48, 96), 1});
  if (scene.environment) frame.environment = zenithSky();
  else frame.lights.push_back(test::sphereLightGivingUnitFloor(kAlbedo, kLightRadius, kLightHeight));  // unshadowed floor: 1
  frame.camera = test::lookAt(Vec3(1.0f, 0.25f, 0.0f), Vec3::Zero(), 0.05f * float(size) / 4.0f);
  frame.settings = test::smallSettings(size, spp, 3);
  frame.settings.seed = seed;
  frame.settings.caustics = caustics;
  return frame;
}

double meanRadiance(const Film& film) {
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) sum += test::channelMean(film, c).mean;
  return sum / 3.0;
}

// Mean and standard error of the image mean over `runs` renders with independent seeds (the
// pixels themselves differ across the caustic, so they are not samples of one mean).
test::MeanEstimate overSeeds(const DropScene& scene, Caustics caustics, int spp, int runs) {
  std::vector<double> means;
  for (int run = 0; run < runs; ++run)
    means.push_back(meanRadiance(renderFrame(dropOverFloor(scene, caustics, spp, 1000 + run))));
  test::MeanEstimate e;
  e.count = means.size();
  for (double m : means) e.mean += m / double(runs);
  double variance = 0.0;
  for (double m : means) variance += (m - e.mean) * (m - e.mean) / double(runs - 1);
  e.standardError = std::sqrt(variance / double(runs));
  return e;
}

// MNEE against brute force, both means with standard errors over independent seeds. The
// check is also made sharp enough to catch a wrong geometry term: with a doubled (or dropped)
// term the MNEE part, nearly all of the light at the focus, would be off by 100% (or by a
// factor of ~10 at least), far outside the tolerance, which is asserted to stay below 20%.
void expectAgreement(const DropScene& scene, int mneeSpp, int bruteSpp, int runs) {
  const test::MeanEstimate mnee = overSeeds(scene, Caustics::Mnee, mneeSpp, runs);
  const test::MeanEstimate brute = overSeeds(scene, Caustics::Off, bruteSpp, runs);
  const double sigma = std::hypot(mnee.standardError, brute.standardError);
  EXPECT_NEAR(mnee.mean, brute.mean, 4.0 * sigma) << "MNEE " << mnee.mean << " +- " << mnee.standardError
                                                  << ", brute force " << brute.mean << " +- " << brute.standardError;
  EXPECT_LT(4.0 * sigma, 0.2 * brute.mean) << "too noisy to tell a wrong geometry term";
  // The straight shadow is far off: the comparison does see the caustic.
  const double straight = overSeeds(scene, Caustics::Straight, mneeSpp, 2).mean;
  std::printf("[ measure  ] MNEE %.4f +- %.4f, brute force %.4f +- %.4f, straight %.4f\n", mnee.mean,
              mnee.standardError, brute.mean, brute.standardError, straight);
  EXPECT_GT(std::abs(straight - brute.mean), 0.3 * brute.mean) << "straight " << straight;
}

TEST(Caustics, TheDropFocusesTheLightInItsShadow) {
  DropScene scene;
  scene.dropHeight = kFocusHeight;
  const double straight = overSeeds(scene, Caustics::Straight, 64, 2).mean;
  const test::MeanEstimate mnee = overSeeds(scene, Caustics::Mnee, 256, 4);
  EXPECT_LT(straight, 1.0) << "a dimmed shadow";  // unshadowed floor: 1
  // Brute force finds about 24 here; MNEE about a third of it, the paraxial refracted path
  // only (see docs/shot-format.md, "Caustics"): still several times the unshadowed floor.
  EXPECT_GT(mnee.mean, 4.0) << "a focused caustic, +- " << mnee.standardError;
  std::printf("[ measure  ] focus: MNEE %.3f +- %.3f, straight %.3f (unshadowed floor 1)\n", mnee.mean,
              mnee.standardError, straight);
}

TEST(Caustics, SphereDropAgreesWithBruteForcePathTracing) {
  expectAgreement(DropScene{}, 256, 16384, 6);
}

// The same drop as a triangle mesh with interpolated normals: MNEE's vertices move over the
// triangles (re-projection by ray casting) and the normal's derivatives come from the vertex normals.
TEST(Caustics, MeshDropAgreesWithBruteForcePathTracing) {
  DropScene scene;
  scene.shape = DropShape::Mesh;
  expectAgreement(scene, 256, 16384, 6);
}

// The end of the chain is a direction (the sky), the geometry term per unit solid angle.
TEST(Caustics, EnvironmentCausticAgreesWithBruteForcePathTracing) {
  DropScene scene;
  scene.environment = true;
  expectAgreement(scene, 256, 16384, 6);
}

// A drop sunk into the floor (centre 4 mm above it): the floor under the cap lies inside the
// water, so the light sample's seed crosses one interface, water -> air (eta = 1 / 1.337), and
// the radiance there carries the n^2 of the denser medium. The cap's focal length (about 4 cm)
// lies far below the floor: one refracted path per light point.
TEST(Caustics, SunkDropAgreesWithBruteForcePathTracing) {
  DropScene scene;
  scene.dropHeight = 0.004f;
  expectAgreement(scene, 256, 8192, 6);
}

TEST(Caustics, RendersTheSameWithAnyThreadCount) {
  DropScene scene;
  scene.dropHeight = kFocusHeight;
  Frame frame = dropOverFloor(scene, Caustics::Mnee, 8, 3, 16);
  test::expectThreadCountIndependent(frame);
}

}  // namespace caustics_test
}  // namespace lacrima
