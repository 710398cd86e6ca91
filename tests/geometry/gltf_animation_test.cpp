// glTF 2.0 animations (spec 3.11, Appendix C) through loadGltfAsset and the evaluation functions,
// on small GLB files written by the test: a one-triangle mesh with two morph targets on node 0
// ("face") and a mesh-less node 1 ("jaw") for translation / rotation / scale channels.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "geometry/glb_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"

namespace lacrima {
namespace gltf_animation_test {

using nlohmann::json;

constexpr int kFloat = 5126, kUnsignedByte = 5121, kShort = 5122;

class AnimatedFile {
 public:
  AnimatedFile() {
    const int positions = addAccessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
    const int open = addAccessor(std::vector<float>{0, 0, 1, 0, 0, 0, 0, 0, 0}, "VEC3");
    const int raise = addAccessor(std::vector<float>{0, 0, 0, 0, 0, 0, 0, 0.5f, 0}, "VEC3");
    gltf_["asset"] = {{"version", "2.0"}};
    gltf_["scene"] = 0;
    gltf_["scenes"] = {{{"nodes", {0, 1}}}};
    gltf_["nodes"] = {{{"name", "face"}, {"mesh", 0}}, {{"name", "jaw"}}};
    gltf_["meshes"] = {{{"name", "Face"},
                        {"extras", {{"targetNames", {"open", "raise"}}}},
                        {"primitives", {{{"attributes", {{"POSITION", positions}}},
                                         {"targets", {{{"POSITION", open}}, {{"POSITION", raise}}}}}}}}};
    gltf_["animations"] = {{{"name", "blink"}, {"channels", json::array()}, {"samplers", json::array()}}};
  }

  // Appends values as a new accessor (with its own bufferView) and returns its index.
  template <class T>
  int addAccessor(const std::vector<T>& values, const std::string& type, int componentType = kFloat,
                  bool normalized = false) {
    const size_t offset = test::appendValues(bin_, values);
    gltf_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
    const size_t components = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
    json accessor = {{"bufferView", gltf_["bufferViews"].size() - 1}, {"componentType", componentType},
                     {"count", values.size() / components}, {"type", type}};
    if (normalized) accessor["normalized"] = true;
    gltf_["accessors"].push_back(accessor);
    return int(gltf_["accessors"].size()) - 1;
  }

  // A sampler over float key times and an output accessor, and the channel that uses it.
  void addChannel(int node, const std::string& path, const std::vector<float>& times, int output,
                  const std::string& interpolation = "LINEAR") {
    json& animation = gltf_["animations"][0];
    animation["samplers"].push_back({{"input", addAccessor(times, "SCALAR")}, {"output", output},
                                     {"interpolation", interpolation}});
    animation["channels"].push_back({{"sampler", animation["samplers"].size() - 1},
                                     {"target", {{"node", node}, {"path", path}}}});
  }

  void addFloatChannel(int node, const std::string& path, const std::vector<float>& times, const std::vector<float>& values,
                       const std::string& type, const std::string& interpolation = "LINEAR") {
    addChannel(node, path, times, addAccessor(values, type), interpolation);
  }

  json& gltf() { return gltf_; }

  std::filesystem::path write(const std::string& name = "animated.glb") {
    json out = gltf_;
    while (bin_.size() % 4 != 0) bin_.push_back(0);
    out["buffers"] = {{{"byteLength", bin_.size()}}};
    const std::filesystem::path path = test::testOutputDir() / name;
    test::writeBytes(path, test::makeGlb(out, bin_));
    return path;
  }

  GltfAsset load() { return loadGltfAsset(write()); }

