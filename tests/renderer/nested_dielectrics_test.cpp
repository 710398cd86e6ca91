// Nested dielectrics with priorities (Schmidt & Budge 2002; medium_stack.hpp, integrator.cpp):
// the stack rules on their own, then small scenes with exact or comparative answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/materials/fresnel.hpp"
#include "medium_stack.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace nested_dielectrics_test {

constexpr float kGlassIor = 1.5f;
constexpr float kWaterIor = 1.333f;
constexpr float kCorneaIor = 1.376f;

Material dielectric(const char* name, float ior, int priority) {
  return Material{name, SmoothDielectricParams{ior, Color::Ones(), priority}, Color::Zero()};
}

Material diffuse(const char* name, float albedo, float emission = 0.0f) {
  return Material{name, DiffuseParams{Color::Constant(albedo)}, Color::Constant(emission)};
}

// Mean over pixels and channels of |a - b|.
double meanAbsoluteDifference(const Film& a, const Film& b) {
  double sum = 0.0;
  for (size_t p = 0; p < a.rgba.size(); p += 4)
    for (int c = 0; c < 3; ++c) sum += std::abs(double(a.rgba[p + c]) - double(b.rgba[p + c]));
  return sum / double(a.rgba.size() / 4 * 3);
}

double meanValue(const Film& film) {
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) sum += test::channelMean(film, c).mean;
  return sum / 3.0;
}

// ---- the stack rules --------------------------------------------------------------------------

TEST(MediumStack, ASurfaceInsideAHigherPriorityMediumIsFalse) {
  MediumStack media;
  media.enter({7, 2});  // cornea
  EXPECT_TRUE(media.classify({3, 1}, true).isFalse);   // entering a tear drop inside the cornea
  EXPECT_TRUE(media.classify({3, 0}, true).isFalse);   // a plain (priority 0) surface too
  const InterfaceCrossing film = media.classify({3, 5}, true);  // a higher priority wins
  EXPECT_FALSE(film.isFalse);
  EXPECT_EQ(film.otherMaterial, 7);
}

TEST(MediumStack, LeavingUsesTheHighestPriorityMediumLeftBehind) {
  MediumStack media;
  media.enter({1, 1});  // water
  media.enter({2, 3});  // glass
  media.enter({4, 2});  // a drop inside the glass: never scatters while the glass is around
  const InterfaceCrossing glassOut = media.classify({2, 3}, false);
  EXPECT_FALSE(glassOut.isFalse);
  EXPECT_EQ(glassOut.otherMaterial, 4);  // the drop fills the overlap once the glass is left
  media.leave(2);
  ASSERT_EQ(media.size(), 2);
  EXPECT_EQ(media[0].materialId, 1u);
  EXPECT_EQ(media[1].materialId, 4u);
  const InterfaceCrossing dropOut = media.classify({4, 2}, false);
  EXPECT_EQ(dropOut.otherMaterial, 1);
}

TEST(MediumStack, OverlappingVolumesOfOneMaterialMerge) {
  MediumStack media;
  media.enter({5, 1});
  EXPECT_TRUE(media.classify({5, 1}, true).isFalse);  // a second drop of the same tear fluid
  media.enter({5, 1});
  EXPECT_TRUE(media.classify({5, 1}, false).isFalse);   // leaving one, still inside the other
  media.leave(5);
  EXPECT_FALSE(media.classify({5, 1}, false).isFalse);  // leaving the last one: air
}

TEST(MediumStack, PriorityZeroSurfacesFaceAirAmongPriorityZeroMedia) {
  MediumStack media;
  media.enter({1, 0});
  const InterfaceCrossing crossing = media.classify({2, 0}, true);
  EXPECT_FALSE(crossing.isFalse);
  EXPECT_EQ(crossing.otherMaterial, -1);
  EXPECT_FALSE(media.classify({1, 0}, true).isFalse);  // plain overlaps keep both surfaces
}

TEST(MediumStack, EnteringBeyondTheCapacityIsIgnoredAndLeavingAnUnknownMediumIsHarmless) {
  MediumStack media;
  for (int i = 0; i < MediumStack::kCapacity + 3; ++i) media.enter({uint32_t(i), i + 1});
  EXPECT_EQ(media.size(), MediumStack::kCapacity);
  EXPECT_EQ(media[MediumStack::kCapacity - 1].materialId, uint32_t(MediumStack::kCapacity - 1));
  media.leave(MediumStack::kCapacity + 1);  // never recorded
  EXPECT_EQ(media.size(), MediumStack::kCapacity);
}

