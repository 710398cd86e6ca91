// Shedding tears in shots ("tears" of type "shedding", Lin & Cheng 2013 section 4.2): growth from their
// start frame, a closed outward mesh on every frame, following the posed and detailed face, motion
// blur, repeatability and exact messages for bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "lacrima/tears/shedding_tear.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "geometry/gltf_builder_support.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace shedding_tear_shot_test {

using test::expectSingleError;
using test::ictFaceShot;
using test::writeShot;



// Down the right cheek (the face's -x side), starting at frame 2: 2 mm long then, 2.1 mm more a frame.
const std::string kPath =
    "[[-0.0345, 0.004, 0.0985], [-0.0345, -0.0018, 0.0995], [-0.0350, -0.009, 0.0990], [-0.0355, -0.016, 0.0975]]";
const std::string kTear =
    R"("tears": [{"type": "shedding", "asset": "face", "part": "M_Face", "path": )" + kPath + R"(,
       "startFrame": 2, "material": "water", "width": 0.004, "thickness": 0.0006, "start": 0.002, "speed": 0.05,
       "headLength": 0.002, "sampleSpacing": 0.001, "acrossSamples": 5, "skinRoughness": 0.3, "seed": 7}])";

std::string tearWith(const std::string& from, const std::string& to) { return test::replaced(kTear, from, to); }

using test::findMesh;

// The face primitive the tear lies on, as rendered in the frame (posed, with details).
const MeshInstance& skinOf(const Frame& frame, const Shot& shot) {
  const std::string name = "face/" + shot.assets[0].gltf->primitives[shot.sheddingTears[0].primitive].name;
  const MeshInstance* m = findMesh(frame, name);
  if (!m) ADD_FAILURE() << "no mesh " << name;
  return m ? *m : frame.meshes.front();
}

// The tear's strip at a frame, in the full primitive's triangles (what buildFrame places).
SheddingTearStrip stripAt(const Shot& shot, double frame) {
  const ShotSheddingTear& tear = shot.sheddingTears[0];
  SheddingTearStrip strip = buildSheddingTearStrip(tear.region->mesh, tear.regionPath, tear.params,
                                                   float(tear.secondsAt(frame, shot.fps)));
  for (SurfacePoint& p : strip.points) p = tear.region->toFull(p);
  return strip;
}

// The strip point each tear vertex sits on: base grid first, then the top's interior columns.
size_t stripPointOf(size_t vertex, const SheddingTearStrip& strip) {
  const size_t base = size_t(strip.rows * strip.columns);
  if (vertex < base) return vertex;
  const size_t top = vertex - base, interior = size_t(strip.columns - 2);
  return (top / interior) * size_t(strip.columns) + top % interior + 1;
}

struct SkinDistances {
  float lowest = std::numeric_limits<float>::infinity();  // signed, along the skin triangle's normal
  float baseError = 0.0f;  // largest |base vertex - (skin point + baseOffset n)|
};

// Every tear vertex against the skin triangle it sits on.
SkinDistances distancesToSkin(const TriangleMesh& tear, const TriangleMesh& skin, const SheddingTearStrip& strip,
                              float baseOffset) {
  SkinDistances d;
  EXPECT_EQ(tear.positions.size(), size_t(strip.rows * (2 * strip.columns - 2)));
  for (size_t v = 0; v < tear.positions.size(); ++v) {
    const SurfacePoint& sp = strip.points[stripPointOf(v, strip)];
    const Vec3 onSkin = surfacePosition(skin, sp);
    const Vec3 n = triangleNormal(skin, sp.triangle);
    d.lowest = std::min(d.lowest, (tear.positions[v] - onSkin).dot(n));
    if (v < size_t(strip.rows * strip.columns))
      d.baseError = std::max(d.baseError, (tear.positions[v] - (onSkin + baseOffset * n)).norm());
  }
  return d;
}

TriangleMesh skinMesh(const MeshInstance& instance, bool atClose) {
  TriangleMesh m = instance.mesh;
  if (atClose) m.positions = instance.positionsAtClose;
  return m;
}

