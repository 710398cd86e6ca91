// The committed ICT face (scenes/assets/ict-face/ict_face.glb) through loadGltfAsset, checked
// against the asset's README and against an independent parse of the GLB's JSON and BIN chunks.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <map>

#include "geometry/glb_support.hpp"
#include "lacrima/io/gltf_asset.hpp"

namespace lacrima {
namespace gltf_face_test {

using nlohmann::json;

// Loaded once: every test reads the same asset.
class IctFace : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto start = std::chrono::steady_clock::now();
    asset_ = new GltfAsset(loadGltfAsset(test::faceAssetPath()));
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("[ info     ] ict_face.glb loaded in %.1f ms\n", ms);
    raw_ = new test::GlbParts(test::splitGlb(test::readBytes(test::faceAssetPath())));
  }
  static void TearDownTestSuite() {
    delete asset_;
    delete raw_;
  }

  static const GltfPrimitive& part(const std::string& name) {
    for (const GltfPrimitive& p : asset_->primitives)
      if (p.part == name) return p;
    throw std::runtime_error("no part " + name);
  }

  // Floats of an accessor's bufferView, read straight from the BIN chunk (tightly packed).
  static std::vector<float> rawFloats(int bufferView) {
    const json& view = raw_->json["bufferViews"][bufferView];
    const size_t offset = view.value("byteOffset", size_t(0)), length = view["byteLength"];
    std::vector<float> out(length / 4);
    std::memcpy(out.data(), raw_->bin.data() + offset, out.size() * 4);
    return out;
  }
  static std::vector<uint32_t> rawU32(int bufferView) {
    const json& view = raw_->json["bufferViews"][bufferView];
    const size_t offset = view.value("byteOffset", size_t(0)), length = view["byteLength"];
    std::vector<uint32_t> out(length / 4);
    std::memcpy(out.data(), raw_->bin.data() + offset, out.size() * 4);
    return out;
  }

  static GltfAsset* asset_;
  static test::GlbParts* raw_;
};
GltfAsset* IctFace::asset_ = nullptr;
test::GlbParts* IctFace::raw_ = nullptr;

TEST_F(IctFace, HasTheDocumentedPrimitivesAndTargets) {
  const std::vector<std::string> parts = {"M_Face",        "M_BackHead",     "M_GumsTongue",  "M_Teeth",
                                          "M_ScleraLeft",  "M_IrisLeft",     "M_ScleraRight", "M_IrisRight",
                                          "M_LacrimalFluid", "M_EyeBlend",   "M_EyeOcclusion", "M_EyeLashes"};
  ASSERT_EQ(asset_->primitives.size(), 12u);
  for (size_t i = 0; i < parts.size(); ++i) {
    EXPECT_EQ(asset_->primitives[i].part, parts[i]);
    EXPECT_EQ(asset_->primitives[i].name, "ICTFace/" + parts[i]);
    EXPECT_EQ(asset_->primitives[i].targets.size(), 57u);
  }
  EXPECT_EQ(part("M_Face").mesh.vertexCount(), 9547u);
  ASSERT_EQ(asset_->targetNames.size(), 57u);
  EXPECT_EQ(asset_->targetNames.front(), "browDown_L");
  EXPECT_GE(asset_->findTarget("jawOpen"), 0);
  EXPECT_GE(asset_->findTarget("PupilDilate_L"), 0);
  EXPECT_EQ(asset_->findTarget("jawopen"), -1);  // exact names only
  EXPECT_TRUE(asset_->cameras.empty());
  EXPECT_EQ(asset_->nodeNames, std::vector<std::string>{"ICTFace"});
}

TEST_F(IctFace, MeshesAreValidWithUnitNormalsAndUvs) {
  for (const GltfPrimitive& p : asset_->primitives) {
    SCOPED_TRACE(p.name);
    EXPECT_EQ(findMeshDefect(p.mesh), "");
    ASSERT_EQ(p.mesh.normals.size(), p.mesh.vertexCount());
    EXPECT_EQ(p.mesh.uvs.size(), p.mesh.vertexCount());
    for (const Vec3& n : p.mesh.normals) ASSERT_NEAR(n.norm(), 1.0f, 1e-5f);
    EXPECT_EQ(p.weldMap.size(), p.mesh.vertexCount());
    EXPECT_TRUE(p.nodeTransform.matrix().isIdentity());
  }
}

