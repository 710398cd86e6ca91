// Small glTF files written by the test: node hierarchies, cameras, materials, accessor formats
// (uint16 indices, normalized uint8 uvs, byteStride, sparse uint8 indices, zero targets).
#include <gtest/gtest.h>

#include "geometry/glb_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"

namespace lacrima {
namespace gltf_synthetic_test {

using nlohmann::json;

// A unit quad in the z = 0 plane facing +z, with:
//  - positions interleaved with padding (byteStride 16),
//  - uint16 indices, normalized uint8 uvs,
//  - target "lift": sparse, uint8 indices, moves vertex 2 by +z 0.5 and vertex 0 by 0 (dropped),
//  - target "none": no bufferView, no sparse block (all zeros),
//  - target "dense": dense deltas, +x 0.25 on vertex 1 only.
struct QuadFile {
  json gltf;
  std::vector<unsigned char> bin;
};

QuadFile makeQuadFile() {
  QuadFile f;
  std::vector<float> interleaved;  // x y z pad
  for (const auto& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)})
    interleaved.insert(interleaved.end(), {p.x(), p.y(), p.z(), -99.0f});
  const size_t positions = test::appendValues(f.bin, interleaved);
  const size_t indices = test::appendValues(f.bin, std::vector<uint16_t>{0, 1, 2, 0, 2, 3});
  const size_t uvs = test::appendValues(f.bin, std::vector<uint8_t>{0, 0, 255, 0, 255, 255, 0, 255});
  const size_t sparseIdx = test::appendValues(f.bin, std::vector<uint8_t>{0, 2});
  const size_t sparseVal = test::appendValues(f.bin, std::vector<float>{0, 0, 0, 0, 0, 0.5f});
  const size_t dense = test::appendValues(f.bin, std::vector<float>{0, 0, 0, 0.25f, 0, 0, 0, 0, 0, 0, 0, 0});
  f.gltf = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0, 3}}}}},
      {"nodes",
       {{{"name", "root"}, {"translation", {1, 2, 3}}, {"children", {1, 2}}},
        {{"name", "quad"}, {"mesh", 0}, {"rotation", {0, 0, std::sqrt(0.5), std::sqrt(0.5)}}, {"scale", {2, 1, 1}}},
        {{"name", "cam"}, {"camera", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}},
        {{"name", "mirror"}, {"mesh", 0}, {"scale", {-1, 1, 1}}}}},
      {"cameras", {{{"name", "front"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"aspectRatio", 1.5}, {"znear", 0.01}}}}}},
      {"materials",
       {{{"name", "water"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.2, 0.3, 1.0}}, {"roughnessFactor", 0.05}, {"metallicFactor", 0.0}}},
         {"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
           {"KHR_materials_ior", {{"ior", 1.337}}},
           {"KHR_materials_volume", {{"thicknessFactor", 0.001}}}}}}}},
      {"meshes",
       {{{"name", "Quad"},
         {"extras", {{"targetNames", {"lift", "none", "dense"}}}},
         {"primitives",
          {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 2}}},
            {"indices", 1},
            {"material", 0},
            {"targets", {{{"POSITION", 3}}, {{"POSITION", 4}}, {{"POSITION", 5}}}}}}}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
        {{"bufferView", 2}, {"componentType", 5121}, {"normalized", true}, {"count", 4}, {"type", "VEC2"}},
        {{"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
         {"sparse", {{"count", 2}, {"indices", {{"bufferView", 3}, {"componentType", 5121}}}, {"values", {{"bufferView", 4}}}}}},
        {{"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
        {{"bufferView", 5}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", positions}, {"byteLength", 64}, {"byteStride", 16}},
        {{"buffer", 0}, {"byteOffset", indices}, {"byteLength", 12}},
        {{"buffer", 0}, {"byteOffset", uvs}, {"byteLength", 8}},
        {{"buffer", 0}, {"byteOffset", sparseIdx}, {"byteLength", 2}},
        {{"buffer", 0}, {"byteOffset", sparseVal}, {"byteLength", 24}},
        {{"buffer", 0}, {"byteOffset", dense}, {"byteLength", 48}}}},
      {"buffers", {{{"byteLength", 0}}}},
  };
  while (f.bin.size() % 4 != 0) f.bin.push_back(0);
  f.gltf["buffers"][0]["byteLength"] = f.bin.size();
  return f;
}

