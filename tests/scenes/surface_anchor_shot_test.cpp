// Surface anchors in shots: a detail centre or a tear start given as a landmark, a vertex or a
// texture coordinate instead of a point near the skin.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lacrima/mesh/surface_point.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace surface_anchor_shot_test {

using test::expectSingleError;
using test::shotErrorOf;
using test::writeShot;


// Frames 1-3 of the face.
std::string faceShot(const std::string& extra, const std::string& asset = "") {
  return test::ictFaceShot(extra, "", asset, 3);
}

std::string detailAt(const std::string& center, const std::string& part = "M_Face") {
  return faceShot(R"("details": [{"pattern": "cheek", "asset": "face", "part": ")" + part + R"(", "center": )" + center +
                  R"(, "extent": [0.01, 0.008], "scale": 0.0005, "startFrame": 1, "endFrame": 3}])");
}

// The glTF facts the anchors refer to: landmark 39 (the inner corner of the subject's right eye).
struct LandmarkFacts {
  size_t primitive = 0;
  uint32_t vertex = 0;
  Vec3 position = Vec3::Zero();
  Vec2 uv = Vec2::Zero();
};

LandmarkFacts landmark39(const Shot& shot) {
  const GltfAsset& gltf = *shot.assets[0].gltf;
  const Landmark& l = gltf.landmarks.at(39);
  const TriangleMesh& mesh = gltf.primitives[size_t(l.primitive)].mesh;
  return {size_t(l.primitive), l.vertex, mesh.positions[l.vertex], mesh.uvs.at(l.vertex)};
}

TEST(SurfaceAnchor, LandmarkVertexAndUvResolveToTheSameSkinPoint) {
  const Shot byLandmark = loadShot(writeShot("landmark.json", detailAt(R"({"landmark": 39})")));
  const LandmarkFacts facts = landmark39(byLandmark);
  const ShotSurfacePoint& a = byLandmark.details.at(0).surfacePoint;
  EXPECT_EQ(a.primitive, facts.primitive);
  EXPECT_EQ(a.reference, facts.position) << "the neutral face at the first frame: exactly the landmark vertex";

  const Shot byVertex =
      loadShot(writeShot("vertex.json", detailAt(fmt::format(R"({{"vertex": {}}})", facts.vertex))));
  EXPECT_EQ(byVertex.details.at(0).surfacePoint.reference, facts.position);

  const Shot byUv =
      loadShot(writeShot("uv.json", detailAt(fmt::format(R"({{"uv": [{:.9g}, {:.9g}]}})", facts.uv.x(), facts.uv.y()))));
  EXPECT_LT((byUv.details.at(0).surfacePoint.reference - facts.position).norm(), 1e-6f);

  const Shot byPoint = loadShot(writeShot(
      "point.json", detailAt(fmt::format("[{:.9g}, {:.9g}, {:.9g}]", facts.position.x(), facts.position.y(),
                                         facts.position.z()))));
  EXPECT_LT((byPoint.details.at(0).surfacePoint.reference - facts.position).norm(), 1e-6f);
}

TEST(SurfaceAnchor, LandmarkAnchorFollowsTheFace) {
  // The tear start on landmark 40 (lower lid) follows an eye blink until the drop starts.
  const std::string tear =
      R"("tears": [{"type": "dripping", "asset": "face", "part": "M_Face", "start": {"landmark": 40},
           "startFrame": 3, "alpha": 0.0005, "beta": 0.004, "lambda": 0.1, "material": "water"}])";
  const Shot shot = loadShot(writeShot("tear.json", faceShot(tear)));
  const Shot blinking = loadShot(
      writeShot("tear_blink.json", faceShot(tear, R"("blendshapes": {"eyeBlink_R": {"keys": [[1, 0], [3, 1]]}})")));
  const ShotTear& still = shot.tears.at(0);
  const ShotTear& moving = blinking.tears.at(0);
  EXPECT_EQ(still.origin, still.surfacePoint.reference);
  EXPECT_EQ(moving.surfacePoint.reference, still.surfacePoint.reference) << "same neutral first frame";
  EXPECT_GT((moving.origin - moving.surfacePoint.reference).norm(), 1e-4f) << "the blink carries the lid point";
}