TEST_F(IctFace, BoundingBoxMatchesReadmeInMetres) {
  Eigen::AlignedBox3f box;
  for (const GltfPrimitive& p : asset_->primitives) box.extend(computeBounds(p.mesh));
  const float mm = 1e-3f;
  EXPECT_NEAR(box.min().x(), -0.124f, mm);
  EXPECT_NEAR(box.max().x(), 0.124f, mm);
  EXPECT_NEAR(box.min().y(), -0.193f, mm);
  EXPECT_NEAR(box.max().y(), 0.145f, mm);
  EXPECT_NEAR(box.min().z(), -0.092f, mm);
  EXPECT_NEAR(box.max().z(), 0.131f, mm);
}

TEST_F(IctFace, PositionsMatchTheRawAccessorBytesAndMinMax) {
  const json& primitives = raw_->json["meshes"][0]["primitives"];
  for (size_t i = 0; i < primitives.size(); ++i) {
    const json& accessor = raw_->json["accessors"][primitives[i]["attributes"]["POSITION"].get<int>()];
    const std::vector<float> raw = rawFloats(accessor["bufferView"]);
    const TriangleMesh& mesh = asset_->primitives[i].mesh;
    SCOPED_TRACE(mesh.name);
    ASSERT_EQ(raw.size(), 3 * mesh.vertexCount());
    for (size_t v : {size_t(0), mesh.vertexCount() / 2, mesh.vertexCount() - 1})
      EXPECT_EQ(mesh.positions[v], Vec3(raw[3 * v], raw[3 * v + 1], raw[3 * v + 2])) << "vertex " << v;
    const Eigen::AlignedBox3f box = computeBounds(mesh);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(box.min()[c], accessor["min"][c].get<double>(), 1e-7);
      EXPECT_NEAR(box.max()[c], accessor["max"][c].get<double>(), 1e-7);
    }
  }
}

TEST_F(IctFace, IndicesMatchTheRawAccessor) {
  const json& primitive = raw_->json["meshes"][0]["primitives"][0];
  const json& accessor = raw_->json["accessors"][primitive["indices"].get<int>()];
  const std::vector<uint32_t> raw = rawU32(accessor["bufferView"]);
  EXPECT_EQ(part("M_Face").mesh.indices, raw);
  EXPECT_EQ(part("M_Face").mesh.triangleCount(), 18460u);
}

TEST_F(IctFace, FaceIsYUpLookingAlongPlusZ) {
  const TriangleMesh& face = part("M_Face").mesh;
  const auto tip = std::max_element(face.positions.begin(), face.positions.end(),
                                    [](const Vec3& a, const Vec3& b) { return a.z() < b.z(); });
  const size_t v = size_t(tip - face.positions.begin());
  EXPECT_NEAR(tip->x(), 0.0f, 0.005f);            // the nose tip is on the symmetry plane
  EXPECT_GT(face.normals[v].z(), 0.7f);           // and its normal faces forward: outward normals
}

