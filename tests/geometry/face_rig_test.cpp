// FaceRig: x(b, j) = T(j)(n + B b) (Bao et al. 2019, eq. 1) on a synthetic face and on the ICT face.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>
#include <random>

#include "geometry/face_support.hpp"
#include "geometry/glb_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/rig/face_rig.hpp"

namespace lacrima {
namespace face_rig_test {

void expectBitwiseEqual(const TriangleMesh& a, const TriangleMesh& b) {
  ASSERT_EQ(a.positions.size(), b.positions.size());
  EXPECT_EQ(0, std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(Vec3))) << a.name;
  ASSERT_EQ(a.normals.size(), b.normals.size());
  EXPECT_EQ(0, std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(Vec3))) << a.name;
  EXPECT_EQ(a.indices, b.indices);
}

float maxDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  float d = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
  return d;
}

class SyntheticRig : public ::testing::Test {
 protected:
  GltfAsset asset = test::makeSyntheticFace();
  FaceRig rig{asset, test::syntheticRigConfig()};
};

TEST_F(SyntheticRig, ZeroWeightsAndIdentityJointsGiveTheNeutralMeshBitwise) {
  FacePose pose;
  pose.blendshapeWeights = {0.0f, 0.0f};
  pose.eyeEulerDegrees = {Vec3::Zero()};
  const std::vector<TriangleMesh> meshes = rig.evaluate(pose);
  ASSERT_EQ(meshes.size(), asset.primitives.size());
  for (size_t i = 0; i < meshes.size(); ++i) expectBitwiseEqual(meshes[i], asset.primitives[i].mesh);
}

TEST_F(SyntheticRig, OneWeightGivesNeutralPlusThatDelta) {
  FacePose pose;
  pose.blendshapeWeights = {0.0f, 0.7f};
  const TriangleMesh face = rig.evaluatePrimitive(0, pose);
  std::vector<Vec3> expected = asset.primitives[0].mesh.positions;
  const SparseDelta& smile = asset.primitives[0].targets[1];
  for (size_t i = 0; i < smile.vertices.size(); ++i) expected[smile.vertices[i]] += 0.7f * smile.deltas[i];
  EXPECT_EQ(face.positions, expected);
  EXPECT_NE(face.normals, asset.primitives[0].mesh.normals);  // moved, so normals were recomputed
  // The eyeball is not moved by the smile: its normals stay the neutral ones bitwise.
  expectBitwiseEqual(rig.evaluatePrimitive(1, pose), asset.primitives[1].mesh);
}

TEST_F(SyntheticRig, BlendshapesAreLinear) {
  const std::vector<float> a = {0.3f, 0.2f}, b = {0.25f, 0.6f};
  const std::vector<Vec3>& n = asset.primitives[0].mesh.positions;
  const std::vector<Vec3> xa = rig.evaluatePrimitive(0, {a, {}, {}, {}}).positions;
  const std::vector<Vec3> xb = rig.evaluatePrimitive(0, {b, {}, {}, {}}).positions;
  const std::vector<Vec3> xab = rig.evaluatePrimitive(0, {{a[0] + b[0], a[1] + b[1]}, {}, {}, {}}).positions;
  float worst = 0.0f;
  for (size_t v = 0; v < n.size(); ++v) worst = std::max(worst, ((xab[v] - n[v]) - ((xa[v] - n[v]) + (xb[v] - n[v]))).norm());
  EXPECT_LT(worst, 1e-7f);  // float rounding of positions about 0.1 m
}