// ---- the material side --------------------------------------------------------------------------

TEST(DielectricMedium, AnInterfaceAgainstAMediumUsesTheRatioOfIndices) {
  const MaterialParams rough = RoughDielectricParams{kCorneaIor, 0.3f, Color::Ones(), 2};
  const MaterialParams paired = againstMedium(rough, kTearIor);
  ASSERT_TRUE(std::holds_alternative<RoughDielectricParams>(paired));
  EXPECT_FLOAT_EQ(std::get<RoughDielectricParams>(paired).ior, kCorneaIor / kTearIor);
  EXPECT_EQ(std::get<RoughDielectricParams>(paired).roughness, 0.3f);
  EXPECT_EQ(dielectricMedium(rough)->priority, 2);
  EXPECT_FALSE(dielectricMedium(DiffuseParams{}).has_value());
  // Index matched: the rough model's half vector is undefined, the interface is a smooth pass-through.
  const MaterialParams matched = againstMedium(rough, kCorneaIor);
  ASSERT_TRUE(std::holds_alternative<SmoothDielectricParams>(matched));
  EXPECT_EQ(std::get<SmoothDielectricParams>(matched).ior, 1.0f);
}

// ---- scenes -----------------------------------------------------------------------------------

// A diffuse floor lit by a rectangle light, seen through a glass ball (radius 0.6) that holds an
// off-centre inner ball; transparent shadows on. innerPriority < 0 leaves the inner ball out.
Frame ballOverFloor(float innerIor, int outerPriority, int innerPriority) {
  Frame frame;
  frame.materials = {diffuse("floor", 0.6f), dielectric("outer", kGlassIor, outerPriority),
                     dielectric("inner", innerIor, std::max(innerPriority, 0))};
  frame.meshes.push_back(test::largeFloor(0));
  frame.spheres.push_back(Sphere{Vec3(0, 0.7f, 0), 0.6f, 1});
  if (innerPriority >= 0) frame.spheres.push_back(Sphere{Vec3(0.15f, 0.8f, 0.1f), 0.3f, 2});
  AreaLight light;
  light.center = Vec3(0.5f, 3, 0.3f);
  light.edgeU = Vec3(0, 0, 1);
  light.edgeV = Vec3(1, 0, 0);  // edgeU x edgeV = -y: faces the floor
  light.radiance = Color::Constant(4.0f);
  frame.lights.push_back(light);
  frame.uniformBackground = Color::Constant(0.2f);
  frame.camera = test::lookAt(Vec3(0, 1.4f, 3), Vec3(0, 0.5f, 0), 35.0f);
  frame.settings = test::smallSettings(24, 16, 8);
  return frame;
}

// Schmidt & Budge: a lower-priority volume entirely inside a higher-priority one does not exist,
// whatever its index; neither the camera paths nor the shadow rays may see it.
TEST(NestedDielectrics, AVolumeInsideAHigherPriorityOneIsNotRendered) {
  const Film without = renderFrame(ballOverFloor(2.0f, 2, -1));
  const Film hidden = renderFrame(ballOverFloor(2.0f, 2, 1));
  const Film plain = renderFrame(ballOverFloor(2.0f, 0, 0));  // no priorities: the inner ball shows
  const double scale = meanValue(without);
  EXPECT_LT(meanAbsoluteDifference(hidden, without), 1e-3 * scale);
  EXPECT_GT(meanAbsoluteDifference(plain, without), 0.02 * scale);
}

// Index matching: an inner ball of the outer ball's index (but higher priority, so its surfaces
// are real) bends nothing and reflects nothing; only the noise of the extra vertices differs.
TEST(NestedDielectrics, AnIndexMatchedInnerBallIsInvisible) {
  // Long paths: the inner ball's extra vertices must not be cut off by the depth limit.
  auto longPaths = [](Frame frame) {
    frame.settings.samplesPerPixel = 256;
    frame.settings.maxDepth = 64;
    return renderFrame(frame);
  };
  const Film without = longPaths(ballOverFloor(kGlassIor, 1, -1));
  const Film matched = longPaths(ballOverFloor(kGlassIor, 1, 2));
  const Film plain = longPaths(ballOverFloor(kGlassIor, 0, 0));  // against air the inner ball refracts
  const double scale = meanValue(without);
  const double matchedDifference = meanAbsoluteDifference(matched, without);
  const double plainDifference = meanAbsoluteDifference(plain, without);
  EXPECT_NEAR(meanValue(matched), scale, 0.005 * scale);
  EXPECT_GT(std::abs(meanValue(plain) - scale), 0.01 * scale);
  EXPECT_LT(matchedDifference, 0.5 * plainDifference) << "matched " << matchedDifference << " plain " << plainDifference;
}