 private:
  json gltf_;
  std::vector<unsigned char> bin_;
};

void expectNear(const std::vector<float>& actual, const std::vector<float>& expected, float tolerance = 1e-6f) {
  ASSERT_EQ(actual.size(), expected.size());
  for (size_t i = 0; i < actual.size(); ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "component " << i;
}

// The InputError message must be exactly "<file>: <what>".
void expectLoadError(AnimatedFile& file, const std::string& what) {
  const std::filesystem::path path = file.write("invalid.glb");
  try {
    loadGltfAsset(path);
    ADD_FAILURE() << "loaded without error; expected: " << what;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": " + what);
  }
}

TEST(GltfAnimation, ReadsChannelsWithTheirNodesAndKeys) {
  AnimatedFile file;
  file.addFloatChannel(0, "weights", {0, 1}, {0, 0, 1, 0.5f}, "SCALAR");
  file.addFloatChannel(1, "translation", {0, 2.5f}, {0, 0, 0, 1, 2, 3}, "VEC3", "STEP");
  const GltfAsset asset = file.load();
  ASSERT_EQ(asset.animations.size(), 1u);
  const GltfAnimation& blink = asset.animations[0];
  EXPECT_EQ(blink.name, "blink");
  ASSERT_EQ(blink.channels.size(), 2u);
  const GltfAnimationChannel& weights = blink.channels[0];
  EXPECT_EQ(weights.node, 0);
  EXPECT_EQ(weights.nodeName, "face");
  EXPECT_EQ(weights.path, GltfAnimationPath::Weights);
  EXPECT_EQ(weights.interpolation, GltfInterpolation::Linear);
  EXPECT_EQ(weights.valueSize, 2u);
  EXPECT_EQ(weights.times, (std::vector<float>{0, 1}));
  EXPECT_EQ(weights.values, (std::vector<float>{0, 0, 1, 0.5f}));
  EXPECT_EQ(blink.channels[1].nodeName, "jaw");
  EXPECT_EQ(blink.channels[1].interpolation, GltfInterpolation::Step);
  EXPECT_FLOAT_EQ(blink.duration(), 2.5f);
}

TEST(GltfAnimation, LinearWeightsHitTheKeysAndInterpolateHalfway) {
  AnimatedFile file;
  file.addFloatChannel(0, "weights", {0, 1}, {0, 0, 1, 0.5f}, "SCALAR");
  const GltfAnimation blink = file.load().animations.at(0);
  expectNear(evaluateMorphWeights(blink, 0, 0.0, 2), {0, 0});
  expectNear(evaluateMorphWeights(blink, 0, 1.0, 2), {1, 0.5f});
  expectNear(evaluateMorphWeights(blink, 0, 0.5, 2), {0.5f, 0.25f});
}

TEST(GltfAnimation, StepWeightsHoldUntilTheNextKey) {
  AnimatedFile file;
  file.addFloatChannel(0, "weights", {0, 1, 2}, {0, 0, 1, 1, 0.2f, 0.2f}, "SCALAR", "STEP");
  const GltfAnimation blink = file.load().animations.at(0);
  expectNear(evaluateMorphWeights(blink, 0, 0.999, 2), {0, 0});
  expectNear(evaluateMorphWeights(blink, 0, 1.0, 2), {1, 1});
  expectNear(evaluateMorphWeights(blink, 0, 1.5, 2), {1, 1});
  expectNear(evaluateMorphWeights(blink, 0, 2.0, 2), {0.2f, 0.2f});
}

TEST(GltfAnimation, CubicSplineWeightsFollowTheHermiteOfAppendixC) {
  AnimatedFile file;
  // Per key: in-tangent, value, out-tangent, each two weights.
  file.addFloatChannel(0, "weights", {0, 2},
                       {0, 0, /**/ 0, 1, /**/ 1, 0,  // key 0 at 0 s
                        0.5f, 0, /**/ 1, 1, /**/ 0, 0},  // key 1 at 2 s
                       "SCALAR", "CUBICSPLINE");
  const GltfAnimation blink = file.load().animations.at(0);
  expectNear(evaluateMorphWeights(blink, 0, 0.0, 2), {0, 1});
  expectNear(evaluateMorphWeights(blink, 0, 2.0, 2), {1, 1});
  // t = 0.5 s: u = 0.25, key interval 2 s. Hermite basis h00 = 0.84375, h10 = 0.140625,
  // h01 = 0.15625, h11 = -0.046875. Weight 0: 0.84375 * 0 + 2 * 0.140625 * 1 + 0.15625 * 1
  // + 2 * (-0.046875) * 0.5 = 0.390625. Weight 1: 0.84375 + 0.15625 = 1 (zero tangents).
  expectNear(evaluateMorphWeights(blink, 0, 0.5, 2), {0.390625f, 1.0f});
}

TEST(GltfAnimation, NormalizedIntegerWeightsAndRotationsAreDecoded) {
  AnimatedFile file;
  file.addChannel(0, "weights", {0, 1}, file.addAccessor(std::vector<uint8_t>{0, 255, 255, 51}, "SCALAR", kUnsignedByte, true));
  file.addChannel(1, "rotation", {0, 1},
                  file.addAccessor(std::vector<int16_t>{0, 0, 0, 32767, 0, 0, 32767, 0}, "VEC4", kShort, true));
  const GltfAnimation blink = file.load().animations.at(0);
  expectNear(evaluateMorphWeights(blink, 0, 1.0, 2), {1.0f, 0.2f});
  const NodeTrs pose = evaluateNodeTransform(blink, 1, 1.0);
  EXPECT_NEAR(pose.rotation.angularDistance(Eigen::Quaternionf(0, 0, 0, 1)), 0.0f, 1e-6f);  // 180 deg about z
}

TEST(GltfAnimation, LinearRotationIsSlerpAndHalvesTheAngle) {
  const float s = std::sqrt(0.5f);
  for (const float sign : {1.0f, -1.0f}) {  // -q is the same rotation: slerp must take the short arc either way
    AnimatedFile file;
    file.addFloatChannel(1, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, sign * s, sign * s}, "VEC4");
    const GltfAnimation blink = file.load().animations.at(0);
    const NodeTrs half = evaluateNodeTransform(blink, 1, 0.5);
    const Eigen::Quaternionf expected(Eigen::AngleAxisf(kPi / 4, Vec3::UnitZ()));  // 90 deg / 2
    EXPECT_NEAR(half.rotation.norm(), 1.0f, 1e-6f);
    EXPECT_NEAR(half.rotation.angularDistance(expected), 0.0f, 1e-3f) << "sign " << sign;
    EXPECT_NEAR(half.rotation.angularDistance(Eigen::Quaternionf::Identity()), kPi / 4, 1e-5f);
    // A quarter of the way is a quarter of the angle: slerp moves at constant angular speed.
    EXPECT_NEAR(evaluateNodeTransform(blink, 1, 0.25).rotation.angularDistance(Eigen::Quaternionf::Identity()), kPi / 8,
                1e-5f);
  }
}

TEST(GltfAnimation, TranslationInterpolatesAndClampsOutsideTheKeys) {
  AnimatedFile file;
  file.addFloatChannel(1, "translation", {1, 3}, {0, 0, 0, 2, 4, 6}, "VEC3");
  const GltfAnimation blink = file.load().animations.at(0);
  NodeTrs rest;
  rest.translation = Vec3(9, 9, 9);
  rest.scale = Vec3(2, 2, 2);
  const NodeTrs middle = evaluateNodeTransform(blink, 1, 2.0, rest);
  EXPECT_LT((middle.translation - Vec3(1, 2, 3)).norm(), 1e-6f);
  EXPECT_EQ(middle.scale, Vec3(2, 2, 2));  // no scale channel: the rest pose's
  EXPECT_TRUE(middle.rotation.isApprox(Eigen::Quaternionf::Identity()));
  EXPECT_EQ(evaluateNodeTransform(blink, 1, 0.0, rest).translation, Vec3(0, 0, 0));    // before the first key: held
  EXPECT_EQ(evaluateNodeTransform(blink, 1, 100.0, rest).translation, Vec3(2, 4, 6));  // after the last key: held
  EXPECT_EQ(evaluateNodeTransform(blink, 0, 2.0, rest).translation, Vec3(9, 9, 9));    // another node: not animated
  EXPECT_LT((middle.matrix() * Vec3(1, 0, 0) - Vec3(3, 2, 3)).norm(), 1e-6f);          // T * R * S
}

TEST(GltfAnimation, ClampsWeightsAndCubicSplinesOutsideTheKeys) {
  AnimatedFile file;
  file.addFloatChannel(0, "weights", {0.5f, 1},
                       {9, 9, /**/ 0.25f, 0.5f, /**/ 9, 9,  // large tangents must not extrapolate
                        9, 9, /**/ 0.75f, 1.0f, /**/ 9, 9},
                       "SCALAR", "CUBICSPLINE");
  const GltfAnimation blink = file.load().animations.at(0);
  expectNear(evaluateMorphWeights(blink, 0, 0.0, 2), {0.25f, 0.5f});
  expectNear(evaluateMorphWeights(blink, 0, -3.0, 2), {0.25f, 0.5f});
  expectNear(evaluateMorphWeights(blink, 0, 7.0, 2), {0.75f, 1.0f});
}

TEST(GltfAnimation, EvaluationRejectsBadArguments) {
  AnimatedFile file;
  file.addFloatChannel(0, "weights", {0, 1}, {0, 0, 1, 1}, "SCALAR");
  const GltfAnimation blink = file.load().animations.at(0);
  EXPECT_THROW(evaluateMorphWeights(blink, 0, 0.5, 3), std::invalid_argument);
  EXPECT_THROW(evaluateMorphWeights(blink, 0, std::nan(""), 2), InputError);
  expectNear(evaluateMorphWeights(blink, 1, 0.5, 2), {0, 0});  // no weights channel for node 1: zeros
}

TEST(GltfAnimation, DescriptionListsAnimationsAndChannels) {
  AnimatedFile file;
  file.addFloatChannel(0, "weights", {0, 1.5f}, {0, 0, 1, 1}, "SCALAR");
  file.addFloatChannel(1, "rotation", {0.5f, 2}, {0, 0, 0, 1, 0, 0, 0, 1}, "VEC4", "STEP");
  const std::string text = describeGltfAsset(file.load());
  for (const char* expected : {"animations: 1\n", "0: blink, 2 channels, duration 2.000 s\n",
                               "face weights (2 targets): 2 keys LINEAR, 0.000..1.500 s\n",
                               "jaw rotation: 2 keys STEP, 0.500..2.000 s\n"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing '" << expected << "' in\n" << text;
}

// ---- invalid files: each names the file, animation and channel, and says what is wrong ----

TEST(GltfAnimationInvalid, NonIncreasingKeyTimes) {
  AnimatedFile file;
  file.addFloatChannel(0, "weights", {0, 1, 1}, {0, 0, 1, 1, 0, 0}, "SCALAR");
  expectLoadError(file, "animation 0 ('blink'), channel 0 (sampler 0) input: key times must be strictly increasing, "
                        "but key 2 at 1 s follows 1 s");
}

TEST(GltfAnimationInvalid, NegativeFirstKeyTime) {
  AnimatedFile file;
  file.addFloatChannel(1, "scale", {-0.5f, 1}, {1, 1, 1, 2, 2, 2}, "VEC3");
  expectLoadError(file, "animation 0 ('blink'), channel 0 (sampler 0) input: the first key time is -0.5 s; times must be >= 0");
}

TEST(GltfAnimationInvalid, WeightsOutputCountIsNotKeysTimesTargets) {
  AnimatedFile file;
  file.addFloatChannel(0, "weights", {0, 1}, {0, 0, 1}, "SCALAR");
  expectLoadError(file, "animation 0 ('blink'), channel 0 (sampler 0) output: accessor 3 has 3 elements, expected 4 "
                        "(2 keys x 2 morph targets)");
}

TEST(GltfAnimationInvalid, CubicSplineOutputCountIsNotThreePerKey) {
  AnimatedFile file;
  file.addFloatChannel(1, "translation", {0, 1}, {0, 0, 0, 1, 1, 1}, "VEC3", "CUBICSPLINE");
  expectLoadError(file, "animation 0 ('blink'), channel 0 (sampler 0) output: accessor 3 has 2 elements, expected 6 "
                        "(2 keys x 3 for CUBICSPLINE)");
}

TEST(GltfAnimationInvalid, CubicSplineWithOneKey) {
  AnimatedFile file;
  file.addFloatChannel(1, "translation", {0}, {0, 0, 0, 1, 1, 1, 0, 0, 0}, "VEC3", "CUBICSPLINE");
  expectLoadError(file, "animation 0 ('blink'), channel 0 (sampler 0) input: accessor 4 has 1 key times; CUBICSPLINE needs "
                        "at least 2");
}

TEST(GltfAnimationInvalid, TargetNodeOutOfRange) {
  AnimatedFile file;
  file.addFloatChannel(7, "translation", {0}, {0, 0, 0}, "VEC3");
  expectLoadError(file, "animation 0 ('blink'), channel 0: target node 7 does not exist (2 nodes)");
}

TEST(GltfAnimationInvalid, SamplerOutOfRange) {
  AnimatedFile file;
  file.addFloatChannel(1, "translation", {0}, {0, 0, 0}, "VEC3");
  file.gltf()["animations"][0]["channels"][0]["sampler"] = 3;
  expectLoadError(file, "animation 0 ('blink'), channel 0: sampler 3 does not exist (1 samplers)");
}

TEST(GltfAnimationInvalid, UnknownTargetPath) {
  AnimatedFile file;
  file.addFloatChannel(1, "color", {0}, {0, 0, 0}, "VEC3");
  expectLoadError(file, "animation 0 ('blink'), channel 0: unknown target path 'color' (expected translation, rotation, "
                        "scale or weights)");
}

TEST(GltfAnimationInvalid, UnknownInterpolation) {
  AnimatedFile file;
  file.addFloatChannel(1, "translation", {0}, {0, 0, 0}, "VEC3", "SMOOTH");
  expectLoadError(file, "animation 0 ('blink'), channel 0 (sampler 0): unknown interpolation 'SMOOTH' (expected LINEAR, "
                        "STEP or CUBICSPLINE)");
}

TEST(GltfAnimationInvalid, OutputAccessorOfTheWrongType) {
  AnimatedFile file;
  file.addFloatChannel(1, "translation", {0}, {0, 0}, "VEC2");
  expectLoadError(file, "animation 0 ('blink'), channel 0 (sampler 0) output: accessor 3 is VEC2, but a translation channel "
                        "needs VEC3");
}

TEST(GltfAnimationInvalid, NormalizedIntegersAreNotAllowedForTranslation) {
  AnimatedFile file;
  file.addChannel(1, "translation", {0}, file.addAccessor(std::vector<int16_t>{0, 0, 0, 0}, "VEC3", kShort, true));
  expectLoadError(file, "animation 0 ('blink'), channel 0 (sampler 0) output: accessor 3 has componentType 5122; "
                        "translation values must be FLOAT (5126)");
}

TEST(GltfAnimationInvalid, IntegerWeightsMustBeNormalized) {
  AnimatedFile file;
  file.addChannel(0, "weights", {0}, file.addAccessor(std::vector<uint8_t>{0, 1, 0, 0}, "SCALAR", kUnsignedByte, false));
  expectLoadError(file, "animation 0 ('blink'), channel 0 (sampler 0) output: accessor 3 has componentType 5121 without "
                        "normalized; weights values must be FLOAT or normalized (unsigned) byte or short");
}

TEST(GltfAnimationInvalid, KeyTimesMustBeFloat) {
  AnimatedFile file;
  file.addFloatChannel(1, "translation", {0}, {0, 0, 0}, "VEC3");
  const int times = file.addAccessor(std::vector<uint8_t>{0, 0, 0, 0}, "SCALAR", kUnsignedByte, true);
  file.gltf()["animations"][0]["samplers"][0]["input"] = times;
  expectLoadError(file, fmt::format("animation 0 ('blink'), channel 0 (sampler 0) input: accessor {} is SCALAR with "
                                    "componentType 5121; key times must be SCALAR FLOAT (5126)", times));
}

TEST(GltfAnimationInvalid, WeightsOfANodeWithoutMesh) {
  AnimatedFile file;
  file.addFloatChannel(1, "weights", {0}, {0}, "SCALAR");
  expectLoadError(file, "animation 0 ('blink'), channel 0: animates the weights of node 1 ('jaw'), which has no mesh");
}

TEST(GltfAnimationInvalid, TwoChannelsForOneTarget) {
  AnimatedFile file;
  file.addFloatChannel(1, "scale", {0}, {1, 1, 1}, "VEC3");
  file.addFloatChannel(1, "scale", {0}, {2, 2, 2}, "VEC3");
  expectLoadError(file, "animation 0 ('blink'), channel 1: node 1 ('jaw') scale is already animated by channel 0");
}

TEST(GltfAnimationInvalid, ZeroQuaternion) {
  AnimatedFile file;
  file.addFloatChannel(1, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, 0, 0}, "VEC4");
  expectLoadError(file, "animation 0 ('blink'), channel 0 (sampler 0) output: the rotation of key 1 is the zero quaternion");
}

}  // namespace gltf_animation_test
}  // namespace lacrima