TEST_F(SyntheticRig, HeadRotationIsRigid) {
  FacePose pose;
  pose.head.eulerDegrees = Vec3(10.0f, -25.0f, 5.0f);
  pose.head.translation = Vec3(0.01f, 0.0f, -0.02f);
  pose.blendshapeWeights = {0.5f, 0.5f};
  const std::vector<TriangleMesh> posed = rig.evaluate(pose);
  const std::vector<TriangleMesh> unposed = rig.evaluate({pose.blendshapeWeights, {}, {}, {}});
  // Distances between vertices, across primitives too, are those of the unposed face.
  std::vector<Vec3> before, after;
  for (size_t i = 0; i < posed.size(); ++i) {
    before.insert(before.end(), unposed[i].positions.begin(), unposed[i].positions.end());
    after.insert(after.end(), posed[i].positions.begin(), posed[i].positions.end());
  }
  float worst = 0.0f;
  for (size_t i = 0; i < before.size(); i += 7)
    for (size_t j = i + 1; j < before.size(); j += 5)
      worst = std::max(worst, std::abs((after[i] - after[j]).norm() - (before[i] - before[j]).norm()));
  EXPECT_LT(worst, 1e-6f);
  EXPECT_GT(maxDistance(after, before), 0.01f);  // and it did move
  // The pivot itself only translates.
  const Affine3 head = jointTransform(pose.head, rig.config().headPivot);
  EXPECT_LT((head * rig.config().headPivot - rig.config().headPivot - pose.head.translation).norm(), 1e-7f);
}

TEST_F(SyntheticRig, GazeTurnsTheEyeballAboutItsFittedCentre) {
  FacePose pose;
  pose.eyeEulerDegrees = {Vec3(-10.0f, 20.0f, 0.0f)};
  const TriangleMesh sclera = rig.evaluatePrimitive(1, pose), iris = rig.evaluatePrimitive(2, pose);
  const Vec3 center = rig.eyeball(0).center;
  EXPECT_LT((fitSphere(sclera.positions).center - center).norm(), 1e-6f);
  EXPECT_GT(maxDistance(iris.positions, asset.primitives[2].mesh.positions), 0.003f);  // the iris turned
  for (size_t v = 0; v < iris.positions.size(); ++v)
    EXPECT_NEAR((iris.positions[v] - center).norm(), (asset.primitives[2].mesh.positions[v] - center).norm(), 1e-6f);
  // The face does not move with the gaze, bitwise.
  expectBitwiseEqual(rig.evaluatePrimitive(0, pose), asset.primitives[0].mesh);
}

TEST_F(SyntheticRig, EyeballSphereIsFittedOnTheSclera) {
  EXPECT_LT((rig.eyeball(0).center - test::kSyntheticEyeCenter).norm(), 1e-4f);  // tessellation error only
  EXPECT_NEAR(rig.eyeball(0).radius, test::kSyntheticEyeRadius, 2e-4f);
  EXPECT_EQ(rig.eyeOfPrimitive(0), -1);
  EXPECT_EQ(rig.eyeOfPrimitive(1), 0);
  EXPECT_EQ(rig.eyeOfPrimitive(2), 0);
}

TEST_F(SyntheticRig, JawWeightsAreTheNormalisedJawOpenDeltaMagnitude) {
  const std::vector<float>& w = rig.jawWeights(0);
  ASSERT_EQ(w.size(), asset.primitives[0].mesh.vertexCount());
  EXPECT_FLOAT_EQ(*std::max_element(w.begin(), w.end()), 1.0f);
  const SparseDelta& jaw = asset.primitives[0].targets[0];
  float largest = 0.0f;
  for (const Vec3& d : jaw.deltas) largest = std::max(largest, d.norm());
  for (size_t i = 0; i < jaw.vertices.size(); ++i) EXPECT_FLOAT_EQ(w[jaw.vertices[i]], jaw.deltas[i].norm() / largest);
  for (size_t v = 0; v < w.size(); ++v) {
    if (asset.primitives[0].mesh.positions[v].y() >= -0.02f) {
      EXPECT_EQ(w[v], 0.0f);
    }
  }
  EXPECT_TRUE(rig.jawWeights(1).empty());  // eyes never follow the jaw
}

TEST_F(SyntheticRig, JawRotationBlendsTheSkullAndJawTransformsByWeight) {
  FacePose pose;
  pose.jaw.eulerDegrees = Vec3(15.0f, 0.0f, 0.0f);
  const TriangleMesh face = rig.evaluatePrimitive(0, pose);
  const Affine3 jaw = jointTransform(pose.jaw, rig.config().jawPivot);
  const std::vector<Vec3>& n = asset.primitives[0].mesh.positions;
  for (size_t v = 0; v < n.size(); ++v) {
    const float w = rig.jawWeights(0)[v];
    const Vec3 expected = (1.0f - w) * n[v] + w * (jaw * n[v]);  // LBS (Bao et al. 2019), skull = identity
    EXPECT_LT((face.positions[v] - expected).norm(), 1e-6f) << v;
  }
  EXPECT_GT(maxDistance(face.positions, n), 0.01f);
}