TEST(SheddingTearShot, NoTearBeforeItsStartFrameThenItGrows) {
  // Without head and noise every row but the leading one stays as it was.
  std::string plainTear = tearWith(R"("headLength": 0.002)", R"("headLength": 0)");
  plainTear.replace(plainTear.find(R"("skinRoughness": 0.3)"), 20, R"("skinRoughness": 0.0)");
  const Shot shot = loadShot(writeShot("shed.json", ictFaceShot(plainTear)));
  ASSERT_EQ(shot.sheddingTears.size(), 1u);
  EXPECT_TRUE(shot.tears.empty());
  const ShotSheddingTear& tear = shot.sheddingTears[0];
  ASSERT_TRUE(tear.region);
  EXPECT_LT(tear.region->mesh.triangleCount(), shot.assets[0].gltf->primitives[tear.primitive].mesh.triangleCount() / 10)
      << "an extracted region, not the face";
  EXPECT_EQ(findMesh(buildFrame(shot, 1), "shedding tear"), nullptr);
  std::vector<Vec3> previous;
  size_t previousTriangles = 0;
  for (int f = 2; f <= 5; ++f) {
    const Frame frame = buildFrame(shot, f);
    const MeshInstance* mesh = findMesh(frame, "shedding tear");
    ASSERT_NE(mesh, nullptr) << "frame " << f;
    EXPECT_EQ(mesh->materialId, uint32_t(shot.findMaterial("water")));
    EXPECT_FALSE(mesh->moves()) << "no shutter";
    EXPECT_GT(mesh->mesh.triangleCount(), previousTriangles) << "frame " << f;
    // The shorter tear's rows (base grid and top, all but its last row) start the longer tear's
    // vertex arrays.
    const SheddingTearStrip strip = stripAt(shot, f);
    EXPECT_NEAR(strip.length, 0.002f + 0.05f * float(f - 2) / 24.0f, 1e-6f);
    if (!previous.empty()) {
      const size_t rows = previous.size() / 8;  // 2 * 5 - 2 vertices per row
      for (size_t v = 0; v < (rows - 1) * 5; ++v) ASSERT_EQ(mesh->mesh.positions[v], previous[v]) << "base " << v;
      const size_t topStart = size_t(strip.rows) * 5, previousTop = rows * 5;
      for (size_t v = 0; v < (rows - 1) * 3; ++v)
        ASSERT_EQ(mesh->mesh.positions[topStart + v], previous[previousTop + v]) << "top " << v;
    }
    previous = mesh->mesh.positions;
    previousTriangles = mesh->mesh.triangleCount();
  }
}

TEST(SheddingTearShot, ClosedOutwardAndFiniteOnEveryFrame) {
  const Shot shot = loadShot(writeShot("shed_closed.json", ictFaceShot(kTear)));
  for (int f = 2; f <= 5; ++f) {
    const Frame frame = buildFrame(shot, f);
    const MeshInstance* mesh = findMesh(frame, "shedding tear");
    ASSERT_NE(mesh, nullptr);
    EXPECT_EQ(findMeshDefect(mesh->mesh), "") << "frame " << f << ": no NaN, normals per vertex";
    EXPECT_EQ(findClosedMeshDefect(mesh->mesh), "") << "frame " << f;
    EXPECT_GT(signedVolume(mesh->mesh), 0.0) << "frame " << f;
  }
}

