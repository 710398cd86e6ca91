// A detail's "subdivision": the face refined around the detail at load, conforming with the
// rest of the face, carrying blendshapes, and checked like every other shot value.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "lacrima/mesh/surface_point.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace detail_subdivision_shot_test {

using test::expectSingleError;
using test::firstLineOf;
using test::shotErrorOf;
using test::writeShot;

const Vec3 kCheek(-0.0345f, -0.0018f, 0.0995f);

// Frames 1-5 of the face at 24 fps with one cheek detail active at frames 2-4.
std::string subdivisionShot(const std::string& subdivision, const std::string& asset = "") {
  return test::ictFaceShot(
      R"("details": [{"pattern": "cheek", "alpha": 1, "beta": 2, "asset": "face", "part": "M_Face",
      "center": [-0.0345, -0.0018, 0.0995], "extent": [0.01, 0.008], "innerRadius": 0.4, "scale": 0.0005,
      "coordinateScale": 1000, "startFrame": 2, "endFrame": 4)" +
          (subdivision.empty() ? "" : ",\n      \"subdivision\": " + subdivision) + "}]",
      "", asset);
}

size_t facePrimitive(const Shot& shot) {
  const GltfAsset& gltf = *shot.assets[0].gltf;
  for (size_t i = 0; i < gltf.primitives.size(); ++i)
    if (gltf.primitives[i].part == "M_Face") return i;
  ADD_FAILURE() << "no M_Face";
  return 0;
}

const TriangleMesh& neutralFace(const Shot& shot) { return shot.assets[0].gltf->primitives[facePrimitive(shot)].mesh; }

const MeshInstance& faceMesh(const Frame& frame, const Shot& shot) {
  const std::string name = "face/" + shot.assets[0].gltf->primitives[facePrimitive(shot)].name;
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name == name) return m;
  ADD_FAILURE() << "no " << name;
  return frame.meshes.front();
}

using Corners = std::array<std::array<float, 3>, 3>;

Corners cornersOf(const TriangleMesh& m, size_t t) {
  Corners c;
  for (int k = 0; k < 3; ++k) {
    const Vec3& p = m.positions[m.indices[3 * t + k]];
    c[size_t(k)] = {p.x(), p.y(), p.z()};
  }
  return c;
}

float distanceToCheek(const TriangleMesh& m, size_t t) {
  float d = std::numeric_limits<float>::infinity();
  for (int k = 0; k < 3; ++k) d = std::min(d, (m.positions[m.indices[3 * t + k]] - kCheek).norm());
  return d;
}

// Edges with one triangle once coincident vertices are merged: the mesh's open boundary, and
// any crack or T-junction. Returns their count and total length.
std::pair<size_t, double> openEdges(const TriangleMesh& m) {
  const std::vector<uint32_t> weld = findCoincidentVertices(m);
  std::map<std::pair<uint32_t, uint32_t>, int> count;
  for (size_t c = 0; c < m.indices.size(); ++c) {
    const uint32_t a = weld[m.indices[c]], b = weld[m.indices[3 * (c / 3) + (c + 1) % 3]];
    ++count[{std::min(a, b), std::max(a, b)}];
  }
  std::pair<size_t, double> out{0, 0.0};
  for (const auto& [edge, n] : count)
    if (n == 1) {
      ++out.first;
      out.second += double((m.positions[edge.first] - m.positions[edge.second]).norm());
    }
  return out;
}

size_t movedVertices(const TriangleMesh& a, const TriangleMesh& b) {
  size_t moved = 0;
  for (size_t i = 0; i < a.positions.size(); ++i) moved += a.positions[i] != b.positions[i] ? 1 : 0;
  return moved;
}

TEST(DetailSubdivisionShot, RefinesTheRegionAndLeavesTheRestOfTheFaceAsItWas) {
  const Shot plain = loadShot(writeShot("plain.json", subdivisionShot("")));
  const Shot refined = loadShot(writeShot("loop2.json", subdivisionShot(R"({"levels": 2})")));
  EXPECT_EQ(refined.details[0].subdivisionLevels, 2);
  EXPECT_EQ(refined.details[0].subdivisionScheme, RefinementScheme::Loop);
  const TriangleMesh& before = neutralFace(plain);
  const TriangleMesh& after = neutralFace(refined);
  size_t nearBefore = 0, nearAfter = 0;
  std::multiset<Corners> farBefore, farAfter;
  for (size_t t = 0; t < before.triangleCount(); ++t) {
    if (distanceToCheek(before, t) < 0.008f) ++nearBefore;
    if (distanceToCheek(before, t) > 0.03f) farBefore.insert(cornersOf(before, t));
  }
  for (size_t t = 0; t < after.triangleCount(); ++t) {
    if (distanceToCheek(after, t) < 0.008f) ++nearAfter;
    if (distanceToCheek(after, t) > 0.03f) farAfter.insert(cornersOf(after, t));
  }
  // Two levels make 16 triangles of one; fewer of the smaller ones reach into the counting sphere.
  EXPECT_GT(nearAfter, 10 * nearBefore);
  EXPECT_EQ(farAfter, farBefore) << "away from the detail the triangles are bitwise the same";
  EXPECT_GT(after.vertexCount(), before.vertexCount());
  // Other parts are untouched.
  for (size_t i = 0; i < plain.assets[0].gltf->primitives.size(); ++i) {
    if (i == facePrimitive(plain)) continue;
    EXPECT_EQ(plain.assets[0].gltf->primitives[i].mesh.indices, refined.assets[0].gltf->primitives[i].mesh.indices);
  }
}

