// Eyes for close-ups on the ICT face's right eyeball shell (M_ScleraRight): the limbus cut into a
// closed cornea and the sclera, the iris and pupil inside the chamber, following the eye's rotation.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include "geometry/glb_support.hpp"
#include "geometry/mesh_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/face/eye.hpp"
#include "lacrima/rig/face_rig.hpp"
#include "lacrima/io/gltf_asset.hpp"

namespace lacrima {
namespace eye_test {

class IctEye : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { asset_ = new GltfAsset(loadGltfAsset(test::faceAssetPath())); }
  static void TearDownTestSuite() { delete asset_; }

  static const GltfPrimitive& part(const std::string& name) {
    for (const GltfPrimitive& p : asset_->primitives)
      if (p.part == name) return p;
    throw std::runtime_error("no part " + name);
  }
  // The part with one blendshape at `weight` (all others 0).
  static TriangleMesh posed(const std::string& name, const std::string& target, float weight) {
    std::vector<float> weights(asset_->targetNames.size(), 0.0f);
    if (!target.empty()) weights[size_t(asset_->findTarget(target))] = weight;
    return applyMorphTargets(part(name), weights);
  }
  static const GltfAsset* asset_;
};
const GltfAsset* IctEye::asset_ = nullptr;

TEST_F(IctEye, ShellIsABallWithACornealBulgeLookingForward) {
  const EyeModel m = analyseEye(part("M_ScleraRight").mesh, EyeParams{}, "right eye");
  std::printf("[ info     ] centre (%.4f, %.4f, %.4f) radius %.2f mm, axis (%.3f, %.3f, %.3f), apex %.2f mm, "
              "limbus loop %zu vertices, iris root %.2f mm at %.2f mm, pupil margin at %.2f mm\n",
              m.center.x(), m.center.y(), m.center.z(), m.radius * 1e3f, m.axis.x(), m.axis.y(), m.axis.z(),
              m.apexHeight * 1e3f, m.limbusLoop.size(), m.irisRootRadius * 1e3f, m.irisRootHeight * 1e3f,
              m.pupilHeight * 1e3f);
  EXPECT_NEAR(m.radius, 0.015f, 0.001f);  // an adult eyeball is about 24 mm across
  EXPECT_GT(m.axis.z(), 0.95f);           // looking forward (+z in the ICT face)
  EXPECT_GT(m.apexHeight, m.radius + 1e-3f);  // the cornea stands out of the ball
  EXPECT_LT(m.apexHeight, m.radius + 4e-3f);
  EXPECT_GT(m.limbusLoop.size(), 8u);
}

TEST_F(IctEye, CorneaAndScleraPartitionTheShell) {
  const TriangleMesh& shell = part("M_ScleraRight").mesh;
  const EyeModel m = analyseEye(shell, EyeParams{}, "right eye");
  const TriangleMesh cut = cutAtLimbus(m, shell);
  std::set<uint32_t> all(m.corneaTriangles.begin(), m.corneaTriangles.end());
  for (uint32_t t : m.scleraTriangles) EXPECT_TRUE(all.insert(t).second) << "triangle " << t << " is in both";
  EXPECT_EQ(all.size(), cut.triangleCount());
  // Each crossed triangle became three covering it: more triangles, the same area.
  EXPECT_GT(cut.triangleCount(), shell.triangleCount());
  EXPECT_NEAR(test::meshArea(cut), test::meshArea(shell), 1e-5 * test::meshArea(shell));
  const EyeMeshes eye = buildEye(m, shell);
  EXPECT_EQ(eye.cornea.triangleCount(), m.corneaTriangles.size() + 3 * m.limbusLoop.size());  // cap, wall, back
  EXPECT_EQ(eye.sclera.triangleCount(), m.scleraTriangles.size());
  // Every cap vertex lies within the limbus, in front of the centre.
  for (uint32_t t : m.corneaTriangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 d = cut.positions[cut.indices[3 * t + k]] - m.center;
      EXPECT_LT((d - d.dot(m.axis) * m.axis).norm(), m.params.limbusRadius + 1e-6f);
      EXPECT_GT(d.dot(m.axis), 0.0f);
    }
}

TEST_F(IctEye, TheLimbusIsACircleNotTheShellsEdges) {
  // The cap's boundary runs on the limbus circle: each loop vertex at limbusRadius from the axis
  // (to the error of interpolating along one shell edge), where the shell's own edges strayed up
  // to 1.5 mm from it (a notched limbus, and an iris root following the notches).
  const TriangleMesh& shell = part("M_ScleraRight").mesh;
  const EyeModel m = analyseEye(shell, EyeParams{}, "right eye");
  const TriangleMesh cut = cutAtLimbus(m, shell);
  float worst = 0.0f;
  for (uint32_t v : m.limbusLoop) {
    const Vec3 d = cut.positions[v] - m.center;
    worst = std::max(worst, std::abs((d - d.dot(m.axis) * m.axis).norm() - m.params.limbusRadius));
  }
  std::printf("[ info     ] limbus loop %zu vertices, at most %.2f um off the circle\n", m.limbusLoop.size(), worst * 1e6f);
  EXPECT_GT(m.limbusLoop.size(), 24u);
  EXPECT_LT(worst, 50e-6f);
  // So the iris root, placed under the loop, is round too.
  for (const Vec2& root : m.irisRoot) EXPECT_NEAR(root.x(), m.irisRootRadius, 50e-6f);
}

TEST_F(IctEye, CorneaIsAClosedOutwardVolumeAndTheIrisLiesInsideIt) {
  const EyeModel m = analyseEye(part("M_ScleraRight").mesh, EyeParams{}, "right eye");
  const EyeMeshes eye = buildEye(m, part("M_ScleraRight").mesh);
  EXPECT_EQ(findMeshDefect(eye.cornea), "");
  EXPECT_EQ(findClosedMeshDefect(eye.cornea), "");
  const double volume = signedVolume(eye.cornea);
  std::printf("[ info     ] closed cornea volume (chamber down to its back) %.1f uL\n", volume * 1e9);
  EXPECT_GT(volume, 0.0);
  for (const TriangleMesh* mesh : {&eye.iris, &eye.pupil}) {
    EXPECT_EQ(findMeshDefect(*mesh), "");
    for (const Vec3& p : mesh->positions) {
      const Vec3 d = p - m.center;
      const float h = d.dot(m.axis), r = (d - h * m.axis).norm();
      EXPECT_LT(r, m.params.limbusRadius + 1e-3f);  // the root reaches under the limbus
      EXPECT_LT(h, m.apexHeight - 2e-3f);  // set back behind the corneal apex
      EXPECT_GT(h, 0.0f);
    }
    // Front faces towards the cornea.
    for (const Vec3& n : mesh->normals) EXPECT_GT(n.dot(m.axis), 0.5f);
  }
  // The pupil margin is irisDepth behind the apex; the pupil is a hole in the iris.
  float innermost = 1.0f;
  for (const Vec3& p : eye.iris.positions) {
    const Vec3 d = p - m.center;
    innermost = std::min(innermost, (d - d.dot(m.axis) * m.axis).norm());
  }
  EXPECT_NEAR(innermost, m.params.pupilRadius, 1e-5f);
}

// The iris's disc uvs (eye.hpp): the root on the circle of radius 0.5, the pupil margin on the
// circle of radius 0.5 kIrisUvPupilRadius, whatever the pupil's size (the sheet stretches), and
// the image's top towards the eye's up.
TEST_F(IctEye, TheIrisIsMappedOntoADiscWithThePupilAtAFixedRadius) {
  const auto radiusOf = [](const Vec2& uv) { return (uv - Vec2(0.5f, 0.5f)).norm(); };
  for (const float pupilRadius : {1.5e-3f, 3.0e-3f}) {
    EyeParams params;
    params.pupilRadius = pupilRadius;
    const EyeModel m = analyseEye(part("M_ScleraRight").mesh, params, "right eye");
    const EyeMeshes eye = buildEye(m, part("M_ScleraRight").mesh);
    ASSERT_EQ(eye.iris.uvs.size(), eye.iris.positions.size());
    EXPECT_EQ(findMeshDefect(eye.iris), "");
    float smallest = 1.0f, largest = 0.0f;
    for (size_t i = 0; i < eye.iris.positions.size(); ++i) {
      const Vec3 d = eye.iris.positions[i] - m.center;
      const float radial = (d - d.dot(m.axis) * m.axis).norm();
      const float uvRadius = radiusOf(eye.iris.uvs[i]);
      smallest = std::min(smallest, uvRadius);
      largest = std::max(largest, uvRadius);
      // The pupil margin's vertices (radial = pupilRadius) all lie on the inner circle.
      if (std::abs(radial - pupilRadius) < 1e-6f) {
        EXPECT_NEAR(uvRadius, 0.5f * kIrisUvPupilRadius, 1e-5f);
      }
      // Up on the eye is up on the image (v runs down it).
      const float up = d.dot(m.up);
      if (up > 0.5f * radial) {
        EXPECT_LT(eye.iris.uvs[i].y(), 0.5f);
      } else if (up < -0.5f * radial) {
        EXPECT_GT(eye.iris.uvs[i].y(), 0.5f);
      }
    }
    EXPECT_NEAR(smallest, 0.5f * kIrisUvPupilRadius, 1e-5f);
    EXPECT_NEAR(largest, 0.5f, 1e-5f);
  }
}

TEST_F(IctEye, FollowsTheEyeballAsTheRigTurnsIt) {
  const FaceRig rig(*asset_, ictFaceRigConfig(*asset_));
  size_t right = 0;
  while (rig.config().eyes[right].name != "right") ++right;
  size_t shell = 0;
  while (rig.primitive(shell).part != "M_ScleraRight") ++shell;
  FacePose pose;
  const TriangleMesh rest = rig.evaluatePrimitive(shell, pose);
  pose.eyeEulerDegrees.assign(rig.config().eyes.size(), Vec3::Zero());
  pose.eyeEulerDegrees[right] = Vec3(-5.0f, 15.0f, 0.0f);
  const TriangleMesh looking = rig.evaluatePrimitive(shell, pose);
  const EyeModel m = analyseEye(rest, EyeParams{}, "right eye");
  const Affine3 motion = eyeMotion(m, looking);
  const float degrees = Eigen::AngleAxisf(motion.linear()).angle() * 180.0f / kPi;
  std::printf("[ info     ] gaze pitch -5, yaw 15 degrees: the fitted eye motion turns %.2f degrees\n", degrees);
  EXPECT_NEAR(degrees, 15.8f, 0.3f);  // acos((cos 5 cos 15 + cos 5 + cos 15 - 1) / 2)
  for (size_t i = 0; i < looking.positions.size(); ++i)
    ASSERT_LT((motion * m.restPositions[i] - looking.positions[i]).norm(), 1e-5f) << "vertex " << i;
  const EyeMeshes atRest = buildEye(m, rest), turned = buildEye(m, looking);
  ASSERT_EQ(atRest.iris.positions.size(), turned.iris.positions.size());
  for (size_t i = 0; i < atRest.iris.positions.size(); ++i)
    EXPECT_LT((motion * atRest.iris.positions[i] - turned.iris.positions[i]).norm(), 1e-6f);
  // The cap is the posed shell's own triangles: it turned with them.
  EXPECT_EQ(findClosedMeshDefect(turned.cornea), "");
  EXPECT_GT((turned.cornea.positions[0] - atRest.cornea.positions[0]).norm(), 1e-3f);
}

// The exact message of analyseEye's InputError for these parameters ("" and a failure if none).
std::string eyeErrorOf(const TriangleMesh& shell, const EyeParams& params) {
  try {
    analyseEye(shell, params, "right eye");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

TEST_F(IctEye, RejectsALimbusWithoutCorneaAPupilLargerThanTheIrisAndAnIrisTooDeep) {
  const TriangleMesh& shell = part("M_ScleraRight").mesh;
  EyeParams tiny;
  tiny.limbusRadius = 1e-6f;
  EXPECT_EQ(eyeErrorOf(shell, tiny), "right eye: no triangle of the eyeball shell lies within the limbus (0.001 mm)");
  EyeParams bigPupil;
  bigPupil.pupilRadius = 0.0056f;
  EXPECT_EQ(eyeErrorOf(shell, bigPupil),
            "right eye: the pupil (5.6 mm) must be at least 0.5 mm smaller than the iris (6.02 mm)");
  EyeParams deep;
  deep.irisDepth = 0.0055f;
  EXPECT_EQ(eyeErrorOf(shell, deep), "right eye: the pupil lies behind the chamber's back; reduce irisDepth (5.5 mm)");
  EyeParams shallow;
  shallow.irisDepth = 0.0005f;
  shallow.pupilRadius = 0.0045f;  // a wide pupil margin right under the apex pokes out of the cornea
  EXPECT_EQ(eyeErrorOf(shell, shallow), "right eye: the iris would cut through the cornea; increase irisDepth (0.5 mm)");
}

}  // namespace eye_test
}  // namespace lacrima
