// glTF skins (spec 3.7.3): the loader bakes the skin's rest pose (ignoring the mesh node's
// transform), playback gives per-skin joint matrices and applyGltfSkin poses a skinned primitive
// (morph first, then skin). The GLB is described in gltf_skin_support.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/gltf_skin_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"

namespace lacrima {
namespace gltf_skin_test {

std::filesystem::path writeStrip(const test::SkinnedStripOptions& options, const std::string& name) {
  test::GltfBuilder b = test::skinnedStrip(options);
  const auto path = test::testOutputDir() / name;
  b.write(path);
  return path;
}

GltfAsset loadStrip(const test::SkinnedStripOptions& options = {}) { return loadGltfAsset(writeStrip(options, "skinned.glb")); }

void expectPositions(const std::vector<Vec3>& actual, const std::vector<Vec3>& expected, float tolerance = 1e-5f) {
  ASSERT_EQ(actual.size(), expected.size());
  for (size_t i = 0; i < actual.size(); ++i)
    EXPECT_LT((actual[i] - expected[i]).norm(), tolerance)
        << "vertex " << i << ": got " << actual[i].transpose() << ", expected " << expected[i].transpose();
}

const std::vector<Vec3> kRest = {Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(1, 2.5f, 0), Vec3(2, 2.5f, 0), Vec3(1, 4, 0), Vec3(2, 4, 0)};

TEST(GltfSkin, InfoListsTheSkinWithItsJoints) {
  const std::string info = describeGltfAsset(loadStrip());
  const std::string line = info.substr(info.find("skins: 1"));
  EXPECT_NE(line.find("0: legs, 2 joints ("), std::string::npos) << info;
  EXPECT_NE(line.find("), 1 primitives"), std::string::npos) << info;
}

TEST(GltfSkin, LoaderReadsTheSkinAndBakesTheRestPoseIgnoringTheMeshNode) {
  const GltfAsset asset = loadStrip();
  ASSERT_EQ(asset.skins.size(), 1u);
  const GltfSkin& skin = asset.skins[0];
  EXPECT_EQ(skin.name, "legs");
  EXPECT_EQ(skin.joints, (std::vector<int>{0, 1}));
  ASSERT_EQ(skin.inverseBindMatrices.size(), 2u);
  EXPECT_TRUE(skin.inverseBindMatrices[1].isApprox(Affine3(Eigen::Translation3f(0, -2, 0))));
  ASSERT_EQ(skin.restJointMatrices.size(), 2u);
  EXPECT_TRUE(skin.restJointMatrices[0].isApprox(Affine3(Eigen::Translation3f(1, 1, 0))));
  EXPECT_TRUE(skin.restJointMatrices[1].isApprox(Affine3(Eigen::Translation3f(1, 0, 0))));

  ASSERT_EQ(asset.primitives.size(), 1u);
  const GltfPrimitive& p = asset.primitives[0];
  EXPECT_EQ(p.skin, 0);
  EXPECT_EQ(p.node, 2);
  EXPECT_TRUE(p.nodeTransform.matrix().isIdentity());
  // S_rest(v) v, not the node's translation (5, 5, 5).
  expectPositions(p.mesh.positions, kRest, 1e-6f);
  ASSERT_EQ(p.skinWeights.size(), 6u);
  EXPECT_EQ(p.skinWeights[2], Vec4(0.5f, 0.5f, 0, 0)) << "weights are normalized to sum 1";
  EXPECT_EQ(p.skinJoints[4][0], 1);
  ASSERT_EQ(p.mesh.normals.size(), 6u);
  EXPECT_LT((p.mesh.normals[0] - Vec3(0, 0, 1)).norm(), 1e-6f);
  ASSERT_EQ(p.targets.size(), 1u);
  ASSERT_EQ(p.targets[0].vertices, (std::vector<uint32_t>{4}));
  EXPECT_EQ(p.targets[0].deltas[0], Vec3(1, 0, 0));
  EXPECT_TRUE(asset.warnings.empty()) << asset.warnings.front();
}

TEST(GltfSkin, RotatingTheChildJointBendsTheTipAndBlendsTheMiddleRow) {
  const GltfAsset asset = loadStrip();
  const GltfAnimationSample sample = sampleGltfAnimation(asset, asset.animations.at(0), 1.0);
  ASSERT_TRUE(sample.anySkinMoves);
  ASSERT_EQ(sample.skinJointMatrices.size(), 1u);
  ASSERT_EQ(sample.skinJointMatrices[0].size(), 2u);
  // The strip's node slides, but a skinned mesh does not follow its node.
  EXPECT_FALSE(sample.anyPrimitiveMoves);
  EXPECT_EQ(sample.primitiveMotion[0].matrix(), Affine3::Identity().matrix());

  // J_knee = T(1,2,0) Rz(90) T(0,-2,0), J_hip = T(1,1,0). By hand on the mesh-space vertices:
  // row 0 (hip) stays; row 1 = (J_hip v + J_knee v) / 2: (0,2,0) -> ((1,3,0) + (1,2,0)) / 2,
  // (1,2,0) -> ((2,3,0) + (1,3,0)) / 2; row 2 (knee): (0,4,0) -> (-1,2,0), (1,4,0) -> (-1,3,0).
  TriangleMesh mesh = asset.primitives[0].mesh;
  applyGltfSkin(asset, asset.primitives[0], sample.skinJointMatrices[0], mesh);
  expectPositions(mesh.positions,
                  {Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(1, 2.5f, 0), Vec3(1.5f, 3, 0), Vec3(-1, 2, 0), Vec3(-1, 3, 0)});
  EXPECT_EQ(mesh.positions[0], asset.primitives[0].mesh.positions[0]) << "fully root-weighted: in place";
  EXPECT_LT((mesh.normals[0] - Vec3(0, 0, 1)).norm(), 1e-5f);

  // At time 0 the joints are at rest: the samples give back the rest positions.
  const GltfAnimationSample start = sampleGltfAnimation(asset, asset.animations[0], 0.0);
  TriangleMesh still = asset.primitives[0].mesh;
  applyGltfSkin(asset, asset.primitives[0], start.skinJointMatrices.at(0), still);
  expectPositions(still.positions, kRest, 1e-6f);
}

TEST(GltfSkin, MorphTargetsApplyBeforeSkinning) {
  const GltfAsset asset = loadStrip();
  const GltfAnimationSample sample = sampleGltfAnimation(asset, asset.animations.at(1), 1.0);
  EXPECT_EQ(sample.weights, (std::vector<float>{1.0f}));
  TriangleMesh mesh = applyMorphTargets(asset.primitives[0], sample.weights);
  expectPositions({mesh.positions[4]}, {Vec3(2, 4, 0)});  // rest (1,4,0) + lift (1,0,0)
  applyGltfSkin(asset, asset.primitives[0], sample.skinJointMatrices.at(0), mesh);
  // Mesh space (0,4,0) + (1,0,0) = (1,4,0), then skinned by the knee: (-1,3,0). Skinning first
  // and adding the delta afterwards would give (-1,2,0) + (1,0,0) = (0,2,0).
  expectPositions({mesh.positions[4]}, {Vec3(-1, 3, 0)});
}

TEST(GltfSkin, AnimationWithoutJointChannelsLeavesTheSkinAlone) {
  test::SkinnedStripOptions o;
  o.withAnimation = false;
  test::GltfBuilder b = test::skinnedStrip(o);
  const int slide = b.addAnimation("slide");
  b.addChannel(slide, 2, "translation", {0, 1}, {5, 5, 5, 6, 6, 6}, "VEC3");
  const auto path = test::testOutputDir() / "skinned_slide.glb";
  b.write(path);
  const GltfAsset asset = loadGltfAsset(path);
  const GltfAnimationSample sample = sampleGltfAnimation(asset, asset.animations.at(0), 1.0);
  EXPECT_FALSE(sample.anySkinMoves);
  EXPECT_FALSE(sample.anyPrimitiveMoves);
  ASSERT_EQ(sample.skinJointMatrices.size(), 1u);
  EXPECT_TRUE(sample.skinJointMatrices[0].empty());
  TriangleMesh mesh = asset.primitives[0].mesh;
  EXPECT_THROW(applyGltfSkin(asset, asset.primitives[0], {}, mesh), std::invalid_argument) << "no joint matrices";
}

TEST(GltfSkin, NormalizedByteWeightsAndShortJointsAreRead) {
  test::GltfBuilder b = test::skinnedStrip();
  nlohmann::json& attributes = b.json()["meshes"][0]["primitives"][0]["attributes"];
  attributes["JOINTS_0"] = b.addAccessorOf(std::vector<uint16_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
                                           5123, "VEC4");
  attributes["WEIGHTS_0"] = b.addAccessorOf(
      std::vector<uint8_t>{255, 0, 0, 0, 255, 0, 0, 0, 100, 100, 0, 0, 128, 128, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0}, 5121, "VEC4",
      true);
  const auto path = test::testOutputDir() / "skin_bytes.glb";
  b.write(path);
  const GltfAsset asset = loadGltfAsset(path);
  const GltfPrimitive& p = asset.primitives.at(0);
  EXPECT_EQ(p.skinJoints[3][1], 1);
  EXPECT_NEAR(p.skinWeights[2][0], 0.5f, 1e-7f);
  EXPECT_NEAR(p.skinWeights[3][1], 0.5f, 1e-7f);
  expectPositions(p.mesh.positions, kRest, 1e-6f);
}

TEST(GltfSkin, MirroringRestSkinKeepsTheWindingAgreeingWithTheNormals) {
  test::SkinnedStripOptions o;
  o.mirrorX = true;
  const GltfAsset asset = loadStrip(o);
  const GltfPrimitive& p = asset.primitives.at(0);
  // x is mirrored before the translations: vertex 1 (1, 0, 0) -> (-1, 0, 0) + (1, 1, 0).
  expectPositions({p.mesh.positions[1]}, {Vec3(0, 1, 0)});
  // A mirror keeps the +z normal of the strip (covector), so the winding must be flipped back.
  EXPECT_LT((p.mesh.normals[0] - Vec3(0, 0, 1)).norm(), 1e-6f) << p.mesh.normals[0].transpose();
  EXPECT_EQ(p.mesh.indices[1], 3u);
  EXPECT_EQ(p.mesh.indices[2], 1u);
}

std::string loadError(const test::SkinnedStripOptions& options, const std::string& name) {
  const auto path = writeStrip(options, name);
  try {
    loadGltfAsset(path);
  } catch (const InputError& e) {
    const std::string message = e.what();
    const std::string prefix = path.string() + ": ";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
    return message.substr(prefix.size());
  }
  ADD_FAILURE() << name << " loaded without error";
  return "";
}

TEST(GltfSkin, InvalidSkinsGetExactMessages) {
  test::SkinnedStripOptions joint;
  joint.joints[17] = 2;  // vertex 4, second influence
  EXPECT_EQ(loadError(joint, "skin_joint.glb"),
            "primitive 0 of mesh 0 ('Strip') '' JOINTS_0: vertex 4 names joint 2, but skin 0 ('legs') has 2 joints");

  test::SkinnedStripOptions zero;
  std::fill(zero.weights.begin() + 12, zero.weights.begin() + 16, 0.0f);  // vertex 3
  EXPECT_EQ(loadError(zero, "skin_zero.glb"), "primitive 0 of mesh 0 ('Strip') '' WEIGHTS_0: vertex 3 has all weights zero");

  test::SkinnedStripOptions negative;
  negative.weights[1] = -0.5f;
  EXPECT_EQ(loadError(negative, "skin_negative.glb"),
            "primitive 0 of mesh 0 ('Strip') '' WEIGHTS_0: vertex 0 has a negative weight -0.5");

  test::SkinnedStripOptions count;
  count.inverseBindMatrices = 3;
  EXPECT_EQ(loadError(count, "skin_ibm.glb"), "skin 0 ('legs') inverseBindMatrices: accessor 5 has 3 matrices for 2 joints");
}

TEST(GltfSkin, SecondInfluenceSetIsWarnedAbout) {
  test::GltfBuilder b = test::skinnedStrip();
  nlohmann::json& attributes = b.json()["meshes"][0]["primitives"][0]["attributes"];
  attributes["JOINTS_1"] = attributes["JOINTS_0"];
  attributes["WEIGHTS_1"] = attributes["WEIGHTS_0"];
  const auto path = test::testOutputDir() / "skin_second_set.glb";
  b.write(path);
  const GltfAsset asset = loadGltfAsset(path);
  ASSERT_EQ(asset.warnings.size(), 1u);
  EXPECT_EQ(asset.warnings[0], "primitive 0 of mesh 0 ('Strip') '': JOINTS_1 / WEIGHTS_1 ignored; only the first four "
                               "joint influences (JOINTS_0 / WEIGHTS_0) are used");
}

}  // namespace gltf_skin_test
}  // namespace lacrima