TEST(DetailSubdivisionShot, LandmarkAnchoredDetailRefinesAroundTheLandmark) {
  // Landmark 40 (the subject's right lower lid) instead of a point: the region is refined there,
  // and the cheek, 3 cm below, is not.
  std::string text = subdivisionShot(R"({"levels": 1, "scheme": "linear"})");
  const std::string point = "[-0.0345, -0.0018, 0.0995]";
  text.replace(text.find(point), point.size(), R"({"landmark": 40})");
  const Shot plain = loadShot(writeShot("plain.json", subdivisionShot("")));
  const Shot refined = loadShot(writeShot("landmark.json", text));
  const GltfAsset& gltf = *refined.assets[0].gltf;
  const Landmark& lid = gltf.landmarks.at(40);
  const Vec3 lidPosition = gltf.primitives[size_t(lid.primitive)].mesh.positions[lid.vertex];
  EXPECT_EQ(lidPosition, neutralFace(plain).positions[lid.vertex]) << "linear refinement keeps original vertices";
  auto countNear = [](const TriangleMesh& m, const Vec3& p, float radius) {
    size_t n = 0;
    for (size_t t = 0; t < m.triangleCount(); ++t)
      for (int k = 0; k < 3; ++k)
        if ((m.positions[m.indices[3 * t + k]] - p).norm() < radius) {
          ++n;
          break;
        }
    return n;
  };
  EXPECT_GT(countNear(neutralFace(refined), lidPosition, 0.005f), 3 * countNear(neutralFace(plain), lidPosition, 0.005f));
  EXPECT_EQ(countNear(neutralFace(refined), kCheek, 0.005f), countNear(neutralFace(plain), kCheek, 0.005f));
  EXPECT_EQ(refined.details[0].surfacePoint.reference, lidPosition) << "the anchor resolves on the refined face";
}

TEST(DetailSubdivisionShot, RefinedFaceIsValidOpensNoEdgeAndShowsMoreOfTheDetail) {
  const Shot plain = loadShot(writeShot("plain.json", subdivisionShot("")));
  const Shot refined = loadShot(writeShot("loop3.json", subdivisionShot(R"({"levels": 3, "scheme": "loop"})")));
  const TriangleMesh restBefore = faceMesh(buildFrame(plain, 1), plain).mesh;
  const TriangleMesh restAfter = faceMesh(buildFrame(refined, 1), refined).mesh;
  const TriangleMesh displacedBefore = faceMesh(buildFrame(plain, 3), plain).mesh;
  const TriangleMesh displacedAfter = faceMesh(buildFrame(refined, 3), refined).mesh;
  EXPECT_EQ(findMeshDefect(displacedAfter), "");
  const auto [openBefore, lengthBefore] = openEdges(restBefore);
  const auto [openAfter, lengthAfter] = openEdges(restAfter);
  EXPECT_EQ(openAfter, openBefore) << "no crack, no T-junction (the cheek is far from the mesh border)";
  EXPECT_NEAR(lengthAfter, lengthBefore, 1e-6 * lengthBefore);
  EXPECT_EQ(openEdges(displacedAfter).first, openBefore);
  const size_t movedBefore = movedVertices(displacedBefore, restBefore);
  const size_t movedAfter = movedVertices(displacedAfter, restAfter);
  EXPECT_GT(movedBefore, 10u);
  EXPECT_GT(movedAfter, 30 * movedBefore) << "three levels: about 64 times the vertices under the detail";
}