// Camera in a large water body (priority 1) looking straight at a glass ball (priority 2) with a
// black core: what it sees is the ball's reflection of an emitter behind the camera, R E with
// R = F(0) of the pair 1.5 / 1.333 (0.35 %), not of glass against air (4 %).
TEST(NestedDielectrics, ReflectanceOfGlassInWaterUsesTheIndexPair) {
  Frame frame;
  frame.materials = {dielectric("water", kWaterIor, 1), dielectric("glass", kGlassIor, 2), diffuse("core", 0.0f),
                     diffuse("emitter", 0.0f, 1.0f)};
  frame.spheres.push_back(Sphere{Vec3::Zero(), 50.0f, 0});
  frame.spheres.push_back(Sphere{Vec3(0, 0, -3), 1.0f, 1});
  frame.spheres.push_back(Sphere{Vec3(0, 0, -3), 0.98f, 2});
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(0, 0, 1), Vec3(20, 0, 0), Vec3(0, 20, 0)), 3});
  frame.camera = test::lookAt(Vec3::Zero(), Vec3(0, 0, -3), 2.0f);
  frame.settings = test::smallSettings(16, 256, 8);
  const double expected = fresnelDielectric(1.0f, kGlassIor / kWaterIor);
  ASSERT_GT(std::abs(expected - fresnelDielectric(1.0f, kGlassIor)), 0.03);
  test::expectMean(renderFrame(frame), expected, 1e-4);
}

// Camera at the centre of a glass ball (priority 2, radius 0.5) inside a water ball (priority 1)
// inside which an emitting black sphere (radius 0.8, radiance 1) sits. Transmission into the
// water and the reflections back through the centre sum to L = (n_glass / n_water)^2 (the n^2 law
// of radiance, Veach 1997 §5.2, for the pair actually present; against air it would be 2.25).
// Also checks the media found around the camera.
TEST(NestedDielectrics, RadianceInsideGlassInWaterScalesWithTheIndexPairSquared) {
  Frame frame;
  frame.materials = {dielectric("water", kWaterIor, 1), dielectric("glass", kGlassIor, 2), diffuse("emitter", 0.0f, 1.0f)};
  frame.spheres.push_back(Sphere{Vec3::Zero(), 1.0f, 0});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 0.5f, 1});
  frame.spheres.push_back(Sphere{Vec3::Zero(), 0.8f, 2});
  frame.camera = test::lookAt(Vec3::Zero(), Vec3(0.3f, 0.2f, -1.0f), 40.0f);
  frame.settings = test::smallSettings(16, 32, 200);
  const double ratio = kGlassIor / kWaterIor;
  test::expectMean(renderFrame(frame), ratio * ratio, 1e-3);
}

// A tear drop (1.337, priority 1) half sunk into a cornea-like ball (1.376, priority 2, radius
// 10, centred at the origin), the drop centred on the cornea's surface at z = -10.
void addCorneaAndDrop(Frame& frame, int corneaPriority, int dropPriority) {
  frame.materials.push_back(dielectric("cornea", kCorneaIor, corneaPriority));
  frame.materials.push_back(dielectric("drop", kTearIor, dropPriority));
  frame.spheres.push_back(Sphere{Vec3::Zero(), 10.0f, uint32_t(frame.materials.size() - 2)});
  frame.spheres.push_back(Sphere{Vec3(0, 0, -10), 0.5f, uint32_t(frame.materials.size() - 1)});
}