TEST_F(IctFace, JawOpenDeltasMatchTheRawSparseAccessor) {
  const int k = asset_->findTarget("jawOpen");
  ASSERT_GE(k, 0);
  const json& accessor = raw_->json["accessors"][raw_->json["meshes"][0]["primitives"][0]["targets"][k]["POSITION"].get<int>()];
  ASSERT_FALSE(accessor.contains("bufferView"));
  const int count = accessor["sparse"]["count"];
  const std::vector<uint32_t> indices = rawU32(accessor["sparse"]["indices"]["bufferView"]);
  const std::vector<float> values = rawFloats(accessor["sparse"]["values"]["bufferView"]);
  std::map<uint32_t, Vec3> expected;
  for (int i = 0; i < count; ++i) {
    const Vec3 d(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
    if (!d.isZero(0.0f)) expected[indices[i]] = d;
  }
  const SparseDelta& loaded = part("M_Face").targets[size_t(k)];
  ASSERT_EQ(loaded.vertices.size(), expected.size());
  ASSERT_GT(loaded.vertices.size(), 1000u);
  ASSERT_TRUE(std::is_sorted(loaded.vertices.begin(), loaded.vertices.end()));
  size_t i = 0;
  for (const auto& [vertex, delta] : expected) {
    EXPECT_EQ(loaded.vertices[i], vertex);
    EXPECT_EQ(loaded.deltas[i], delta);
    ++i;
  }
  // The jaw opens downwards (+Y is up): the largest displacement points down.
  float lowest = 0.0f;
  for (const Vec3& d : loaded.deltas) lowest = std::min(lowest, d.y());
  EXPECT_LT(lowest, -0.02f);
}

TEST_F(IctFace, MorphWithWeightOneIsNeutralPlusDelta) {
  const int k = asset_->findTarget("jawOpen");
  const GltfPrimitive& face = part("M_Face");
  std::vector<float> weights(asset_->targetNames.size(), 0.0f);
  weights[size_t(k)] = 1.0f;
  const TriangleMesh morphed = applyMorphTargets(face, weights);
  const SparseDelta& target = face.targets[size_t(k)];
  std::vector<bool> moved(face.mesh.vertexCount(), false);
  for (size_t i = 0; i < target.vertices.size(); ++i) {
    const uint32_t v = target.vertices[i];
    moved[v] = true;
    EXPECT_EQ(morphed.positions[v], Vec3(face.mesh.positions[v] + target.deltas[i])) << "vertex " << v;
  }
  size_t untouched = 0;
  for (size_t v = 0; v < moved.size(); ++v) {
    if (moved[v]) continue;
    ++untouched;
    EXPECT_EQ(morphed.positions[v], face.mesh.positions[v]) << "vertex " << v;
  }
  EXPECT_GT(untouched, 0u);
  EXPECT_EQ(morphed.indices, face.mesh.indices);
  EXPECT_EQ(morphed.uvs, face.mesh.uvs);
  EXPECT_NE(morphed.normals, face.mesh.normals);  // normals were recomputed for the open jaw
  EXPECT_EQ(findMeshDefect(morphed), "");
}

TEST_F(IctFace, MorphWithZeroWeightsIsBitwiseNeutral) {
  for (const GltfPrimitive& p : asset_->primitives) {
    for (const std::vector<float>& weights : {std::vector<float>(57, 0.0f), std::vector<float>{}}) {
      const TriangleMesh m = applyMorphTargets(p, weights);
      EXPECT_EQ(m.positions, p.mesh.positions);
      EXPECT_EQ(m.normals, p.mesh.normals);
    }
  }
}

TEST_F(IctFace, MorphIsLinearInTheWeights) {
  const GltfPrimitive& face = part("M_Face");
  const int a = asset_->findTarget("jawOpen"), b = asset_->findTarget("eyeBlink_L");
  ASSERT_LT(b, a);
  std::vector<float> weights(static_cast<size_t>(a + 1), 0.0f);  // shorter than 57: the rest count as 0
  weights[size_t(a)] = 0.5f;
  weights[size_t(b)] = -0.25f;
  const TriangleMesh morphed = applyMorphTargets(face, weights);
  std::vector<Vec3> expected = face.mesh.positions;
  for (int k : {a, b})
    for (size_t i = 0; i < face.targets[size_t(k)].vertices.size(); ++i)
      expected[face.targets[size_t(k)].vertices[i]] += weights[size_t(k)] * face.targets[size_t(k)].deltas[i];
  for (size_t v = 0; v < expected.size(); ++v) ASSERT_LT((morphed.positions[v] - expected[v]).norm(), 1e-7f);
}

TEST_F(IctFace, EyeballsMoveOnlyWithPupilDilation) {
  for (const char* name : {"M_ScleraLeft", "M_ScleraRight"})
    for (const SparseDelta& t : part(name).targets) EXPECT_TRUE(t.vertices.empty()) << name;
  const GltfPrimitive& iris = part("M_IrisLeft");
  for (size_t k = 0; k < iris.targets.size(); ++k)
    EXPECT_EQ(iris.targets[k].vertices.empty(), asset_->targetNames[k] != "PupilDilate_L") << asset_->targetNames[k];
  // A non-zero weight on a target that does not move a primitive keeps its normals bitwise.
  std::vector<float> weights(57, 0.0f);
  weights[size_t(asset_->findTarget("jawOpen"))] = 1.0f;
  EXPECT_EQ(applyMorphTargets(iris, weights).normals, iris.mesh.normals);
}

TEST_F(IctFace, SeamCopiesShareNormalsBeforeAndAfterMorphing) {
  std::vector<float> weights(57, 0.0f);
  weights[size_t(asset_->findTarget("eyeBlink_R"))] = 1.0f;
  size_t seamVertices = 0;
  for (const GltfPrimitive& p : asset_->primitives) {
    const TriangleMesh morphed = applyMorphTargets(p, weights);
    for (size_t v = 0; v < p.weldMap.size(); ++v) {
      if (p.weldMap[v] == v) continue;
      ++seamVertices;
      ASSERT_EQ(p.mesh.positions[v], p.mesh.positions[p.weldMap[v]]);
      ASSERT_EQ(p.mesh.normals[v], p.mesh.normals[p.weldMap[v]]) << p.name << " vertex " << v;
      ASSERT_EQ(morphed.normals[v], morphed.normals[p.weldMap[v]]) << p.name << " vertex " << v;
    }
  }
  EXPECT_GT(seamVertices, 1000u);  // the face really is split at UV seams
}

TEST_F(IctFace, MaterialsKeepLacrimaDefaultsWithoutPbrFactors) {
  for (const GltfPrimitive& p : asset_->primitives) {
    EXPECT_EQ(p.material.name, p.part);
    EXPECT_FALSE(p.material.hasPbrFactors);
    EXPECT_EQ(p.material.metallic, 0.0f);  // glTF's default would be 1 (metal)
  }
  EXPECT_TRUE(part("M_LacrimalFluid").material.doubleSided);
  EXPECT_FALSE(part("M_Face").material.doubleSided);
}

TEST_F(IctFace, Has68LandmarksOnTheFace) {
  ASSERT_EQ(asset_->landmarks.size(), 68u);
  const json& raw = raw_->json["nodes"][0]["extras"]["landmarks68"];
  for (size_t i = 0; i < 68; ++i) {
    const Landmark& l = asset_->landmarks[i];
    EXPECT_EQ(l.index, int(i));
    EXPECT_EQ(l.primitive, 0);
    EXPECT_EQ(l.vertex, raw[i]["vertex"].get<uint32_t>());
  }
  // 39 and 42 are the inner eye corners, mirror images across x = 0; 36-41 is the subject's
  // right eye, which is at -x for a face looking along +Z with +Y up.
  const auto at = [&](int i) { return part("M_Face").mesh.positions[asset_->landmarks[size_t(i)].vertex]; };
  EXPECT_NEAR(at(39).x(), -at(42).x(), 1e-3f);
  EXPECT_NEAR(at(39).y(), at(42).y(), 1e-3f);
  EXPECT_LT(at(36).x(), at(39).x());
  EXPECT_LT(at(39).x(), 0.0f);
}

// The committed face is a static rig: its JSON has no "animations" array at all.
TEST_F(IctFace, HasNoAnimations) {
  EXPECT_FALSE(raw_->json.contains("animations"));
  EXPECT_TRUE(asset_->animations.empty());
  EXPECT_NE(describeGltfAsset(*asset_).find("animations: 0\n"), std::string::npos);
}

TEST_F(IctFace, DescriptionListsPartsTargetsAndBounds) {
  const std::string text = describeGltfAsset(*asset_);
  for (const char* expected : {"ict_face.glb", "primitives: 12", "M_Face", "9547", "18460", "M_EyeLashes",
                               "morph targets: 57", "jawOpen", "PupilDilate_R", "cameras: 0", "bounds (m): x -0.124..0.124",
                               "landmarks: 68"})
    EXPECT_NE(text.find(expected), std::string::npos) << "missing '" << expected << "' in\n" << text;
  for (const std::string& line : [&] {
         std::vector<std::string> lines;
         size_t start = 0;
         for (size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1)
           lines.push_back(text.substr(start, end - start));
         return lines;
       }())
    EXPECT_LE(line.size(), 110u) << line;
}

}  // namespace gltf_face_test
}  // namespace lacrima
