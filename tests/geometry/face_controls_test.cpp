// Animator controls: b(w), j(w) of Bao et al. 2019 eq. 2.
#include <gtest/gtest.h>

#include <functional>

#include "geometry/face_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/rig/face_controls.hpp"

namespace lacrima {
namespace face_controls_test {

const std::vector<std::string> kTargets = {"jawOpen", "mouthSmile_L", "mouthSmile_R", "eyeBlink_L"};
const std::vector<std::string> kEyes = {"left", "right"};

FaceControls makeControls() {
  return FaceControls(kTargets, kEyes,
                      {
                          {"smile", -1.0f, 1.0f, {{"mouthSmile_L", 1.0f}, {"mouthSmile_R", 1.0f}}, {}},
                          {"mouthOpen", 0.0f, 1.0f, {{"jawOpen", 0.6f}}, {{"jaw.rx", 20.0f}}},
                          {"smileLeft", 0.0f, 1.0f, {{"mouthSmile_L", 0.5f}}, {}},
                          {"look", -30.0f, 30.0f, {}, {{"eye.left.ry", 1.0f}, {"eye.right.ry", 1.0f}}},
                          {"nod", -2.0f, 2.0f, {}, {{"head.rx", 10.0f}, {"head.ty", -0.01f}}},
                      });
}

TEST(FaceControls, MapsControlsLinearlyToWeightsAndJoints) {
  const FacePose pose = makeControls().evaluate({{"mouthOpen", 0.5f}, {"look", 12.0f}, {"nod", 1.5f}});
  ASSERT_EQ(pose.blendshapeWeights.size(), kTargets.size());
  EXPECT_FLOAT_EQ(pose.blendshapeWeights[0], 0.3f);
  EXPECT_FLOAT_EQ(pose.blendshapeWeights[1], 0.0f);
  EXPECT_FLOAT_EQ(pose.jaw.eulerDegrees.x(), 10.0f);
  ASSERT_EQ(pose.eyeEulerDegrees.size(), 2u);
  EXPECT_FLOAT_EQ(pose.eyeEulerDegrees[0].y(), 12.0f);
  EXPECT_FLOAT_EQ(pose.eyeEulerDegrees[1].y(), 12.0f);
  EXPECT_FLOAT_EQ(pose.head.eulerDegrees.x(), 15.0f);
  EXPECT_FLOAT_EQ(pose.head.translation.y(), -0.015f);
  EXPECT_TRUE(pose.head.eulerDegrees.tail<2>().isZero(0.0f));
}

TEST(FaceControls, ClampsControlsToTheirRangeAndWeightsToZeroOne) {
  const FaceControls controls = makeControls();
  FacePose pose = controls.evaluate({{"mouthOpen", 4.0f}, {"look", -100.0f}});
  EXPECT_FLOAT_EQ(pose.blendshapeWeights[0], 0.6f);  // control clamped to 1, gain 0.6
  EXPECT_FLOAT_EQ(pose.jaw.eulerDegrees.x(), 20.0f);
  EXPECT_FLOAT_EQ(pose.eyeEulerDegrees[0].y(), -30.0f);
  pose = controls.evaluate({{"smile", -1.0f}});
  EXPECT_EQ(pose.blendshapeWeights[1], 0.0f);  // a negative weight is clamped to 0
  EXPECT_EQ(pose.blendshapeWeights[2], 0.0f);
}

TEST(FaceControls, SumsContributionsBeforeClampingTheWeight) {
  const FaceControls controls = makeControls();
  FacePose pose = controls.evaluate({{"smile", 0.3f}, {"smileLeft", 0.8f}});
  EXPECT_FLOAT_EQ(pose.blendshapeWeights[1], 0.3f + 0.4f);
  EXPECT_FLOAT_EQ(pose.blendshapeWeights[2], 0.3f);
  pose = controls.evaluate({{"smile", 0.9f}, {"smileLeft", 1.0f}});
  EXPECT_EQ(pose.blendshapeWeights[1], 1.0f);  // 1.4 clamped
  pose = controls.evaluate({{"smile", -0.2f}, {"smileLeft", 1.0f}});
  EXPECT_FLOAT_EQ(pose.blendshapeWeights[1], 0.3f);  // -0.2 + 0.5: the sum is clamped, not each term
}

TEST(FaceControls, ControlsNotGivenSitAtZeroClampedToTheirRange) {
  const FaceControls controls(kTargets, {}, {{"halfBlink", 0.5f, 1.0f, {{"eyeBlink_L", 1.0f}}, {}}});
  EXPECT_FLOAT_EQ(controls.evaluate({}).blendshapeWeights[3], 0.5f);
}

TEST(FaceControls, UnknownNamesAreInputErrorsWithTheClosestName) {
  const auto expectMessage = [](const std::function<void()>& f, const std::string& expected) {
    try {
      f();
      ADD_FAILURE() << "expected InputError containing " << expected;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  expectMessage([] { FaceControls(kTargets, kEyes, {{"c", 0, 1, {{"jawopen", 1}}, {}}}); }, "did you mean 'jawOpen'");
  expectMessage([] { FaceControls(kTargets, kEyes, {{"c", 0, 1, {{"mouthSmileL", 1}}, {}}}); }, "'mouthSmile_L'");
  expectMessage([] { FaceControls(kTargets, kEyes, {{"c", 0, 1, {}, {{"jaw.rotx", 1}}}}); }, "did you mean 'jaw.rx'");
  expectMessage([] { FaceControls(kTargets, kEyes, {{"c", 0, 1, {}, {{"eye.lft.ry", 1}}}}); }, "'eye.left.ry'");
  expectMessage([] { makeControls().evaluate({{"smiel", 1.0f}}); }, "unknown face control 'smiel' (did you mean 'smile'?)");
  EXPECT_THROW(FaceControls(kTargets, kEyes, {{"c", 1, 0, {}, {}}}), InputError);                 // min > max
  EXPECT_THROW(FaceControls(kTargets, kEyes, {{"c", 0, 1, {}, {}}, {"c", 0, 1, {}, {}}}), InputError);  // twice
  EXPECT_THROW(makeControls().evaluate({{"smile", NAN}}), InputError);
}

TEST(FaceControls, DriveTheRig) {
  // Bao et al. 2019 eq. 2 end to end: a control opens the synthetic jaw through both b and j.
  const GltfAsset asset = test::makeSyntheticFace();
  const FaceRig rig(asset, test::syntheticRigConfig());
  const FaceControls controls(rig, {{"open", 0, 1, {{"jawOpen", 1.0f}}, {{"jaw.rx", 5.0f}}},
                                    {"gaze", -40, 40, {}, {{"eye.left.ry", 1.0f}}}});
  const FacePose pose = controls.evaluate({{"open", 1.0f}, {"gaze", 10.0f}});
  EXPECT_EQ(pose.eyeEulerDegrees.size(), 1u);
  const TriangleMesh face = rig.evaluatePrimitive(0, pose);
  const TriangleMesh blendOnly = rig.evaluatePrimitive(0, {pose.blendshapeWeights, {}, {}, {}});
  EXPECT_NE(face.positions, blendOnly.positions);  // the jaw joint moved it further
  EXPECT_NE(rig.evaluatePrimitive(2, pose).positions, asset.primitives[2].mesh.positions);  // the iris turned
}

}  // namespace face_controls_test
}  // namespace lacrima
