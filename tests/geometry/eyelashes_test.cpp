// Eyelashes as tubes on the ICT face's lash cards (M_EyeLashes): strips found as grids, counts,
// lengths and radii as asked, roots on the lid margin, repeatable per seed, following a blink.
#include <gtest/gtest.h>

#include <cstdio>

#include "geometry/glb_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/face/eye.hpp"
#include "lacrima/face/eyelashes.hpp"
#include "lacrima/rig/face_rig.hpp"
#include "lacrima/io/gltf_asset.hpp"
#include "lacrima/mesh/surface_point.hpp"

namespace lacrima {
namespace eyelashes_test {

class IctLashes : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    asset_ = new GltfAsset(loadGltfAsset(test::faceAssetPath()));
    rig_ = new FaceRig(*asset_, ictFaceRigConfig(*asset_));
  }
  static void TearDownTestSuite() {
    delete rig_;
    delete asset_;
  }
  static size_t primitiveOf(const std::string& part) {
    for (size_t i = 0; i < rig_->primitiveCount(); ++i)
      if (rig_->primitive(i).part == part) return i;
    throw std::runtime_error("no part " + part);
  }
  // The part with the right eye's blink at `blink`.
  static TriangleMesh posed(const std::string& part, float blink) {
    FacePose pose;
    pose.blendshapeWeights.assign(rig_->targetNames().size(), 0.0f);
    pose.blendshapeWeights[size_t(asset_->findTarget("eyeBlink_R"))] = blink;
    return rig_->evaluatePrimitive(primitiveOf(part), pose);
  }
  static EyeModel rightEye() { return analyseEye(posed("M_ScleraRight", 0.0f), EyeParams{}, "right eye"); }

  static const GltfAsset* asset_;
  static const FaceRig* rig_;
};
const GltfAsset* IctLashes::asset_ = nullptr;
const FaceRig* IctLashes::rig_ = nullptr;

TEST_F(IctLashes, CardsAreTwelveStripsOfNineteenColumnsBySixRows) {
  const EyeModel eye = rightEye();
  const auto strips = findLashStrips(posed("M_EyeLashes", 0.0f), eye.center, "M_EyeLashes");
  ASSERT_EQ(strips.size(), 12u);  // three layered strips per lid, two lids, two eyes
  for (const LashStrip& s : strips) {
    EXPECT_EQ(s.columns, 19);
    EXPECT_EQ(s.rows, 6);
  }
}

TEST_F(IctLashes, CountsLengthsAndRootsOnTheLid) {
  const EyeModel eye = rightEye();
  const TriangleMesh cards = posed("M_EyeLashes", 0.0f), face = posed("M_Face", 0.0f);
  const auto strips = findLashStrips(cards, eye.center, "M_EyeLashes");
  LashParams params;
  params.upper = 90;
  params.lower = 45;
  const auto lashes = placeLashes(strips, eye.center, eye.up, 2.0f * eye.radius, params);
  int upper = 0;
  float shortest = 1.0f, longest = 0.0f, farthestRoot = 0.0f;
  for (const Lash& lash : lashes) {
    upper += lash.upper ? 1 : 0;
    EXPECT_LT((strips[lash.strip].restCentroid - eye.center).norm(), 2.0f * eye.radius);
    const std::vector<Vec3> line = lashCentreline(strips[lash.strip], lash, cards);
    float length = 0.0f;
    for (size_t i = 1; i < line.size(); ++i) length += (line[i] - line[i - 1]).norm();
    if (lash.upper) {
      shortest = std::min(shortest, length);
      longest = std::max(longest, length);
    }
    const Vec3 root = line.front();
    farthestRoot = std::max(farthestRoot, (surfacePosition(face, closestSurfacePoint(face, root)) - root).norm());
  }
  std::printf("[ info     ] upper lashes %.2f-%.2f mm long; roots within %.2f mm of the lid's skin\n", shortest * 1e3f,
              longest * 1e3f, farthestRoot * 1e3f);
  EXPECT_EQ(upper, 90);
  EXPECT_EQ(lashes.size(), 135u);
  EXPECT_GT(shortest, 4.5e-3f);
  EXPECT_LT(longest, 11e-3f);
  EXPECT_LT(farthestRoot, 1.0e-3f);
}

TEST_F(IctLashes, TubesAreClosedTaperedAndRepeatablePerSeed) {
  const EyeModel eye = rightEye();
  const TriangleMesh cards = posed("M_EyeLashes", 0.0f);
  const auto strips = findLashStrips(cards, eye.center, "M_EyeLashes");
  LashParams params;
  params.upper = 10;
  params.lower = 5;
  const auto lashes = placeLashes(strips, eye.center, eye.up, 2.0f * eye.radius, params);
  const TriangleMesh tubes = buildLashes(strips, lashes, cards, params);
  EXPECT_EQ(findMeshDefect(tubes), "");
  EXPECT_EQ(findClosedMeshDefect(tubes), "");
  EXPECT_GT(signedVolume(tubes), 0.0);
  // Ring 0 of the first lash has the root radius.
  const Vec3 root = lashCentreline(strips[lashes[0].strip], lashes[0], cards).front();
  EXPECT_NEAR((tubes.positions[0] - root).norm(), params.rootRadius, 1e-7f);
  EXPECT_EQ(buildLashes(strips, placeLashes(strips, eye.center, eye.up, 2.0f * eye.radius, params), cards, params)
                .positions,
            tubes.positions);
  params.seed = 2;
  EXPECT_NE(buildLashes(strips, placeLashes(strips, eye.center, eye.up, 2.0f * eye.radius, params), cards, params)
                .positions,
            tubes.positions);
}

TEST_F(IctLashes, UpperLashesComeDownWithTheBlink) {
  const EyeModel eye = rightEye();
  const auto strips = findLashStrips(posed("M_EyeLashes", 0.0f), eye.center, "M_EyeLashes");
  LashParams params;
  const auto lashes = placeLashes(strips, eye.center, eye.up, 2.0f * eye.radius, params);
  const TriangleMesh open = posed("M_EyeLashes", 0.0f), closed = posed("M_EyeLashes", 1.0f);
  float meanDrop = 0.0f;
  int upper = 0;
  for (const Lash& lash : lashes) {
    if (!lash.upper) continue;
    const Vec3 a = lashCentreline(strips[lash.strip], lash, open).front();
    const Vec3 b = lashCentreline(strips[lash.strip], lash, closed).front();
    meanDrop += (a - b).dot(eye.up);
    ++upper;
  }
  meanDrop /= float(upper);
  std::printf("[ info     ] eyeBlink_R 1: upper lash roots come down %.2f mm on average\n", meanDrop * 1e3f);
  EXPECT_GT(meanDrop, 4e-3f);  // the upper lid closes over the eye's opening (~10 mm high)
}

TEST_F(IctLashes, CardsWithoutUvsOrGridsAreRejected) {
  TriangleMesh cards = posed("M_EyeLashes", 0.0f);
  cards.uvs.clear();
  try {
    findLashStrips(cards, Vec3::Zero(), "part 'M_EyeLashes'");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "part 'M_EyeLashes': the lash cards need texture coordinates to find their strips");
  }
  TriangleMesh face = posed("M_Face", 0.0f);
  try {
    findLashStrips(face, Vec3::Zero(), "part 'M_Face'");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a grid of columns along the lid by rows from root to tip"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace eyelashes_test
}  // namespace lacrima