TEST(DetailSubdivisionShot, KeyedBlendshapeCarriesTheNewVerticesWithTheFace) {
  const std::string keyed = R"("blendshapes": {"cheekRaiser_R": {"keys": [[1, 0], [5, 1]], "interpolation": "linear"}})";
  const Shot plain = loadShot(writeShot("plain_keyed.json", subdivisionShot("", keyed)));
  const Shot refined = loadShot(writeShot("linear_keyed.json", subdivisionShot(R"({"levels": 2, "scheme": "linear"})", keyed)));
  const TriangleMesh plain1 = faceMesh(buildFrame(plain, 1), plain).mesh;
  const TriangleMesh plain5 = faceMesh(buildFrame(plain, 5), plain).mesh;
  const TriangleMesh refined1 = faceMesh(buildFrame(refined, 1), refined).mesh;
  const TriangleMesh refined5 = faceMesh(buildFrame(refined, 5), refined).mesh;
  // Linear refinement: a new vertex lies on the old surface, and its blendshape delta is the
  // barycentric mix of its old triangle's deltas; so it sits where that surface point went.
  size_t followed = 0;
  for (size_t v = plain1.vertexCount(); v < refined1.vertexCount(); ++v) {
    const SurfacePoint onOld = closestSurfacePoint(plain1, refined1.positions[v]);
    ASSERT_LT((surfacePosition(plain1, onOld) - refined1.positions[v]).norm(), 1e-6f) << v;
    EXPECT_LT((surfacePosition(plain5, onOld) - refined5.positions[v]).norm(), 2e-6f) << v;
    if ((refined5.positions[v] - refined1.positions[v]).norm() > 1e-4f) ++followed;
  }
  EXPECT_GT(followed, (refined1.vertexCount() - plain1.vertexCount()) / 2) << "the raised cheek moves them";
  for (size_t v = 0; v < plain5.vertexCount(); ++v) ASSERT_EQ(refined5.positions[v], plain5.positions[v]) << v;
}

TEST(DetailSubdivisionShot, RiggedAssetIsRebuiltOnTheRefinedFace) {
  const Shot shot = loadShot(writeShot("rig.json", subdivisionShot(R"({"levels": 1})", R"("rig": {"preset": "ict"},
      "joints": {"jaw.rx": {"keys": [[1, 0], [5, 10]], "interpolation": "linear"}})")));
  ASSERT_TRUE(shot.assets[0].rig);
  const size_t face = facePrimitive(shot);
  EXPECT_EQ(shot.assets[0].rig->primitive(face).mesh.vertexCount(), neutralFace(shot).vertexCount());
  const TriangleMesh open = faceMesh(buildFrame(shot, 5), shot).mesh;
  EXPECT_EQ(findMeshDefect(open), "");
  EXPECT_GT(movedVertices(open, faceMesh(buildFrame(shot, 1), shot).mesh), 1000u) << "the jaw opens";
}

TEST(DetailSubdivisionShot, ZeroLevelsChangeNothing) {
  const Shot plain = loadShot(writeShot("plain.json", subdivisionShot("")));
  const Shot zero = loadShot(writeShot("zero.json", subdivisionShot(R"({"levels": 0, "scheme": "linear"})")));
  for (size_t i = 0; i < plain.assets[0].gltf->primitives.size(); ++i) {
    const TriangleMesh& a = plain.assets[0].gltf->primitives[i].mesh;
    const TriangleMesh& b = zero.assets[0].gltf->primitives[i].mesh;
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.indices, b.indices);
  }
  const TriangleMesh a = faceMesh(buildFrame(plain, 3), plain).mesh;
  const TriangleMesh b = faceMesh(buildFrame(zero, 3), zero).mesh;
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.normals, b.normals);
}

TEST(DetailSubdivisionShot, BadSubdivisionsAreReportedAtTheirPath) {
  expectSingleError("subdivision_levels.json", subdivisionShot(R"({"levels": 7})"),
                    "/details/0/subdivision/levels: expected an integer in [0, 4], found 7");
  expectSingleError("subdivision_scheme.json", subdivisionShot(R"({"levels": 1, "scheme": "catmull"})"),
                    "/details/0/subdivision/scheme: unknown subdivision scheme 'catmull' (expected 'loop' or 'linear')");
  expectSingleError("subdivision_typo.json", subdivisionShot(R"({"levels": 1, "scheme": "lop"})"),
                    "/details/0/subdivision/scheme: unknown subdivision scheme 'lop'; did you mean 'loop'?");
  expectSingleError("subdivision_missing.json", subdivisionShot(R"({"scheme": "loop"})"),
                    "/details/0/subdivision: missing required key 'levels' (an integer in [0, 4])");
  const auto path = writeShot("subdivision_file.json", subdivisionShot(R"({"levels": 7})"));
  EXPECT_EQ(firstLineOf(shotErrorOf(path)).rfind(path.string() + ":", 0), 0u) << "the message names the file";
}

}  // namespace detail_subdivision_shot_test
}  // namespace lacrima