TEST(SheddingTearShot, FollowsTheDeformingFace) {
  const std::string smile = R"("blendshapes": {"cheekRaiser_R": {"keys": [[1, 0], [5, 1]], "interpolation": "linear"}})";
  const Shot shot = loadShot(writeShot("shed_smile.json", ictFaceShot(kTear, "", smile)));
  const Shot still = loadShot(writeShot("shed_still.json", ictFaceShot(kTear)));
  for (int f = 2; f <= 5; ++f) {
    const Frame frame = buildFrame(shot, f);
    const MeshInstance* tear = findMesh(frame, "shedding tear");
    ASSERT_NE(tear, nullptr);
    const SkinDistances d = distancesToSkin(tear->mesh, skinOf(frame, shot).mesh, stripAt(shot, f), 2e-5f);
    EXPECT_GE(d.lowest, 0.0f) << "frame " << f;
    EXPECT_LT(d.baseError, 1e-6f) << "frame " << f << ": the base is baseOffset above the posed skin";
    const Frame stillFrame = buildFrame(still, f);
    const MeshInstance* unmoved = findMesh(stillFrame, "shedding tear");
    ASSERT_EQ(unmoved->mesh.positions.size(), tear->mesh.positions.size()) << "the same strip";
    if (f > 2) {
      float moved = 0.0f;
      for (size_t v = 0; v < tear->mesh.positions.size(); ++v)
        moved = std::max(moved, (tear->mesh.positions[v] - unmoved->mesh.positions[v]).norm());
      EXPECT_GT(moved, 1e-4f) << "frame " << f << ": the raised cheek carries the tear";
    }
  }
}

const std::string kDetail =
    R"(, "details": [{"pattern": "cheek", "alpha": 1, "beta": 2, "asset": "face", "part": "M_Face",
       "center": [-0.0345, -0.0018, 0.0995], "extent": [0.01, 0.008], "innerRadius": 0.4, "scale": 0.0005,
       "coordinateScale": 1000, "startFrame": 2, "endFrame": 5}])";

TEST(SheddingTearShot, FollowsTheSkinDetail) {
  const Shot shot = loadShot(writeShot("shed_detail.json", ictFaceShot(kTear + kDetail)));
  const Shot plain = loadShot(writeShot("shed_plain.json", ictFaceShot(kTear)));
  const Frame frame = buildFrame(shot, 4);
  const MeshInstance* tear = findMesh(frame, "shedding tear");
  const Frame plainFrame = buildFrame(plain, 4);
  const MeshInstance* undetailed = findMesh(plainFrame, "shedding tear");
  ASSERT_NE(tear, nullptr);
  ASSERT_NE(undetailed, nullptr);
  const SkinDistances d = distancesToSkin(tear->mesh, skinOf(frame, shot).mesh, stripAt(shot, 4), 2e-5f);
  EXPECT_GE(d.lowest, 0.0f);
  EXPECT_LT(d.baseError, 1e-6f) << "the base sits on the wrinkled skin";
  float moved = 0.0f;
  for (size_t v = 0; v < tear->mesh.positions.size(); ++v)
    moved = std::max(moved, (tear->mesh.positions[v] - undetailed->mesh.positions[v]).norm());
  EXPECT_GT(moved, 5e-5f) << "the wrinkles move the tear's base";
}

TEST(SheddingTearShot, LiesOnTheSkinRefinedUnderADetail) {
  std::string refined = kDetail;
  refined.replace(refined.find(R"("endFrame": 5)"), 13, R"("endFrame": 5, "subdivision": {"levels": 1})");
  const Shot shot = loadShot(writeShot("shed_refined.json", ictFaceShot(kTear + refined)));
  const Shot plain = loadShot(writeShot("shed_unrefined.json", ictFaceShot(kTear + kDetail)));
  const size_t primitive = shot.sheddingTears[0].primitive;
  ASSERT_GT(shot.assets[0].gltf->primitives[primitive].mesh.triangleCount(),
            plain.assets[0].gltf->primitives[primitive].mesh.triangleCount())
      << "the face is refined under the detail";
  EXPECT_GT(shot.sheddingTears[0].region->mesh.triangleCount(), plain.sheddingTears[0].region->mesh.triangleCount())
      << "the tear's region is taken from the refined face";
  const Frame frame = buildFrame(shot, 4);
  const MeshInstance* tear = findMesh(frame, "shedding tear");
  ASSERT_NE(tear, nullptr);
  const SkinDistances d = distancesToSkin(tear->mesh, skinOf(frame, shot).mesh, stripAt(shot, 4), 2e-5f);
  EXPECT_GE(d.lowest, 0.0f);
  EXPECT_LT(d.baseError, 1e-6f);
}