std::filesystem::path writeQuad(const QuadFile& f, const std::string& name) {
  const std::filesystem::path path = test::testOutputDir() / name;
  test::writeBytes(path, test::makeGlb(f.gltf, f.bin));
  return path;
}

GltfAsset loadQuad(const std::string& name = "quad.glb") { return loadGltfAsset(writeQuad(makeQuadFile(), name)); }

TEST(GltfSynthetic, AppliesTheNodeHierarchy) {
  const GltfAsset asset = loadQuad();
  ASSERT_EQ(asset.primitives.size(), 2u);  // the quad node and its mirror instance
  const GltfPrimitive& quad = asset.primitives[0];
  EXPECT_EQ(quad.name, "Quad/water");  // no extras.part: the material name
  EXPECT_EQ(quad.part, "water");
  // world = T(1,2,3) * Rz(90 deg) * S(2,1,1): (x,y,z) -> (1 - y, 2 + 2x, 3 + z)
  const std::vector<Vec3> expected = {Vec3(1, 2, 3), Vec3(1, 4, 3), Vec3(0, 4, 3), Vec3(0, 2, 3)};
  for (size_t v = 0; v < 4; ++v) EXPECT_LT((quad.mesh.positions[v] - expected[v]).norm(), 1e-6f) << v;
  for (const Vec3& n : quad.mesh.normals) EXPECT_LT((n - Vec3(0, 0, 1)).norm(), 1e-6f);
  EXPECT_LT((quad.nodeTransform * Vec3(1, 0, 0) - expected[1]).norm(), 1e-6f);
}

TEST(GltfSynthetic, MirroredInstanceKeepsWindingAndNormalsConsistent) {
  const GltfAsset asset = loadQuad();
  const TriangleMesh& mirror = asset.primitives[1].mesh;
  for (size_t i = 0; i < mirror.indices.size(); i += 3) {
    const Vec3& a = mirror.positions[mirror.indices[i]];
    const Vec3 geometric = (mirror.positions[mirror.indices[i + 1]] - a).cross(mirror.positions[mirror.indices[i + 2]] - a);
    EXPECT_GT(geometric.dot(mirror.normals[mirror.indices[i]]), 0.0f);
    EXPECT_GT(geometric.z(), 0.0f);  // a mirror in x keeps the quad facing +z
  }
}

