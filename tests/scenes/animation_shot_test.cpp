// Animated shots: keyed values, the face rig and its controls, performance tracks, the camera
// shutter (motion blur) and shapes attached to the skin, checked through loadShot/buildFrame
// against the geometry library evaluated directly.
#include <gtest/gtest.h>

#include <fstream>

#include "lacrima/rig/face_rig.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace animation_shot_test {

using test::shotErrorOf;
using test::expectSingleError;
using test::firstLineOf;
using test::writeShot;

// Frames 1-5 of the face; `asset` adds members to the asset, `extra` top-level members.
std::string faceShot(const std::string& asset, const std::string& extra = "", const std::string& cameraExtra = "") {
  return test::ictFaceShot(extra, cameraExtra, asset);
}

size_t facePrimitive(const GltfAsset& asset) {
  for (size_t i = 0; i < asset.primitives.size(); ++i)
    if (asset.primitives[i].part == "M_Face") return i;
  ADD_FAILURE() << "no M_Face";
  return 0;
}

// The frame's mesh of the M_Face primitive (meshes are named "<asset>/<primitive name>").
const MeshInstance& faceMesh(const Frame& frame, const Shot& shot) {
  const GltfAsset& gltf = *shot.assets[0].gltf;
  const std::string name = "face/" + gltf.primitives[facePrimitive(gltf)].name;
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name == name) return m;
  ADD_FAILURE() << "no mesh " << name;
  return frame.meshes.front();
}

std::vector<float> weightsWith(const GltfAsset& gltf, std::initializer_list<std::pair<const char*, float>> values) {
  std::vector<float> w(gltf.targetNames.size(), 0.0f);
  for (const auto& [name, value] : values) w[size_t(gltf.findTarget(name))] = value;
  return w;
}

void expectPositionsNear(const std::vector<Vec3>& a, const std::vector<Vec3>& b, float tolerance) {
  ASSERT_EQ(a.size(), b.size());
  float worst = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (a[i] - b[i]).norm());
  EXPECT_LE(worst, tolerance);
}

TEST(AnimatedShot, KeyedBlendshapeIsInterpolatedBetweenKeys) {
  const Shot shot = loadShot(writeShot(
      "keyed.json", faceShot(R"("blendshapes": {"jawOpen": {"keys": [[1, 0], [5, 0.8]], "interpolation": "linear"}})")));
  const GltfAsset& gltf = *shot.assets[0].gltf;
  const TriangleMesh expected = applyMorphTargets(gltf.primitives[facePrimitive(gltf)], weightsWith(gltf, {{"jawOpen", 0.4f}}));
  expectPositionsNear(faceMesh(buildFrame(shot, 3), shot).mesh.positions, expected.positions, 1e-6f);
  // Frame 1 is the first key: weight 0, the neutral face bitwise.
  EXPECT_EQ(faceMesh(buildFrame(shot, 1), shot).mesh.positions, gltf.primitives[facePrimitive(gltf)].mesh.positions);
}

TEST(AnimatedShot, ControlsDriveBlendshapesWithGainsAndClampToTheirRange) {
  const Shot shot = loadShot(writeShot("controls.json", faceShot(R"("controls": {"sadness": {"range": [0, 1],
      "blendshapes": {"browInnerUp_L": 0.8, "mouthFrown_L": 0.5}, "value": {"keys": [[1, 0], [5, 2]], "interpolation": "linear"}}})")));
  const GltfAsset& gltf = *shot.assets[0].gltf;
  // Frame 5: the value 2 is clamped to the range's 1.
  const TriangleMesh expected = applyMorphTargets(gltf.primitives[facePrimitive(gltf)],
                                                  weightsWith(gltf, {{"browInnerUp_L", 0.8f}, {"mouthFrown_L", 0.5f}}));
  expectPositionsNear(faceMesh(buildFrame(shot, 5), shot).mesh.positions, expected.positions, 1e-6f);
}