// Inside the cornea, looking sideways through the sunk half of the drop at an emitting patch
// also inside the cornea: the drop's sunk half does not exist, the image is the one without a drop.
Frame throughTheSunkHalf(bool withDrop, int corneaPriority, int dropPriority) {
  Frame frame;
  frame.materials.push_back(diffuse("emitter", 0.0f, 1.0f));
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(-1.5f, 0, -9.7f), Vec3(0, 0, 0.3f), Vec3(0, 0.3f, 0)), 0});
  addCorneaAndDrop(frame, corneaPriority, dropPriority);
  if (!withDrop) frame.spheres.pop_back();
  frame.camera = test::lookAt(Vec3(1.5f, 0, -9.7f), Vec3(0, 0, -9.7f), 4.0f);
  frame.settings = test::smallSettings(16, 16, 8);
  return frame;
}

TEST(NestedDielectrics, TheDropsPartInsideTheCorneaIsNotRendered) {
  const Film without = renderFrame(throughTheSunkHalf(false, 2, 1));
  const Film hidden = renderFrame(throughTheSunkHalf(true, 2, 1));
  const Film plain = renderFrame(throughTheSunkHalf(true, 0, 0));
  const double scale = meanValue(without);
  ASSERT_GT(scale, 0.1);
  EXPECT_LT(meanAbsoluteDifference(hidden, without), 1e-3 * scale);
  EXPECT_GT(meanAbsoluteDifference(plain, without), 0.05 * scale);
  // The depth AOV sees the emitter, 3 m away, through the skipped surfaces.
  for (size_t p = 0; p < hidden.depth.size(); ++p) ASSERT_NEAR(hidden.depth[p], without.depth[p], 1e-4f) << "pixel " << p;
  EXPECT_NEAR(hidden.depth[0], 3.0f, 0.01f);
}

// From outside, straight at the drop's top: the cap reflects F(0) of tear against air, then the
// drop-cornea interface (the pair 1.376 / 1.337) a tiny F(0) more; a black core in the cornea
// absorbs the rest. Without priorities the drop's sunk half and the cornea would each reflect
// against air (about 0.045 in total).
TEST(NestedDielectrics, TheVisibleDropRefractsWithTheTearIndexAgainstAir) {
  Frame frame;
  frame.materials.push_back(diffuse("core", 0.0f));
  frame.materials.push_back(diffuse("emitter", 0.0f, 1.0f));
  frame.spheres.push_back(Sphere{Vec3::Zero(), 9.0f, 0});
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(0, 0, -14), Vec3(20, 0, 0), Vec3(0, 20, 0)), 1});
  addCorneaAndDrop(frame, 2, 1);
  frame.camera = test::lookAt(Vec3(0, 0, -13), Vec3(0, 0, -10), 2.0f);
  frame.settings = test::smallSettings(16, 256, 8);
  const double cap = fresnelDielectric(1.0f, kTearIor);
  const double dropCornea = fresnelDielectric(1.0f, kCorneaIor / kTearIor);
  test::expectMean(renderFrame(frame), cap + (1.0 - cap) * (1.0 - cap) * dropCornea, 1e-4);
}

// Same seed, same pixels, whatever the number of threads (the stack draws no random numbers).
TEST(NestedDielectrics, RendersTheSameWithAnyThreadCount) {
  Frame frame = ballOverFloor(2.0f, 1, 2);
  frame.settings.threads = 1;
  const Film one = renderFrame(frame);
  frame.settings.threads = 3;
  EXPECT_EQ(renderFrame(frame).rgba, one.rgba);
}

// Shadow rays (transparent shadows): a floor point lit straight through a glass ball (priority
// 1, radius 0.5) holding a concentric water ball (radius 0.25). With the water at priority 2 the
// shadow ray crosses four real interfaces, two of them glass-water; at priority 0 the water
// ball does not exist and only the two glass-air interfaces dim the light. Direct light only.
Frame floorUnderNestedBalls(int waterPriority) {
  Frame frame;
  constexpr float kAlbedo = 0.5f, kLightRadius = 0.5f, kLightHeight = 50.0f;
  frame.materials = {diffuse("floor", kAlbedo), dielectric("glass", kGlassIor, 1), dielectric("water", kWaterIor, waterPriority)};
  frame.meshes.push_back(test::largeFloor(0));
  frame.spheres.push_back(Sphere{Vec3(0, 1, 0), 0.5f, 1});
  frame.spheres.push_back(Sphere{Vec3(0, 1, 0), 0.25f, 2});
  // The unshadowed floor's radiance is 1.
  frame.lights.push_back(test::sphereLightGivingUnitFloor(kAlbedo, kLightRadius, kLightHeight));
  frame.camera = test::lookAt(Vec3(2, 1, 0), Vec3::Zero(), 0.5f);
  frame.settings = test::smallSettings(12, 64, 1);
  frame.settings.caustics = Caustics::Straight;  // the straight shadow ray is what this checks
  return frame;
}