TEST(GltfSynthetic, ReadsUvsIndicesAndMaterial) {
  const GltfAsset asset = loadQuad();
  const GltfPrimitive& quad = asset.primitives[0];
  EXPECT_EQ(quad.mesh.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  ASSERT_EQ(quad.mesh.uvs.size(), 4u);
  EXPECT_EQ(quad.mesh.uvs[2], Vec2(1.0f, 1.0f));  // normalized uint8 255 -> 1
  EXPECT_EQ(quad.mesh.uvs[1], Vec2(1.0f, 0.0f));
  const GltfMaterialInfo& m = quad.material;
  EXPECT_EQ(m.name, "water");
  EXPECT_TRUE(m.hasPbrFactors);
  EXPECT_TRUE((m.baseColor - Color(0.1f, 0.2f, 0.3f)).abs().maxCoeff() < 1e-6f);
  EXPECT_FLOAT_EQ(m.roughness, 0.05f);
  EXPECT_FLOAT_EQ(m.metallic, 0.0f);
  EXPECT_FLOAT_EQ(m.transmission, 1.0f);
  EXPECT_FLOAT_EQ(m.ior, 1.337f);
  EXPECT_TRUE(m.hasVolume);
}

TEST(GltfSynthetic, MorphTargetsAreSparseAndTransformedByTheLinearPart) {
  const GltfAsset asset = loadQuad();
  EXPECT_EQ(asset.targetNames, (std::vector<std::string>{"lift", "none", "dense"}));
  const GltfPrimitive& quad = asset.primitives[0];
  ASSERT_EQ(quad.targets.size(), 3u);
  // "lift": the zero delta on vertex 0 is dropped; +z stays +z under Rz and S(2,1,1).
  EXPECT_EQ(quad.targets[0].vertices, std::vector<uint32_t>{2});
  EXPECT_LT((quad.targets[0].deltas[0] - Vec3(0, 0, 0.5f)).norm(), 1e-6f);
  EXPECT_TRUE(quad.targets[1].vertices.empty());
  // "dense": +x 0.25 becomes +y 0.5 (scaled by 2 in x, then rotated 90 deg about z).
  EXPECT_EQ(quad.targets[2].vertices, std::vector<uint32_t>{1});
  EXPECT_LT((quad.targets[2].deltas[0] - Vec3(0, 0.5f, 0)).norm(), 1e-6f);

  const TriangleMesh lifted = applyMorphTargets(quad, {1.0f, 0.0f, 0.0f});
  EXPECT_LT((lifted.positions[2] - Vec3(0, 4, 3.5f)).norm(), 1e-6f);
  EXPECT_NE(lifted.normals, quad.mesh.normals);
}

TEST(GltfSynthetic, ReadsPerspectiveCameras) {
  const GltfAsset asset = loadQuad();
  ASSERT_EQ(asset.cameras.size(), 1u);
  const GltfCamera& cam = asset.cameras[0];
  EXPECT_EQ(cam.name, "front");
  EXPECT_FLOAT_EQ(cam.yfovRadians, 0.5f);
  EXPECT_FLOAT_EQ(cam.aspectRatio, 1.5f);
  EXPECT_LT((cam.cameraToAsset.translation() - Vec3(1, 2, 8)).norm(), 1e-6f);  // root T(1,2,3) * matrix T(0,0,5)
  EXPECT_EQ(asset.nodeNames, (std::vector<std::string>{"root", "quad", "cam", "mirror"}));
  EXPECT_NE(describeGltfAsset(asset).find("front: yfov 28.6 deg"), std::string::npos) << describeGltfAsset(asset);
}

TEST(GltfSynthetic, NonIndexedPrimitivesUseConsecutiveTriples) {
  QuadFile f = makeQuadFile();
  f.gltf["meshes"][0]["primitives"][0].erase("indices");
  f.gltf["accessors"][0]["count"] = 3;
  for (int t = 3; t <= 5; ++t) f.gltf["accessors"][t]["count"] = 3;
  f.gltf["accessors"][2]["count"] = 3;
  f.gltf["accessors"][3]["sparse"]["count"] = 1;  // only vertex 0 (a zero delta)
  const GltfAsset asset = loadGltfAsset(writeQuad(f, "quad_nonindexed.glb"));
  EXPECT_EQ(asset.primitives[0].mesh.indices, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(GltfSynthetic, AsciiGltfWithDataUriLoads) {
  QuadFile f = makeQuadFile();
  static const char* kBase64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string encoded;
  for (size_t i = 0; i < f.bin.size(); i += 3) {
    const uint32_t n = (uint32_t(f.bin[i]) << 16) | (i + 1 < f.bin.size() ? uint32_t(f.bin[i + 1]) << 8 : 0u) |
                       (i + 2 < f.bin.size() ? uint32_t(f.bin[i + 2]) : 0u);
    encoded += kBase64[(n >> 18) & 63];
    encoded += kBase64[(n >> 12) & 63];
    encoded += i + 1 < f.bin.size() ? kBase64[(n >> 6) & 63] : '=';
    encoded += i + 2 < f.bin.size() ? kBase64[n & 63] : '=';
  }
  f.gltf["buffers"][0]["uri"] = "data:application/octet-stream;base64," + encoded;
  const std::filesystem::path path = test::testOutputDir() / "quad.gltf";
  const std::string text = f.gltf.dump(1);
  test::writeBytes(path, std::vector<unsigned char>(text.begin(), text.end()));
  const GltfAsset asset = loadGltfAsset(path);
  ASSERT_EQ(asset.primitives.size(), 2u);
  EXPECT_EQ(asset.primitives[0].targets[0].vertices, std::vector<uint32_t>{2});
}

}  // namespace gltf_synthetic_test
}  // namespace lacrima