TEST_F(SyntheticRig, UnknownPartsAndBadPosesAreInputErrors) {
  FaceRigConfig config = test::syntheticRigConfig();
  config.eyes[0].spherePart = "M_ScleraLft";
  try {
    FaceRig bad(asset, config);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'M_ScleraLeft'"), std::string::npos) << e.what();
  }
  config = test::syntheticRigConfig();
  config.jawWeightTarget = "jawopen";
  EXPECT_THROW(FaceRig(asset, config), InputError);
  EXPECT_THROW(rig.evaluate({{0.0f, NAN}, {}, {}, {}}), InputError);
  EXPECT_THROW(rig.evaluate({{0.0f, 0.0f, 0.0f}, {}, {}, {}}), InputError);  // more weights than targets
  EXPECT_THROW(rig.evaluate({{}, {}, {}, {Vec3::Zero(), Vec3::Zero()}}), InputError);  // one eye only
}

TEST_F(SyntheticRig, TargetsMustListTheirVerticesInAscendingOrder) {
  // The rig splits a target's vertices between threads by their indices, which it can only do when
  // they ascend (as glTF's sparse accessors must).
  GltfAsset unsorted = asset;
  SparseDelta& smile = unsorted.primitives[0].targets[1];
  ASSERT_GE(smile.vertices.size(), 2u);
  std::swap(smile.vertices[0], smile.vertices[1]);
  EXPECT_THROW(FaceRig(unsorted, test::syntheticRigConfig()), std::invalid_argument);
  smile.vertices[1] = smile.vertices[0];  // repeated
  EXPECT_THROW(FaceRig(unsorted, test::syntheticRigConfig()), std::invalid_argument);
}

TEST(LinearBlendSkinning, IdentityBonesLeavePositionsUnchanged) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<Vec3> positions(100);
  for (Vec3& p : positions) p = Vec3(u(rng), u(rng), u(rng));
  SkinWeights w{3, {}};
  for (size_t v = 0; v < positions.size(); ++v) {
    const float a = 0.5f + 0.5f * u(rng), b = (1.0f - a) * (0.5f + 0.5f * u(rng));
    w.weights.insert(w.weights.end(), {a, b, 1.0f - a - b});
  }
  std::vector<Vec3> skinned = positions;
  applyLinearBlendSkinning(skinned, {Affine3::Identity(), Affine3::Identity(), Affine3::Identity()}, w);
  EXPECT_LT(maxDistance(skinned, positions), 1e-6f);
}

TEST(LinearBlendSkinning, IsTheWeightedAverageOfTheBoneTransforms) {
  const Affine3 a = jointTransform({Vec3(30, 0, 0), Vec3(0, 1, 0)}, Vec3(0, 0, 1));
  const Affine3 b = jointTransform({Vec3(0, -45, 10), Vec3::Zero()}, Vec3(1, 0, 0));
  std::vector<Vec3> p = {Vec3(0.3f, -0.2f, 0.5f), Vec3(1, 2, 3)};
  const std::vector<Vec3> original = p;
  applyLinearBlendSkinning(p, {a, b}, SkinWeights{2, {0.25f, 0.75f, 1.0f, 0.0f}});
  EXPECT_LT((p[0] - (0.25f * (a * original[0]) + 0.75f * (b * original[0]))).norm(), 1e-6f);
  EXPECT_LT((p[1] - a * original[1]).norm(), 1e-6f);
  EXPECT_THROW(applyLinearBlendSkinning(p, {a}, SkinWeights{2, {0.25f, 0.75f, 1.0f, 0.0f}}), std::invalid_argument);
}

