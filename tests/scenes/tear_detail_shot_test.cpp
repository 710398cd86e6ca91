// Dripping tears and animated skin details in shots ("tears" and "details"), checked through
// loadShot/buildFrame against the geometry library evaluated directly.
#include <gtest/gtest.h>

#include "lacrima/face/detail_patterns.hpp"
#include "lacrima/tears/dripping_tear.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace tear_detail_shot_test {

using test::shotErrorOf;
using test::expectSingleError;
using test::firstLineOf;
using test::ictFaceShot;
using test::writeShot;

const Vec3 kCheek(-0.0345f, -0.0018f, 0.0995f);


const std::string kTear =
    R"("tears": [{"type": "dripping", "asset": "face", "part": "M_Face", "start": [-0.0345, -0.0018, 0.0995],
       "startFrame": 3, "alpha": 0.0005, "beta": 0.004, "lambda": 0.1, "material": "water", "rings": 12, "segments": 16}])";

using test::findMesh;

const MeshInstance& faceMesh(const Frame& frame, const Shot& shot) {
  const GltfAsset& gltf = *shot.assets[0].gltf;
  for (const GltfPrimitive& p : gltf.primitives)
    if (p.part == "M_Face")
      if (const MeshInstance* m = findMesh(frame, "face/" + p.name)) return *m;
  ADD_FAILURE() << "no M_Face mesh";
  return frame.meshes.front();
}

TEST(TearShot, DrippingTearAppearsFromItsStartFrameAtTheSkin) {
  const Shot shot = loadShot(writeShot("tear.json", ictFaceShot(kTear)));
  ASSERT_EQ(shot.tears.size(), 1u);
  const ShotTear& tear = shot.tears[0];
  EXPECT_LT((tear.origin - kCheek).norm(), 2e-3f) << "snapped to the skin near the written start";
  EXPECT_EQ(tear.origin, tear.surfacePoint.reference) << "a still face: the skin point does not move";
  EXPECT_EQ(findMesh(buildFrame(shot, 1), "tear"), nullptr);
  EXPECT_EQ(findMesh(buildFrame(shot, 2), "tear"), nullptr);
  for (int f : {3, 5}) {
    const Frame frame = buildFrame(shot, f);
    const MeshInstance* drop = findMesh(frame, "tear");
    ASSERT_NE(drop, nullptr) << "frame " << f;
    EXPECT_EQ(findClosedMeshDefect(drop->mesh), "");
    EXPECT_FALSE(drop->moves()) << "no shutter, no blur";
    EXPECT_EQ(drop->materialId, uint32_t(shot.findMaterial("water")));
    TriangleMesh expected = makeDrippingTear(tear.params, float((f - 3) / 24.0), 12, 16);
    placeDrippingTear(expected, tear.origin, Vec3(0, -1, 0));
    EXPECT_EQ(drop->mesh.positions, expected.positions);
  }
}

TEST(TearShot, DrippingTearFollowsTheSkinUntilItStartsAndBlursWithAShutter) {
  const Shot shot = loadShot(writeShot(
      "tear_blur.json",
      ictFaceShot(kTear, R"(, "shutter": {"open": -0.25, "close": 0.25})",
               R"("blendshapes": {"cheekRaiser_R": {"keys": [[1, 0], [5, 1]], "interpolation": "linear"}})")));
  const ShotTear& tear = shot.tears[0];
  EXPECT_GT((tear.origin - tear.surfacePoint.reference).norm(), 1e-4f) << "the raised cheek carries the start point";
  const Frame frame = buildFrame(shot, 4);
  const MeshInstance* drop = findMesh(frame, "tear");
  ASSERT_NE(drop, nullptr);
  ASSERT_TRUE(drop->moves());
  EXPECT_EQ(drop->positionsAtClose.size(), drop->mesh.positions.size());
  TriangleMesh atClose = makeDrippingTear(tear.params, float(1.25 / 24.0), 12, 16);
  placeDrippingTear(atClose, tear.origin, Vec3(0, -1, 0));
  EXPECT_EQ(drop->positionsAtClose, atClose.positions);
}

const std::string kDetail =
    R"("details": [{"pattern": "cheek", "alpha": 1, "beta": 2, "asset": "face", "part": "M_Face",
       "center": [-0.0345, -0.0018, 0.0995], "extent": [0.01, 0.008], "innerRadius": 0.4, "scale": 0.0005,
       "coordinateScale": 1000, "startFrame": 2, "endFrame": 4, "amplitude": AMP}])";