TEST(SurfaceAnchor, BadAnchorsGetExactMessages) {
  expectSingleError("range.json", detailAt(R"({"landmark": 68})"),
                    "/details/0/center/landmark: expected an integer in [0, 67], found 68");
  expectSingleError("part.json", detailAt(R"({"landmark": 39})", "M_ScleraRight"),
                    "/details/0/center/landmark: landmark 39 is a vertex of part 'M_Face', not of 'M_ScleraRight'");
  expectSingleError("vertex.json", detailAt(R"({"vertex": 9547})"),
                    "/details/0/center/vertex: expected an integer in [0, 9546], found 9547");
  expectSingleError("uv.json", detailAt(R"({"uv": [5, 5]})"),
                    "/details/0/center/uv: no triangle of part 'M_Face' covers uv [5, 5]");
  expectSingleError("typo.json", detailAt(R"({"landmrk": 39})"),
                    "/details/0/center/landmrk: unknown key 'landmrk'; did you mean 'landmark'?");
  expectSingleError("two.json", detailAt(R"({"landmark": 39, "vertex": 1})"),
                    "/details/0/center: expected a surface anchor, [x, y, z], {\"landmark\": i}, {\"vertex\": i} or "
                    "{\"uv\": [u, v]}; found an object");
  expectSingleError("missing.json", faceShot(R"("details": [{"pattern": "cheek", "asset": "face", "part": "M_Face",
                      "extent": [0.01, 0.008], "scale": 0.0005, "startFrame": 1, "endFrame": 3}])"),
                    "/details/0: missing required key 'center' (a point [x, y, z] near the skin, {\"landmark\": i}, "
                    "{\"vertex\": i} or {\"uv\": [u, v]})");
}

TEST(SurfaceAnchor, AnIndexWrittenAsAWholeDecimalIsTheSameAnchor) {
  // The index is taken when the shot is read and checked once the asset is loaded: both must read
  // 39.0 as 39, as the checked reader of integers does.
  const Shot whole = loadShot(writeShot("landmark_39.json", detailAt(R"({"landmark": 39})")));
  const Shot decimal = loadShot(writeShot("landmark_39.0.json", detailAt(R"({"landmark": 39.0})")));
  EXPECT_EQ(decimal.details.at(0).center.index, 39u);
  EXPECT_EQ(decimal.details.at(0).surfacePoint.reference, whole.details.at(0).surfacePoint.reference);
  const uint32_t vertex = landmark39(whole).vertex;
  const Shot byVertex =
      loadShot(writeShot("vertex_decimal.json", detailAt(fmt::format(R"({{"vertex": {}.0}})", vertex))));
  EXPECT_EQ(byVertex.details.at(0).surfacePoint.reference, whole.details.at(0).surfacePoint.reference);
}

TEST(SurfaceAnchor, AnAnchorOnAnUnknownPartIsStillCheckedAsWritten) {
  // The part is checked against the loaded asset; the anchor's own form is checked whatever the part.
  std::vector<Diagnostic> diagnostics;
  shotErrorOf(writeShot("unknown_part_bad_anchor.json", detailAt(R"({"landmark": 39, "vertex": 1})", "M_Fase")),
              &diagnostics);
  ASSERT_EQ(diagnostics.size(), 2u);
  EXPECT_EQ(diagnostics[0].jsonPath + ": " + test::firstLineOf(diagnostics[0].message),
            "/details/0/part: asset 'face' has no part 'M_Fase'; did you mean 'M_Face'?");
  EXPECT_EQ(diagnostics[1].jsonPath, "/details/0/center");
  // A well-formed anchor on an unknown part is not checked against the mesh: one problem, the part.
  expectSingleError("unknown_part.json", detailAt(R"({"landmark": 39})", "M_Fase"),
                    "/details/0/part: asset 'face' has no part 'M_Fase'; did you mean 'M_Face'?");
}

}  // namespace surface_anchor_shot_test
}  // namespace lacrima