TEST(SphereFit, RecoversTheCentreAndRadiusOfANoisySyntheticSphere) {
  std::mt19937 rng(3);
  std::normal_distribution<float> g(0.0f, 1.0f);
  const Vec3 center(0.031f, 0.027f, 0.058f);
  const float radius = 0.0121f;
  std::vector<Vec3> points;
  for (int i = 0; i < 2000; ++i) {
    // Only the front cap (z > -0.3 r), as on a scanned eye: the fit must not need the whole sphere.
    Vec3 d(g(rng), g(rng), g(rng));
    d.normalize();
    if (d.z() < -0.3f) continue;
    points.push_back(center + d * (radius + 1e-5f * g(rng)));
  }
  const FittedSphere s = fitSphere(points);
  EXPECT_LT((s.center - center).norm(), 5e-6f);
  EXPECT_NEAR(s.radius, radius, 5e-6f);
}

TEST(SphereFit, RejectsTooFewOrCoplanarPoints) {
  EXPECT_THROW(fitSphere({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}), InputError);
  EXPECT_THROW(fitSphere({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 3, 0)}), InputError);
}

TEST(JawHinge, RecoversTheRotationOfARigidlyRotatedPart) {
  GltfPrimitive teeth = test::makeSyntheticPrimitive(
      "M_Teeth", makeEllipsoid(Vec3(0.0f, -0.05f, 0.06f), Mat3(Vec3(0.02f, 0.005f, 0.01f).asDiagonal()), 6, 12), 1);
  const Vec3 pivot(0.0f, -0.01f, -0.03f);
  const Affine3 open = jointTransform({Vec3(14.0f, 0, 0), Vec3::Zero()}, pivot);
  for (uint32_t v = 0; v < teeth.mesh.vertexCount(); ++v) {
    teeth.targets[0].vertices.push_back(v);
    teeth.targets[0].deltas.push_back(open * teeth.mesh.positions[v] - teeth.mesh.positions[v]);
  }
  const JawHinge hinge = estimateJawHinge(teeth, 0);
  EXPECT_NEAR(hinge.openingDegrees, 14.0f, 1e-3f);
  EXPECT_LT((hinge.pivot - pivot).norm(), 1e-5f);
  teeth.targets[0] = {};
  EXPECT_THROW(estimateJawHinge(teeth, 0), InputError);
}

// The committed ICT face, loaded once.
class IctFaceRig : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    asset_ = new GltfAsset(loadGltfAsset(test::faceAssetPath()));
    rig_ = new FaceRig(*asset_, ictFaceRigConfig(*asset_));
  }
  static void TearDownTestSuite() {
    delete rig_;
    delete asset_;
  }
  static GltfAsset* asset_;
  static FaceRig* rig_;
};
GltfAsset* IctFaceRig::asset_ = nullptr;
FaceRig* IctFaceRig::rig_ = nullptr;

TEST_F(IctFaceRig, NeutralPoseIsTheLoadedAssetBitwise) {
  const std::vector<TriangleMesh> meshes = rig_->evaluate(FacePose{std::vector<float>(57, 0.0f), {}, {}, {}});
  for (size_t i = 0; i < meshes.size(); ++i) expectBitwiseEqual(meshes[i], asset_->primitives[i].mesh);
}

TEST_F(IctFaceRig, FittedEyeballsAndJawHingeAreAnatomicallyPlausible) {
  for (size_t e = 0; e < 2; ++e) {
    const FittedSphere& s = rig_->eyeball(e);
    std::printf("[ info     ] %s eyeball centre (%.4f, %.4f, %.4f) m, radius %.2f mm\n",
                rig_->config().eyes[e].name.c_str(), s.center.x(), s.center.y(), s.center.z(), s.radius * 1000.0f);
    // The ICT scleras are about 30 mm across (bounds), larger than a real 24 mm eye; the cornea
    // bulge makes them slightly non-spherical, so the fit is checked against the bounds.
    const Eigen::AlignedBox3f bounds = computeBounds(asset_->primitives[e == 0 ? 4 : 6].mesh);
    EXPECT_NEAR(s.radius, 0.5f * bounds.sizes().mean(), 0.0015f);
    EXPECT_LT((s.center - bounds.center()).norm(), 0.002f);
  }
  EXPECT_EQ(asset_->primitives[4].part, "M_ScleraLeft");
  EXPECT_EQ(asset_->primitives[6].part, "M_ScleraRight");
  EXPECT_GT(rig_->eyeball(0).center.x(), 0.0f);  // the subject's left eye is at +x
  EXPECT_LT(rig_->eyeball(1).center.x(), 0.0f);
  EXPECT_NEAR(rig_->eyeball(0).center.x(), -rig_->eyeball(1).center.x(), 0.002f);  // mirror images
  const Vec3 jaw = rig_->config().jawPivot;
  std::printf("[ info     ] jaw pivot (%.4f, %.4f, %.4f) m, head pivot (%.4f, %.4f, %.4f) m\n", jaw.x(), jaw.y(),
              jaw.z(), rig_->config().headPivot.x(), rig_->config().headPivot.y(), rig_->config().headPivot.z());
  // The hinge is below the eyes and behind the teeth.
  EXPECT_LT(jaw.y(), rig_->eyeball(0).center.y());
  EXPECT_LT(jaw.z(), rig_->eyeball(0).center.z());
}