std::string detail(const std::string& amplitude) {
  std::string s = kDetail;
  s.replace(s.find("AMP"), 3, amplitude);
  return s;
}

TEST(DetailShot, DetailDisplacesOnlyInsideItsRegionAndFrameRange) {
  const Shot shot = loadShot(writeShot("detail.json", ictFaceShot(detail("1"))));
  ASSERT_EQ(shot.details.size(), 1u);
  const Frame neutral = buildFrame(shot, 1);
  const MeshInstance& rest = faceMesh(neutral, shot);
  // Outside [startFrame, endFrame] the face is bitwise the face without details.
  const Shot plain = loadShot(writeShot("plain.json", ictFaceShot(R"("shapes": [])")));
  EXPECT_EQ(rest.mesh.positions, faceMesh(buildFrame(plain, 1), plain).mesh.positions);
  EXPECT_EQ(rest.mesh.normals, faceMesh(buildFrame(plain, 1), plain).mesh.normals);
  EXPECT_EQ(faceMesh(buildFrame(shot, 5), shot).mesh.positions, rest.mesh.positions);
  const Vec3 center = shot.details[0].surfacePoint.reference;
  for (int f : {2, 3, 4}) {
    const Frame frame = buildFrame(shot, f);
    const MeshInstance& face = faceMesh(frame, shot);
    ASSERT_EQ(face.mesh.positions.size(), rest.mesh.positions.size());
    size_t moved = 0;
    float farthest = 0.0f, largest = 0.0f;
    for (size_t i = 0; i < rest.mesh.positions.size(); ++i) {
      if (face.mesh.positions[i] == rest.mesh.positions[i]) continue;
      ++moved;
      farthest = std::max(farthest, (rest.mesh.positions[i] - center).norm());
      largest = std::max(largest, (face.mesh.positions[i] - rest.mesh.positions[i]).norm());
    }
    EXPECT_GT(moved, 10u) << "frame " << f;
    // Inside the ellipse (semi-axis 1 cm) and within 1 cm of the skin plane.
    EXPECT_LE(farthest, 0.01f * std::sqrt(2.0f)) << "frame " << f;
    EXPECT_LE(largest, 0.0005f * 1.0001f) << "|cheek pattern| <= alpha = 1 times scale";
    EXPECT_NE(face.mesh.normals, rest.mesh.normals) << "normals follow the displaced skin";
  }
  // t grows with the frame: the pattern changes.
  EXPECT_NE(faceMesh(buildFrame(shot, 2), shot).mesh.positions, faceMesh(buildFrame(shot, 3), shot).mesh.positions);
}

TEST(DetailShot, MovedVerticesLieInsideTheEllipseOfTheSkinFrame) {
  const Shot shot = loadShot(writeShot("detail_frame.json", ictFaceShot(detail("1"))));
  const MeshInstance rest = faceMesh(buildFrame(shot, 1), shot);
  const Frame frame = buildFrame(shot, 3);
  const MeshInstance& face = faceMesh(frame, shot);
  // The local frame as documented: interpolated skin normal at the snapped centre, x = +x projected.
  const ShotSurfacePoint& sp = shot.details[0].surfacePoint;
  const uint32_t* tri = &rest.mesh.indices[3 * size_t(sp.triangle)];
  ASSERT_EQ(rest.mesh.normals.size(), rest.mesh.positions.size());
  const Vec3 normal = (sp.barycentric.x() * rest.mesh.normals[tri[0]] + sp.barycentric.y() * rest.mesh.normals[tri[1]] +
                       sp.barycentric.z() * rest.mesh.normals[tri[2]]).normalized();
  const Vec3 tx = (Vec3(Vec3::UnitX()) - normal.x() * normal).normalized();
  const Vec3 ty = normal.cross(tx);
  size_t moved = 0, innerStill = 0;
  for (size_t i = 0; i < rest.mesh.positions.size(); ++i) {
    const Vec3 d = rest.mesh.positions[i] - sp.reference;
    const float rho = std::hypot(d.dot(tx) / 0.01f, d.dot(ty) / 0.008f);
    const bool near = std::abs(d.dot(normal)) <= 0.01f;
    if (face.mesh.positions[i] != rest.mesh.positions[i]) {
      ++moved;
      EXPECT_LT(rho, 1.0f + 1e-4f) << "vertex " << i;
      EXPECT_TRUE(near) << "vertex " << i;
      // Along the skin normal of the vertex.
      const Vec3 step = face.mesh.positions[i] - rest.mesh.positions[i];
      EXPECT_GT(std::abs(step.normalized().dot(rest.mesh.normals[i])), 0.999f) << "vertex " << i;
    } else if (rho < 0.4f && near) {
      ++innerStill;  // possible only where the pattern height is exactly 0
    }
  }
  // Normals change only on triangles with a moved vertex.
  std::vector<bool> touched(rest.mesh.positions.size(), false);
  for (size_t t = 0; t < rest.mesh.triangleCount(); ++t) {
    const uint32_t* v = &rest.mesh.indices[3 * t];
    bool any = false;
    for (int k = 0; k < 3; ++k) any = any || face.mesh.positions[v[k]] != rest.mesh.positions[v[k]];
    if (any)
      for (int k = 0; k < 3; ++k) touched[v[k]] = true;
  }
  for (size_t i = 0; i < touched.size(); ++i) {
    if (!touched[i]) {
      ASSERT_EQ(face.mesh.normals[i], rest.mesh.normals[i]) << "vertex " << i;
    }
  }
  EXPECT_GT(moved, 10u);
  EXPECT_LE(innerStill, moved / 20) << "nearly every vertex of the inner region moves";
}