TEST(SheddingTearShot, MovesWithTheSkinDuringTheShutter) {
  const std::string smile = R"("blendshapes": {"cheekRaiser_R": {"keys": [[1, 0], [5, 1]], "interpolation": "linear"}})";
  const std::string shutter = R"(, "shutter": {"open": -0.25, "close": 0.25})";
  const Shot shot = loadShot(writeShot("shed_blur.json", ictFaceShot(kTear, shutter, smile)));
  const Frame frame = buildFrame(shot, 4);
  const MeshInstance* tear = findMesh(frame, "shedding tear");
  ASSERT_NE(tear, nullptr);
  ASSERT_TRUE(tear->moves());
  ASSERT_EQ(tear->positionsAtClose.size(), tear->mesh.positions.size());
  ASSERT_EQ(tear->normalsAtClose.size(), tear->mesh.positions.size());
  // The strip of the shutter-open time on the skin at shutter close.
  const MeshInstance& skin = skinOf(frame, shot);
  ASSERT_TRUE(skin.moves());
  TriangleMesh atClose = tear->mesh;
  atClose.positions = tear->positionsAtClose;
  const SheddingTearStrip strip = stripAt(shot, 3.75);
  const SkinDistances d = distancesToSkin(atClose, skinMesh(skin, true), strip, 2e-5f);
  EXPECT_LT(d.baseError, 1e-6f);
  EXPECT_GE(d.lowest, 0.0f);
  // A still face: the tear does not move within the shutter.
  const Shot still = loadShot(writeShot("shed_blur_still.json", ictFaceShot(kTear, shutter)));
  EXPECT_FALSE(findMesh(buildFrame(still, 4), "shedding tear")->moves());
}

TEST(SheddingTearShot, SameSeedSameTearOtherSeedOtherNoise) {
  const Shot a = loadShot(writeShot("seed_a.json", ictFaceShot(kTear)));
  const Shot b = loadShot(writeShot("seed_b.json", ictFaceShot(kTear)));
  const Shot c = loadShot(writeShot("seed_c.json", ictFaceShot(tearWith(R"("seed": 7)", R"("seed": 8)"))));
  const Shot smooth = loadShot(writeShot("seed_d.json", ictFaceShot(tearWith(R"("skinRoughness": 0.3)", R"("skinRoughness": 0)"))));
  const auto positions = [](const Shot& shot) { return findMesh(buildFrame(shot, 5), "shedding tear")->mesh.positions; };
  EXPECT_EQ(positions(a), positions(b));
  EXPECT_NE(positions(a), positions(c));
  EXPECT_NE(positions(a), positions(smooth)) << "skinRoughness raises bumps";
}