TEST_F(IctFaceRig, JawRotationOpensTheMouthAndKeepsTheForeheadStill) {
  FacePose pose;
  pose.jaw.eulerDegrees = Vec3(10.0f, 0.0f, 0.0f);
  size_t face = 0;
  while (asset_->primitives[face].part != "M_Face") ++face;
  const TriangleMesh posed = rig_->evaluatePrimitive(face, pose);
  const TriangleMesh& neutral = asset_->primitives[face].mesh;
  const uint32_t chin = uint32_t(asset_->landmarks[8].vertex);  // landmark 8: the chin
  const uint32_t browLandmark = uint32_t(asset_->landmarks[19].vertex);  // a brow point
  EXPECT_LT(posed.positions[chin].y(), neutral.positions[chin].y() - 0.005f);
  // jawOpen moves the brow by a hair, so its jaw weight is tiny but not zero.
  EXPECT_LT((posed.positions[browLandmark] - neutral.positions[browLandmark]).norm(), 1e-5f);
  EXPECT_TRUE(findMeshDefect(posed).empty());
}

TEST_F(IctFaceRig, APoseIsTheSameForAnyThreadCount) {
  // Blendshapes, the jaw's skinning and the head's transform run split over vertex ranges.
  FacePose pose{std::vector<float>(57, 0.0f), {}, {}, {}};
  for (size_t k = 0; k < pose.blendshapeWeights.size(); k += 3) pose.blendshapeWeights[k] = 0.1f + 0.01f * float(k);
  pose.jaw.eulerDegrees = Vec3(8.0f, 0.0f, 0.0f);
  pose.head.eulerDegrees = Vec3(6.0f, -1.0f, 12.0f);
  const std::vector<TriangleMesh> parallel = rig_->evaluate(pose);
  std::vector<TriangleMesh> serial;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    serial = rig_->evaluate(pose);
  }
  ASSERT_EQ(parallel.size(), serial.size());
  for (size_t i = 0; i < parallel.size(); ++i) expectBitwiseEqual(parallel[i], serial[i]);
}

TEST_F(IctFaceRig, BlendshapesAddInTargetOrderAsOneLoopWould) {
  FacePose pose{std::vector<float>(57, 0.0f), {}, {}, {}};
  for (size_t k = 0; k < pose.blendshapeWeights.size(); k += 2) pose.blendshapeWeights[k] = 0.3f - 0.004f * float(k);
  size_t face = 0;
  while (asset_->primitives[face].part != "M_Face") ++face;
  const GltfPrimitive& primitive = asset_->primitives[face];
  ASSERT_GT(primitive.mesh.positions.size(), 8192u);  // split into several vertex ranges
  std::vector<Vec3> expected = primitive.mesh.positions;
  for (size_t k = 0; k < primitive.targets.size(); ++k)
    for (size_t i = 0; i < primitive.targets[k].vertices.size(); ++i)
      expected[primitive.targets[k].vertices[i]] += pose.blendshapeWeights[k] * primitive.targets[k].deltas[i];
  const TriangleMesh posed = rig_->evaluatePrimitive(face, pose);
  ASSERT_EQ(posed.positions.size(), expected.size());
  EXPECT_EQ(0, std::memcmp(posed.positions.data(), expected.data(), expected.size() * sizeof(Vec3)));
}

}  // namespace face_rig_test
}  // namespace lacrima