TEST(DetailShot, KeyedAmplitudeScalesTheDisplacementAndZeroLeavesTheFace) {
  const Shot shot = loadShot(writeShot(
      "detail_keys.json", ictFaceShot(detail(R"({"keys": [[2, 0], [4, 2]], "interpolation": "linear"})"))));
  const Shot constant = loadShot(writeShot("detail_one.json", ictFaceShot(detail("1"))));
  const MeshInstance rest = faceMesh(buildFrame(shot, 1), shot);
  EXPECT_EQ(faceMesh(buildFrame(shot, 2), shot).mesh.positions, rest.mesh.positions) << "amplitude 0";
  // Frame 3: amplitude 1, as the constant one.
  const auto keyed = faceMesh(buildFrame(shot, 3), shot).mesh.positions;
  const auto one = faceMesh(buildFrame(constant, 3), constant).mesh.positions;
  ASSERT_EQ(keyed.size(), one.size());
  for (size_t i = 0; i < keyed.size(); ++i) ASSERT_LT((keyed[i] - one[i]).norm(), 1e-7f) << i;
}

TEST(DetailShot, SumOfPatternsAndAShutterBlurTheStillFace) {
  const Shot shot = loadShot(writeShot("detail_sum.json", ictFaceShot(
      R"("details": [{"patterns": [{"pattern": "cheek", "alpha": 1, "beta": 2}, {"pattern": "frown", "alpha": 0.5}],
         "asset": "face", "part": "M_Face", "center": [-0.0345, -0.0018, 0.0995], "extent": [0.01, 0.01],
         "scale": 0.0005, "coordinateScale": 1000, "startFrame": 1, "endFrame": 5, "tangent": [1, 0.2, 0]}])",
      R"(, "shutter": {"open": 0, "close": 0.5})")));
  ASSERT_EQ(shot.details[0].patterns.size(), 2u);
  EXPECT_EQ(shot.details[0].patterns[1].kind, DetailPatternKind::Frown);
  const Frame frame = buildFrame(shot, 3);
  EXPECT_TRUE(faceMesh(frame, shot).moves()) << "the detail animates within the shutter";
}


std::string tearWith(const std::string& from, const std::string& to) {
  return ictFaceShot(test::replaced(kTear, from, to));
}

std::string detailWith(const std::string& from, const std::string& to) {
  return ictFaceShot(test::replaced(detail("1"), from, to));
}