TEST(AnimatedShot, RigJointsPoseTheFaceAsTheRigDoes) {
  const Shot shot = loadShot(writeShot("joints.json", faceShot(R"("rig": {"preset": "ict"},
      "joints": {"head.ry": {"keys": [[1, 0], [5, 12]], "interpolation": "linear"}, "jaw.rx": 4})")));
  const GltfAsset& gltf = *shot.assets[0].gltf;
  const FaceRig rig(gltf, ictFaceRigConfig(gltf));
  FacePose pose;
  pose.head.eulerDegrees = Vec3(0, 6, 0);
  pose.jaw.eulerDegrees = Vec3(4, 0, 0);
  const TriangleMesh expected = rig.evaluatePrimitive(facePrimitive(gltf), pose);
  expectPositionsNear(faceMesh(buildFrame(shot, 3), shot).mesh.positions, expected.positions, 1e-6f);
}

TEST(AnimatedShot, ARigWrittenOutInTheShotPosesLikeTheSameConfig) {
  const Shot shot = loadShot(writeShot("custom_rig.json", faceShot(R"("rig": {"headPivot": [0, -0.1, 0.05],
      "jawPivot": [0, -0.01, 0.02], "eyes": [{"name": "right", "fit": "M_ScleraRight", "parts": ["M_ScleraRight", "M_IrisRight"]}]},
      "joints": {"head.rz": 5, "eye.right.ry": 10})")));
  const GltfAsset& gltf = *shot.assets[0].gltf;
  FaceRigConfig config;
  config.headPivot = Vec3(0, -0.1f, 0.05f);
  config.jawPivot = Vec3(0, -0.01f, 0.02f);
  config.eyes = {{"right", "M_ScleraRight", {"M_ScleraRight", "M_IrisRight"}}};
  const FaceRig rig(gltf, config);
  FacePose pose;
  pose.head.eulerDegrees = Vec3(0, 0, 5);
  pose.eyeEulerDegrees = {Vec3(0, 10, 0)};
  const Frame frame = buildFrame(shot, 1);
  expectPositionsNear(faceMesh(frame, shot).mesh.positions, rig.evaluatePrimitive(facePrimitive(gltf), pose).positions,
                      1e-6f);
}

TEST(AnimatedShot, PerformanceTrackIsResampledToTheShotRate) {
  const auto dir = writeShot("placeholder.json", "").parent_path();
  std::ofstream(dir / "track.csv") << "time,jawOpen,eyeBlink_L\n0,0,1\n1,0.6,0\n";
  const Shot shot = loadShot(writeShot(
      "performance.json", faceShot(R"("performance": {"file": "track.csv", "startFrame": 1})")));
  const GltfAsset& gltf = *shot.assets[0].gltf;
  // Frame 4 plays 3/24 s into the track: jawOpen 0.6 * 3/24, eyeBlink_L 1 - 3/24.
  const TriangleMesh expected = applyMorphTargets(
      gltf.primitives[facePrimitive(gltf)], weightsWith(gltf, {{"jawOpen", 0.075f}, {"eyeBlink_L", 0.875f}}));
  expectPositionsNear(faceMesh(buildFrame(shot, 4), shot).mesh.positions, expected.positions, 1e-5f);
}

TEST(AnimatedShot, PerformanceTrackInJsonWithANameMap) {
  const auto dir = writeShot("placeholder.json", "").parent_path();
  std::ofstream(dir / "track.json") << R"({"fps": 12, "weights": {"JawOpen": [0, 0.6]}})";
  const Shot shot = loadShot(writeShot(
      "performance_json.json", faceShot(R"("performance": {"file": "track.json", "nameMap": {"JawOpen": "jawOpen"}})")));
  const GltfAsset& gltf = *shot.assets[0].gltf;
  // 12 fps track resampled to 24 fps: frame 2 is halfway between the two samples.
  const TriangleMesh expected =
      applyMorphTargets(gltf.primitives[facePrimitive(gltf)], weightsWith(gltf, {{"jawOpen", 0.3f}}));
  expectPositionsNear(faceMesh(buildFrame(shot, 2), shot).mesh.positions, expected.positions, 1e-5f);
}

TEST(AnimatedShot, APerformanceTracksHeadChannelsTurnTheHeadThroughTheRig) {
  // A tracker's output (lacrima track's performance.csv): weights and the rig's head channels.
  const auto dir = writeShot("placeholder.json", "").parent_path();
  std::ofstream(dir / "tracked.csv") << "frame,jawOpen,head.ry,head.tx\n1,0,0,0\n5,0.4,8,0.01\n";
  const Shot shot = loadShot(writeShot("tracked.json", faceShot(R"("rig": {"preset": "ict"},
      "performance": {"file": "tracked.csv", "fps": 24})")));
  const GltfAsset& gltf = *shot.assets[0].gltf;
  const FaceRig rig(gltf, ictFaceRigConfig(gltf));
  FacePose pose;
  pose.blendshapeWeights = weightsWith(gltf, {{"jawOpen", 0.2f}});
  pose.head.eulerDegrees = Vec3(0, 4, 0);
  pose.head.translation = Vec3(0.005f, 0, 0);
  // Frame 3 is halfway between the two samples.
  expectPositionsNear(faceMesh(buildFrame(shot, 3), shot).mesh.positions,
                      rig.evaluatePrimitive(facePrimitive(gltf), pose).positions, 1e-5f);
  // Without a rig the head channels are an error naming the column and what it needs.
  const std::string message = shotErrorOf(writeShot("tracked_no_rig.json", faceShot(R"("performance": {"file": "tracked.csv"})")));
  EXPECT_NE(message.find("the column 'head.ry' is a joint channel: it needs a 'rig' on the asset"), std::string::npos)
      << message;
}

TEST(AnimatedShot, APlayedTakeReplacesTheAssetsOwnAnimation) {
  // `lacrima render --performance face=take.csv`: the keyed weights and joints give way to the take.
  const auto dir = writeShot("placeholder.json", "").parent_path();
  std::ofstream(dir / "take.csv") << "frame,mouthSmile_L,head.ry\n1,0.2,0\n5,0.6,8\n";
  const auto shotFile = writeShot("keyed_then_played.json", faceShot(R"("rig": {"preset": "ict"},
      "blendshapes": {"jawOpen": {"keys": [[1, 0.2], [5, 0.9]]}},
      "joints": {"head.rx": 10})"));
  const Shot keyed = loadShot(shotFile);
  const FacePose own = assetFacePoseAt(keyed, 0, 3);
  const GltfAsset& gltf = *keyed.assets[0].gltf;
  const auto weightOf = [&](const FacePose& pose, const std::string& name) {
    return pose.blendshapeWeights[size_t(std::find(gltf.targetNames.begin(), gltf.targetNames.end(), name) -
                                         gltf.targetNames.begin())];
  };
  EXPECT_GT(weightOf(own, "jawOpen"), 0.2f);
  EXPECT_FLOAT_EQ(own.head.eulerDegrees.x(), 10.0f);

  // The take at the shot's 24 fps (a shot's own "performance" would default to 30).
  const Shot played = loadShot(shotFile, {PerformanceOverride{"face", dir / "take.csv", std::nullopt}});
  const FacePose take = assetFacePoseAt(played, 0, 3);  // halfway between the take's two samples
  EXPECT_FLOAT_EQ(weightOf(take, "jawOpen"), 0.0f);
  EXPECT_NEAR(weightOf(take, "mouthSmile_L"), 0.4f, 1e-6f);
  EXPECT_TRUE(take.head.eulerDegrees.isApprox(Vec3(0, 4, 0), 1e-6f)) << take.head.eulerDegrees.transpose();
  expectPositionsNear(faceMesh(buildFrame(played, 3), played).mesh.positions,
                      FaceRig(gltf, ictFaceRigConfig(gltf)).evaluatePrimitive(facePrimitive(gltf), take).positions, 1e-5f);

  // An asset the shot does not have is named, with the shot's assets.
  try {
    loadShot(shotFile, {PerformanceOverride{"nose", dir / "take.csv", std::nullopt}});
    ADD_FAILURE() << "no error for an unknown asset";
  } catch (const ShotError& e) {
    ASSERT_EQ(e.diagnostics().size(), 1u);
    EXPECT_EQ(e.diagnostics()[0].jsonPath, "/assets");
    EXPECT_NE(e.diagnostics()[0].message.find("no asset named 'nose'"), std::string::npos) << e.what();
    EXPECT_NE(e.diagnostics()[0].message.find("'face'"), std::string::npos) << e.what();
  }
}

TEST(AnimatedShot, ShutterGivesMovingGeometryItsPositionsAtClose) {
  const std::string drop =
      R"("shapes": [{"type": "sphere", "radius": 0.01, "material": "water", "center": {"keys": [[1, [0, 0, 0]], [5, [0, -0.4, 0]]], "interpolation": "linear"}}])";
  const Shot blurred = loadShot(writeShot(
      "shutter.json", faceShot(R"("blendshapes": {"jawOpen": {"keys": [[1, 0], [5, 1]], "interpolation": "linear"}})",
                               drop, R"(, "shutter": {"open": -0.25, "close": 0.25})")));
  const Frame frame = buildFrame(blurred, 3);
  ASSERT_EQ(frame.spheres.size(), 1u);
  EXPECT_TRUE(frame.spheres[0].center.isApprox(Vec3(0, -0.175f, 0), 1e-5f));
  ASSERT_TRUE(frame.spheres[0].centerAtClose.has_value());
  EXPECT_TRUE(frame.spheres[0].centerAtClose->isApprox(Vec3(0, -0.225f, 0), 1e-5f));
  EXPECT_TRUE(faceMesh(frame, blurred).moves());
  EXPECT_TRUE(frame.hasMotion());
}

TEST(AnimatedShot, StillShotWithAShutterHasNoMotion) {
  const Shot shot = loadShot(writeShot(
      "still_shutter.json", faceShot(R"("blendshapes": {"jawOpen": 0.3})", "", R"(, "shutter": {"open": 0, "close": 0.5})")));
  EXPECT_FALSE(buildFrame(shot, 2).hasMotion());
}

TEST(AnimatedShot, AttachedDropFollowsTheSkin) {
  const std::string drop =
      R"("shapes": [{"type": "sphere", "center": [-0.0345, -0.0018, 0.0995], "radius": 0.002, "material": "water", "attach": {"asset": "face", "part": "M_Face"}}])";
  const Shot shot = loadShot(writeShot(
      "attached.json",
      faceShot(R"("blendshapes": {"cheekRaiser_R": {"keys": [[1, 0], [5, 1]], "interpolation": "linear"}})", drop)));
  ASSERT_TRUE(shot.shapes[0].attachment.has_value());
  EXPECT_LT((shot.shapes[0].attachment->reference - Vec3(-0.0345f, -0.0018f, 0.0995f)).norm(), 2e-3f);
  // At the first frame the drop is where it was written; later it moves with the raised cheek.
  EXPECT_TRUE(buildFrame(shot, 1).spheres[0].center.isApprox(Vec3(-0.0345f, -0.0018f, 0.0995f), 1e-6f));
  const Vec3 moved = buildFrame(shot, 5).spheres[0].center;
  EXPECT_GT((moved - Vec3(-0.0345f, -0.0018f, 0.0995f)).norm(), 5e-4f) << "the cheek raiser should move the drop";
  EXPECT_GT(moved.y(), -0.0018f) << "a cheek raiser lifts the cheek";
}

TEST(AnimatedShot, KeyedCameraIsPlacedAtEveryFrameAndBlursWithAShutter) {
  const Shot shot = loadShot(writeShot("camera.json", faceShot("", "", "").replace(
      faceShot("", "", "").find(R"("position": [0, 0, 0.5])"), 23,
      R"("position": {"keys": [[1, [0, 0, 0.5]], [5, [0.4, 0, 0.5]]], "interpolation": "linear"}, "shutter": {"open": 0, "close": 1})")));
  const Frame frame = buildFrame(shot, 3);
  EXPECT_TRUE(frame.camera.cameraToWorld.translation().isApprox(Vec3(0.2f, 0, 0.5f), 1e-6f));
  ASSERT_TRUE(frame.camera.cameraToWorldAtClose.has_value());
  EXPECT_TRUE(frame.camera.cameraToWorldAtClose->translation().isApprox(Vec3(0.3f, 0, 0.5f), 1e-6f));
}

TEST(AnimatedShot, KeyedLightMovesAndDims) {
  const Shot shot = loadShot(writeShot("light.json", faceShot("", R"("lights": [{"type": "sphere", "radius": 0.1,
      "radiance": [2, 2, 2], "center": {"keys": [[1, [0, 1, 0]], [5, [0, 1, 4]]], "interpolation": "linear"},
      "intensity": {"keys": [[1, 1], [5, 0]], "interpolation": "linear"}}])")));
  const Frame frame = buildFrame(shot, 4);
  ASSERT_EQ(frame.lights.size(), 1u);
  EXPECT_TRUE(frame.lights[0].center.isApprox(Vec3(0, 1, 3), 1e-6f));
  EXPECT_NEAR(frame.lights[0].radiance[0], 0.5f, 1e-6f);
}


TEST(AnimatedShot, BadAnimationsGetExactMessages) {
  expectSingleError("keys_order.json", faceShot(R"("blendshapes": {"jawOpen": {"keys": [[1, 0], [1, 1]]}})"),
              "/assets/0/blendshapes/jawOpen/keys/1/0: key frames must increase: frame 1 is not after the previous "
              "key's frame 1");
  expectSingleError("interpolation.json", faceShot(R"("blendshapes": {"jawOpen": {"keys": [[1, 0]], "interpolation": "lineer"}})"),
              "/assets/0/blendshapes/jawOpen/interpolation: unknown interpolation 'lineer'; did you mean 'linear'?");
  expectSingleError("weight_range.json", faceShot(R"("blendshapes": {"jawOpen": {"keys": [[1, 0], [2, 1.5]]}})"),
              "/assets/0/blendshapes/jawOpen/keys/1/1: expected a number in [0, 1], found 1.5");
  expectSingleError("joints_without_rig.json", faceShot(R"("joints": {"head.ry": 3})"),
              "/assets/0/joints: joints need a 'rig' on the asset (for example \"rig\": {\"preset\": \"ict\"})");
  expectSingleError("joint_name.json", faceShot(R"("rig": {"preset": "ict"}, "joints": {"head.ryy": 3})"),
              "/assets/0/joints/head.ryy: unknown joint channel 'head.ryy'; did you mean 'head.ry'?");
  expectSingleError("rig_preset.json", faceShot(R"("rig": {"preset": "ictt"})"),
              "/assets/0/rig/preset: unknown rig preset 'ictt'; did you mean 'ict'? (this version knows the ICT "
              "face rig 'ict')");
  expectSingleError("rig_pivots.json", faceShot(R"("rig": {"jawPivot": [0, 0, 0]})"),
              "/assets/0/rig: missing required key 'headPivot' (a point: the head rotates about it (or give \"preset\"))");
  expectSingleError("rig_eye_part.json",
              faceShot(R"("rig": {"preset": "ict", "eyes": [{"name": "l", "fit": "M_ScleraLeft", "parts": ["M_IrisLft"]}]})"),
              "/assets/0/rig/eyes/0/parts/0: unknown part 'M_IrisLft'; did you mean 'M_IrisLeft'?");
  expectSingleError("control_shape.json", faceShot(R"("controls": {"sad": {"blendshapes": {"browInnerUp": 1}}})"),
              "/assets/0/controls/sad/blendshapes/browInnerUp: unknown blendshape 'browInnerUp'; did you mean "
              "'browInnerUp_L'?");
  expectSingleError("shutter.json", faceShot("", "", R"(, "shutter": {"open": 0.25, "close": -0.25})"),
              "/camera/shutter/close: the shutter must close after it opens: close -0.25 < open 0.25");
  expectSingleError("attach.json",
              faceShot("", R"("shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.01, "material": "water", "attach": {"asset": "face", "part": "M_Fcae"}}])"),
              "/shapes/0/attach/part: asset 'face' has no part 'M_Fcae'; did you mean 'M_Face'?");
}

TEST(AnimatedShot, MissingPerformanceFileIsReportedAtItsKey) {
  const auto path = writeShot("no_track.json", faceShot(R"("performance": {"file": "nope.csv"})"));
  std::vector<Diagnostic> diagnostics;
  shotErrorOf(path, &diagnostics);
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].jsonPath, "/assets/0/performance/file");
  EXPECT_NE(diagnostics[0].message.find("nope.csv"), std::string::npos) << diagnostics[0].message;
}

}  // namespace animation_shot_test
}  // namespace lacrima