TEST(SheddingTearShot, BadTearsGetExactMessages) {
  const auto bad = [](const std::string& name, const std::string& from, const std::string& to, const std::string& error) {
    expectSingleError(name, ictFaceShot(tearWith(from, to)), error);
  };
  bad("type.json", R"("shedding")", R"("sheding")", "/tears/0/type: unknown tear type 'sheding'; did you mean 'shedding'?");
  bad("one_point.json", kPath, "[[-0.0345, 0.004, 0.0985]]",
      "/tears/0/path: expected an array of two or more points [[x, y, z], ...], found an array of 1 element");
  bad("point.json", kPath, "[[-0.0345, 0.004, 0.0985], [-0.0345, -0.0018]]",
      "/tears/0/path/1: expected [x, y, z] (an array of 3 numbers), found an array of 2 elements");
  bad("key.json", R"("width")", R"("widht")", "/tears/0/widht: unknown key 'widht'; did you mean 'width'?");
  bad("width.json", R"("width": 0.004)", R"("width": 0)", "/tears/0/width: expected a number > 0, found 0");
  bad("roughness.json", R"("skinRoughness": 0.3)", R"("skinRoughness": 2)",
      "/tears/0/skinRoughness: expected a number in [0, 1], found 2");
  bad("columns.json", R"("acrossSamples": 5)", R"("acrossSamples": 2)",
      "/tears/0/acrossSamples: expected an integer in [3, 101], found 2");
  bad("material.json", R"("material": "water", )", "",
      "/tears/0: missing required key 'material' (the name of a material in 'materials')");
  bad("off_skin.json", "[-0.0345, -0.0018, 0.0995]", "[-0.0345, -0.0018, 0.1495]",
      "/tears/0/path/1: path point 1 is 0.0344 m from the skin of part 'M_Face' (its nearest skin point at the first "
      "frame is [-0.0094, 0.0014, 0.1262]); path points must lie within 0.01 m of it");
  bad("grid.json", R"("sampleSpacing": 0.001)", R"("sampleSpacing": 0.000001)",
      "/tears/0: the path (0.0201 m long) with sampleSpacing 1e-06 and acrossSamples 5 makes about 100456 grid "
      "points; at most 50000 (use a larger sampleSpacing or fewer acrossSamples)");
  bad("same.json", "[-0.0345, -0.0018, 0.0995]", "[-0.0345, 0.004, 0.0985]",
      "/tears/0/path/1: path point 1 snaps to the same skin point as path point 0; give distinct points");
}

// Two 2 cm squares side by side in z = 0, meshes "A" (x in [0, 2 cm]) and "B" (x in [2, 4 cm]),
// both of part "skin".
std::filesystem::path writeTwoSquaresGlb() {
  test::GltfBuilder b;
  for (const float x0 : {0.0f, 0.02f}) {
    const float x1 = x0 + 0.02f;
    b.addMesh(x0 == 0.0f ? "A" : "B", {x0, 0, 0, x1, 0, 0, x1, 0.02f, 0, x0, 0, 0, x1, 0.02f, 0, x0, 0.02f, 0}, {}, {});
    b.json()["meshes"].back()["primitives"][0]["extras"] = {{"part", "skin"}};
  }
  b.json()["scenes"] = {{{"nodes", {0, 1}}}};
  b.json()["nodes"] = {{{"name", "a"}, {"mesh", 0}}, {{"name", "b"}, {"mesh", 1}}};
  const auto path = writeShot("placeholder.json", "").parent_path() / "two_squares.glb";
  b.write(path);
  return path;
}

TEST(SheddingTearShot, PathMustStayOnOnePrimitive) {
  const std::string shot = "{\"version\": 1, \"frames\": {\"start\": 1, \"end\": 1}, \"output\": \"o.exr\","
      " \"render\": {\"width\": 8, \"height\": 8, \"spp\": 1},"
      " \"camera\": {\"position\": [0, 0, 1], \"lookAt\": [0, 0, 0], \"fov\": 30},"
      " \"materials\": {\"water\": {\"type\": \"water\"}},"
      " \"assets\": [{\"name\": \"squares\", \"file\": \"" + writeTwoSquaresGlb().string() + "\"}],"
      " \"tears\": [{\"type\": \"shedding\", \"asset\": \"squares\", \"part\": \"skin\", \"startFrame\": 1,"
      " \"material\": \"water\", \"path\": PATH}]}";
  const auto with = [&](const std::string& path) {
    std::string s = shot;
    s.replace(s.find("PATH"), 4, path);
    return s;
  };
  const Shot ok = loadShot(writeShot("one_square.json", with("[[0.005, 0.018, 0.001], [0.006, 0.002, 0.001]]")));
  EXPECT_EQ(ok.assets[0].gltf->primitives[ok.sheddingTears[0].primitive].name, "A/skin");
  expectSingleError("two_squares.json", with("[[0.01, 0.018, 0.001], [0.03, 0.002, 0.001]]"),
                    "/tears/0/path/1: path point 1 snaps to primitive 'B/skin' of part 'skin' but path point 0 to "
                    "'A/skin'; a shedding tear runs over one primitive");
}

}  // namespace shedding_tear_shot_test
}  // namespace lacrima
