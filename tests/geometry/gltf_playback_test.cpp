// Playing glTF animations on a flattened asset (sampleGltfAnimation): node hierarchy and rest
// poses recorded by the loader, node motion per primitive relative to the rest pose, and weights
// channels mapped to asset-wide morph target indices. Small GLBs written by the test:
//   node 0 "root"  translation (1, 0, 0), child node 1, no mesh
//   node 1 "child" translation (0, 1, 0), mesh 0 "A" (targets open, raise)
//   node 2 "other" no transform,          mesh 1 "B" (targets raise, smile)
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/gltf_builder_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"

namespace lacrima {
namespace gltf_playback_test {

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

test::GltfBuilder hierarchy() {
  test::GltfBuilder b;
  const int a = b.addMesh("A", kTriangle, {"open", "raise"}, {{0, 0, 1, 0, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 0, 0, 1, 0}});
  const int m = b.addMesh("B", kTriangle, {"raise", "smile"}, {{0, 0, 0, 0, 1, 0, 0, 0, 0}, {1, 0, 0, 0, 0, 0, 0, 0, 0}});
  b.json()["scenes"] = {{{"nodes", {0, 2}}}};
  b.json()["nodes"] = {{{"name", "root"}, {"translation", {1, 0, 0}}, {"children", {1}}},
                       {{"name", "child"}, {"translation", {0, 1, 0}}, {"mesh", a}},
                       {{"name", "other"}, {"mesh", m}}};
  return b;
}

GltfAsset load(test::GltfBuilder& b) {
  const auto path = test::testOutputDir() / "playback.glb";
  b.write(path);
  return loadGltfAsset(path);
}

void expectPoint(const Vec3& actual, const Vec3& expected, float tolerance = 1e-5f) {
  EXPECT_LT((actual - expected).norm(), tolerance) << "got " << actual.transpose() << ", expected "
                                                   << expected.transpose();
}

TEST(GltfPlayback, LoaderRecordsNodesParentsRestPosesAndTargetSlots) {
  test::GltfBuilder b = hierarchy();
  const GltfAsset asset = load(b);
  ASSERT_EQ(asset.nodes.size(), 3u);
  EXPECT_EQ(asset.nodes[0].parent, -1);
  EXPECT_EQ(asset.nodes[1].parent, 0);
  EXPECT_EQ(asset.nodes[2].parent, -1);
  EXPECT_EQ(asset.nodes[1].name, "child");
  EXPECT_EQ(asset.nodes[1].mesh, 0);
  EXPECT_EQ(asset.nodes[0].trs.translation, Vec3(1, 0, 0));
  EXPECT_FALSE(asset.nodes[0].hasMatrix);
  EXPECT_TRUE(asset.nodes[1].matrix.isApprox(asset.nodes[1].trs.matrix()));
  EXPECT_EQ(asset.targetNames, (std::vector<std::string>{"open", "raise", "smile"}));
  EXPECT_EQ(asset.nodes[1].targetSlots, (std::vector<int>{0, 1}));
  EXPECT_EQ(asset.nodes[2].targetSlots, (std::vector<int>{1, 2}));
  EXPECT_TRUE(asset.nodes[0].targetSlots.empty());
  ASSERT_EQ(asset.primitives.size(), 2u);
  EXPECT_EQ(asset.primitives[0].node, 1);
  EXPECT_EQ(asset.primitives[1].node, 2);
}

TEST(GltfPlayback, RestPoseWithoutChannelsIsIdentityAndZeroWeights) {
  test::GltfBuilder b = hierarchy();
  b.addAnimation("empty");
  const GltfAsset asset = load(b);
  const GltfAnimationSample sample = sampleGltfAnimation(asset, asset.animations.at(0), 0.7);
  EXPECT_EQ(sample.weights, (std::vector<float>{0, 0, 0}));
  ASSERT_EQ(sample.primitiveMotion.size(), 2u);
  for (const Affine3& m : sample.primitiveMotion) EXPECT_EQ(m.matrix(), Affine3::Identity().matrix());
  EXPECT_FALSE(sample.anyPrimitiveMoves);
}

TEST(GltfPlayback, NodeTranslationMovesItsPrimitiveOnly) {
  test::GltfBuilder b = hierarchy();
  const int anim = b.addAnimation("slide");
  // The child goes from its rest translation (0, 1, 0) to (0, 1, 2) over 1 s.
  b.addChannel(anim, 1, "translation", {0, 1}, {0, 1, 0, 0, 1, 2}, "VEC3");
  const GltfAsset asset = load(b);
  const GltfAnimationSample sample = sampleGltfAnimation(asset, asset.animations.at(0), 0.25);
  EXPECT_TRUE(sample.anyPrimitiveMoves);
  // Flattened vertex 1 of mesh A is at (1, 0, 0) + (0, 1, 0) + (1, 0, 0) = (2, 1, 0); it moves by (0, 0, 0.5).
  expectPoint(asset.primitives[0].mesh.positions[1], Vec3(2, 1, 0));
  expectPoint(sample.primitiveMotion[0] * asset.primitives[0].mesh.positions[1], Vec3(2, 1, 0.5f));
  EXPECT_EQ(sample.primitiveMotion[1].matrix(), Affine3::Identity().matrix());
  // Held after the last key; at time 0 the rest pose.
  expectPoint(sampleGltfAnimation(asset, asset.animations[0], 9.0).primitiveMotion[0] * Vec3(2, 1, 0), Vec3(2, 1, 2));
  EXPECT_TRUE(sampleGltfAnimation(asset, asset.animations[0], 0.0).primitiveMotion[0].isApprox(Affine3::Identity()));
}

TEST(GltfPlayback, ChildFollowsItsRotatingParent) {
  test::GltfBuilder b = hierarchy();
  const int anim = b.addAnimation("turn");
  const float s = std::sqrt(0.5f);
  b.addChannel(anim, 0, "rotation", {0, 1}, {0, 0, 0, 1, 0, 0, s, s}, "VEC4");  // 0 -> 90 degrees about +Z
  const GltfAsset asset = load(b);
  const GltfAnimationSample sample = sampleGltfAnimation(asset, asset.animations.at(0), 1.0);
  // Animated child world = T(1,0,0) Rz(90) T(0,1,0): local (0,0,0) -> (0,0,0), local (1,0,0) -> (0,1,0),
  // local (0,1,0) -> (-1,0,0). The flattened (rest) vertices are local + (1, 1, 0).
  const auto& rest = asset.primitives[0].mesh.positions;
  expectPoint(sample.primitiveMotion[0] * rest[0], Vec3(0, 0, 0));
  expectPoint(sample.primitiveMotion[0] * rest[1], Vec3(0, 1, 0));
  expectPoint(sample.primitiveMotion[0] * rest[2], Vec3(-1, 0, 0));
  // Halfway: 45 degrees about the root's origin (1, 0, 0); the child's origin (1, 1, 0) swings to
  // (1 - sin 45, cos 45, 0).
  const GltfAnimationSample half = sampleGltfAnimation(asset, asset.animations[0], 0.5);
  expectPoint(half.primitiveMotion[0] * rest[0], Vec3(1 - s, s, 0));
  EXPECT_EQ(half.primitiveMotion[1].matrix(), Affine3::Identity().matrix()) << "node 2 is not under the root";
}

TEST(GltfPlayback, WeightsChannelsMapToAssetTargetIndicesAndTheLastChannelWins) {
  test::GltfBuilder b = hierarchy();
  const int anim = b.addAnimation("faces");
  b.addChannel(anim, 1, "weights", {0, 1}, {0, 0, 0.5f, 1.0f}, "SCALAR");   // A: open, raise
  b.addChannel(anim, 2, "weights", {0, 1}, {0, 0, 0.25f, 0.75f}, "SCALAR");  // B: raise, smile
  const GltfAsset asset = load(b);
  const GltfAnimationSample sample = sampleGltfAnimation(asset, asset.animations.at(0), 1.0);
  // open from A; raise from both, B's channel comes last; smile from B.
  EXPECT_EQ(sample.weights, (std::vector<float>{0.5f, 0.25f, 0.75f}));
  EXPECT_FALSE(sample.anyPrimitiveMoves);
  const GltfAnimationSample half = sampleGltfAnimation(asset, asset.animations[0], 0.5);
  EXPECT_NEAR(half.weights[0], 0.25f, 1e-6f);
  EXPECT_NEAR(half.weights[2], 0.375f, 1e-6f);
  EXPECT_THROW(sampleGltfAnimation(asset, asset.animations[0], std::nan("")), InputError);
}

}  // namespace gltf_playback_test
}  // namespace lacrima