TEST(NestedDielectrics, ShadowRaysUseTheIndexPairAndSkipFalseInterfaces) {
  const double glassAir = 1.0 - fresnelDielectric(1.0f, kGlassIor);
  const double glassWater = 1.0 - fresnelDielectric(1.0f, kWaterIor / kGlassIor);
  test::expectMean(renderFrame(floorUnderNestedBalls(2)), glassAir * glassAir * glassWater * glassWater, 2e-3);
  test::expectMean(renderFrame(floorUnderNestedBalls(0)), glassAir * glassAir, 2e-3);
}

// Priority 0 is the plain model, bit for bit, even when another material (unused here) switches
// the nested machinery on: two overlapping priority-0 drops on a lit floor.
Frame overlappingPlainDrops(bool explicitZero, bool nestedMaterialPresent) {
  Frame frame;
  SmoothDielectricParams drop;
  drop.ior = kTearIor;
  if (explicitZero) drop.priority = 0;
  frame.materials = {diffuse("floor", 0.5f), Material{"drop", drop, Color::Zero()}};
  if (nestedMaterialPresent) frame.materials.push_back(dielectric("unused", kCorneaIor, 3));
  frame.meshes.push_back(test::largeFloor(0));
  frame.spheres.push_back(Sphere{Vec3(0, 0.3f, 0), 0.35f, 1});
  frame.spheres.push_back(Sphere{Vec3(0.3f, 0.35f, 0.1f), 0.3f, 1});
  AreaLight light;
  light.center = Vec3(0.5f, 3, 0.3f);
  light.edgeU = Vec3(0, 0, 1);
  light.edgeV = Vec3(1, 0, 0);
  light.radiance = Color::Constant(4.0f);
  frame.lights.push_back(light);
  frame.uniformBackground = Color::Constant(0.2f);
  frame.camera = test::lookAt(Vec3(0, 1.2f, 2), Vec3(0.1f, 0.3f, 0), 35.0f);
  frame.settings = test::smallSettings(20, 8, 8);
  return frame;
}

TEST(NestedDielectrics, PriorityZeroRendersBitwiseAsThePlainModel) {
  const Film implicitZero = renderFrame(overlappingPlainDrops(false, false));
  const Film explicitZero = renderFrame(overlappingPlainDrops(true, false));
  const Film nestedOn = renderFrame(overlappingPlainDrops(false, true));
  EXPECT_EQ(explicitZero.rgba, implicitZero.rgba);
  EXPECT_EQ(nestedOn.rgba, implicitZero.rgba);
  EXPECT_GT(meanValue(implicitZero), 0.05);
}

// More nested volumes than the stack holds (12 concentric balls, priority rising inwards):
// the innermost ones are not tracked (medium_stack.hpp), the render stays finite, camera
// inside or outside.
TEST(NestedDielectrics, MoreNestedVolumesThanTheStackHoldsDegradeGracefully) {
  for (const bool cameraInside : {false, true}) {
    SCOPED_TRACE(cameraInside);
    Frame frame;
    constexpr int kBalls = MediumStack::kCapacity + 4;
    for (int i = 0; i < kBalls; ++i) {
      frame.materials.push_back(dielectric("shell", 1.3f + 0.02f * float(i), i + 1));
      frame.spheres.push_back(Sphere{Vec3::Zero(), 1.0f - 0.07f * float(i), uint32_t(i)});
    }
    frame.uniformBackground = Color::Ones();
    const Vec3 eye = cameraInside ? Vec3(0.01f, 0.02f, 0.03f) : Vec3(0, 0, 3);
    frame.camera = test::lookAt(eye, eye + Vec3(0.1f, 0.05f, -1), cameraInside ? 60.0f : 30.0f);
    frame.settings = test::smallSettings(12, 4, 64);
    const Film film = renderFrame(frame);
    for (const float value : film.rgba) ASSERT_TRUE(std::isfinite(value));
    EXPECT_GT(meanValue(film), 0.1);
  }
}

}  // namespace nested_dielectrics_test
}  // namespace lacrima