TEST(DetailShot, PatternOriginMovesThePatternWithinTheSameRegion) {
  const Shot centred = loadShot(writeShot("detail_centred.json", ictFaceShot(detail("1"))));
  const Shot shifted = loadShot(writeShot("detail_shifted.json", detailWith(R"("amplitude": 1)",
                                                                       R"("amplitude": 1, "patternOrigin": [0.002, -0.003])")));
  EXPECT_EQ(shifted.details[0].patternOrigin, Vec2(0.002f, -0.003f));
  const auto rest = faceMesh(buildFrame(centred, 1), centred).mesh.positions;
  const auto a = faceMesh(buildFrame(centred, 3), centred).mesh.positions;
  const auto b = faceMesh(buildFrame(shifted, 3), shifted).mesh.positions;
  size_t moved = 0, differ = 0;
  for (size_t i = 0; i < rest.size(); ++i) {
    // Same damping, so the same vertices move (or stay) in both; the heights differ.
    EXPECT_EQ(a[i] == rest[i], b[i] == rest[i]) << i;
    moved += a[i] != rest[i] ? 1 : 0;
    differ += a[i] != b[i] ? 1 : 0;
  }
  EXPECT_GT(moved, 10u);
  EXPECT_EQ(differ, moved) << "every displaced vertex has another height";
}

TEST(TearShot, BadTearsGetExactMessages) {
  expectSingleError("type.json", tearWith(R"("dripping")", R"("driping")"),
              "/tears/0/type: unknown tear type 'driping'; did you mean 'dripping'?");
  expectSingleError("asset.json", tearWith(R"("asset": "face")", R"("asset": "fcae")"),
              "/tears/0/asset: undefined asset 'fcae'; did you mean 'face'?");
  expectSingleError("part.json", tearWith(R"("M_Face")", R"("M_Fcae")"),
              "/tears/0/part: asset 'face' has no part 'M_Fcae'; did you mean 'M_Face'?");
  expectSingleError("material.json", tearWith(R"("material": "water")", R"("material": "watr")"),
              "/tears/0/material: undefined material 'watr'; did you mean 'water'?");
  expectSingleError("alpha.json", tearWith(R"("alpha": 0.0005)", R"("alpha": 0)"),
              "/tears/0/alpha: expected a number > 0, found 0");
  expectSingleError("beta.json", tearWith(R"("beta": 0.004)", R"("beta": -1)"),
              "/tears/0/beta: expected a number > 0, found -1");
  expectSingleError("gravity.json", tearWith(R"("rings": 12)", R"("gravity": [0, 0, 0], "rings": 12)"),
              "/tears/0/gravity: the gravity direction must not be zero");
  expectSingleError("key.json", tearWith(R"("lambda")", R"("lamda")"),
              "/tears/0/lamda: unknown key 'lamda'; did you mean 'lambda'?");
  expectSingleError("segments.json", tearWith(R"("segments": 16)", R"("segments": 2)"),
              "/tears/0/segments: expected an integer in [3, 1024], found 2");
}

TEST(DetailShot, BadDetailsGetExactMessages) {
  expectSingleError("pattern.json", detailWith(R"("cheek")", R"("cheeck")"),
              "/details/0/pattern: unknown detail pattern 'cheeck'; did you mean 'cheek'?");
  expectSingleError("part.json", detailWith(R"("M_Face")", R"("M_Fac")"),
              "/details/0/part: asset 'face' has no part 'M_Fac'; did you mean 'M_Face'?");
  expectSingleError("extent.json", detailWith("[0.01, 0.008]", "[0.01, 0]"),
              "/details/0/extent/1: expected a number > 0, found 0");
  expectSingleError("inner.json", detailWith(R"("innerRadius": 0.4)", R"("innerRadius": 1)"),
              "/details/0/innerRadius: expected a number in [0, 1), found 1");
  expectSingleError("frames.json", detailWith(R"("endFrame": 4)", R"("endFrame": 1)"),
              "/details/0/endFrame: the detail must end at or after its start: endFrame 1 < startFrame 2");
  expectSingleError("amplitude.json", detailWith(R"("amplitude": 1)", R"("amplitude": -1)"),
              "/details/0/amplitude: expected a number >= 0, found -1");
  expectSingleError("fraction.json", detailWith(R"("amplitude": 1)", R"("amplitude": 1, "validFraction": 2)"),
              "/details/0/validFraction: expected a number in [0, 1], found 2");
  expectSingleError("origin.json", detailWith(R"("amplitude": 1)", R"("amplitude": 1, "patternOrigin": [0.01])"),
              "/details/0/patternOrigin: expected [x, y] (an array of 2 numbers), found an array of 1 element");
  expectSingleError("key.json", detailWith(R"("beta": 2)", R"("bta": 2)"),
              "/details/0/bta: unknown key 'bta'; did you mean 'beta'?");
}

}  // namespace tear_detail_shot_test
}  // namespace lacrima
