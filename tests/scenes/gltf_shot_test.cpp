// A tiny glTF written by the test: a camera node and two primitives whose unbound materials are
// mapped automatically (transmissive -> smooth dielectric with the glTF ior, else diffuse).
#include <gtest/gtest.h>

#include <variant>

#include "shot_support.hpp"

namespace lacrima {
namespace gltf_shot_test {

using test::writeShot;

// One triangle (0,0,0), (1,0,0), (0,1,0) used by two primitives; camera "closeup" 2 m along +Z
// of the asset, looking down -Z.
const char* kTinyGltf = R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [0, 1]}],
  "nodes": [{"name": "drop", "mesh": 0}, {"name": "camNode", "camera": 0, "translation": [0, 0, 2]}],
  "cameras": [{"name": "closeup", "type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.01}}],
  "meshes": [{"name": "drop", "primitives": [
    {"attributes": {"POSITION": 0}, "material": 0},
    {"attributes": {"POSITION": 0}, "material": 1}]}],
  "materials": [
    {"name": "tearfilm", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]},
     "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_ior": {"ior": 1.33}}},
    {"name": "paint", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1]}}],
  "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_ior"],
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}]
})";

// Each test writes its own copy of the glTF (ctest may run tests in parallel processes).
std::string tinyShot(const std::string& gltfName, const std::string& camera, const std::string& assetExtra = "") {
  writeShot(gltfName, kTinyGltf);
  return R"({
  "version": 1,
  "frames": {"start": 1, "end": 1},
  "output": "tiny.exr",
  "render": {"width": 16, "height": 16, "spp": 1},
  "camera": )" +
         camera + R"(,
  "assets": [{"name": "tiny", "file": ")" +
         gltfName + R"(",
              "transform": {"translate": [10, 0, 0], "rotate": {"axis": [0, 1, 0], "angle": 90}, "scale": 3})" +
         assetExtra + R"(}]
})";
}

TEST(GltfShot, CameraFromTheAssetFollowsItsTransform) {
  const Shot shot = loadShot(writeShot(
      "tiny_camera.json", tinyShot("tiny_camera.gltf", R"({"gltf": {"asset": "tiny", "camera": "closeup"}})")));
  EXPECT_EQ(shot.camera.kind, ShotCamera::Kind::Gltf);
  const Camera& camera = shot.camera.camera;
  EXPECT_FLOAT_EQ(camera.verticalFovRadians, 0.5f);  // the glTF yfov when the shot gives none
  EXPECT_EQ(camera.lensRadius, 0.0f);
  // Camera at asset (0,0,2): scaled by 3, rotated 90 degrees about Y (+Z -> +X), moved by +10 in X.
  EXPECT_NEAR((camera.cameraToWorld.translation() - Vec3(16, 0, 0)).norm(), 0.0f, 1e-5f);
  // It looks down its -Z, which the rotation turned into -X; the scale does not scale the camera.
  EXPECT_NEAR((camera.cameraToWorld.linear() * Vec3(0, 0, -1) - Vec3(-1, 0, 0)).norm(), 0.0f, 1e-5f);
  EXPECT_NEAR(camera.cameraToWorld.linear().determinant(), 1.0f, 1e-5f);
}

TEST(GltfShot, UnboundMaterialsAreMappedAutomatically) {
  const Shot shot = loadShot(
      writeShot("tiny_materials.json",
                tinyShot("tiny_materials.gltf", R"({"gltf": {"asset": "tiny", "camera": "closeup"}, "fov": 20})")));
  EXPECT_NEAR(shot.camera.camera.verticalFovRadians, degreesToRadians(20.0f), 1e-6f);  // the shot's fov wins
  ASSERT_EQ(shot.assetMaterials.size(), 2u);
  EXPECT_EQ(shot.assetMaterials[0].name, "tiny/tearfilm");
  ASSERT_TRUE(std::holds_alternative<SmoothDielectricParams>(shot.assetMaterials[0].params));
  EXPECT_FLOAT_EQ(std::get<SmoothDielectricParams>(shot.assetMaterials[0].params).ior, 1.33f);
  EXPECT_EQ(shot.assetMaterials[1].name, "tiny/paint");
  ASSERT_TRUE(std::holds_alternative<DiffuseParams>(shot.assetMaterials[1].params));
  EXPECT_TRUE((std::get<DiffuseParams>(shot.assetMaterials[1].params).albedo == Color(0.2f, 0.4f, 0.6f)).all());

  const Frame frame = buildFrame(shot, 1);
  ASSERT_EQ(frame.meshes.size(), 2u);
  EXPECT_EQ(frame.meshes[0].materialId, 0u);
  EXPECT_EQ(frame.meshes[1].materialId, 1u);
  // World space: (1,0,0) of the asset -> scaled (3,0,0) -> rotated (0,0,-3) -> moved (10,0,-3).
  EXPECT_NEAR((frame.meshes[0].mesh.positions[1] - Vec3(10, 0, -3)).norm(), 0.0f, 1e-5f);
}

TEST(GltfShot, BindingsAndHidingByMaterialName) {
  std::string text = tinyShot("tiny_bound.gltf", R"({"gltf": {"asset": "tiny", "camera": "closeup"}})",
                              R"(, "materials": {"tearfilm": "tear"}, "hide": ["paint"])");
  text.insert(text.find("\"assets\""), "\"materials\": {\"tear\": {\"type\": \"water\"}},\n  ");
  const Shot shot = loadShot(writeShot("tiny_bound.json", text));
  EXPECT_TRUE(shot.assetMaterials.empty());
  EXPECT_EQ(shot.assets[0].primitiveMaterials, (std::vector<int>{0, -1}));
  const Frame frame = buildFrame(shot, 1);
  ASSERT_EQ(frame.meshes.size(), 1u);
  EXPECT_EQ(frame.materials[frame.meshes[0].materialId].name, "tear");
}

TEST(GltfShot, UnknownCameraSuggestsTheClosest) {
  const auto f = writeShot("tiny_bad_camera.json",
                           tinyShot("tiny_bad_camera.gltf", R"({"gltf": {"asset": "tiny", "camera": "closup"}})"));
  std::vector<Diagnostic> diagnostics;
  test::shotErrorOf(f, &diagnostics);
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].jsonPath, "/camera/gltf/camera");
  EXPECT_EQ(diagnostics[0].message.substr(0, diagnostics[0].message.find('\n')),
            "asset 'tiny' has no camera 'closup'; did you mean 'closeup'?");
  EXPECT_EQ(diagnostics[0].line, 6);
}

TEST(GltfShot, FStopWithAGltfCameraNeedsAFocusDistance) {
  const auto f =
      writeShot("tiny_fstop.json",
                tinyShot("tiny_fstop.gltf", R"({"gltf": {"asset": "tiny", "camera": "closeup"}, "fStop": 2})"));
  std::vector<Diagnostic> diagnostics;
  test::shotErrorOf(f, &diagnostics);
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].jsonPath, "/camera");
  EXPECT_EQ(diagnostics[0].message.substr(0, diagnostics[0].message.find('\n')),
            "missing required key 'focusDistance' (metres; with 'fStop', a glTF camera has no look-at point to "
            "focus on: give it, or \"focus\": \"surface\")");
  const auto g = writeShot("tiny_fstop_surface.json",
                           tinyShot("tiny_fstop_surface.gltf",
                                    R"({"gltf": {"asset": "tiny", "camera": "closeup"}, "fStop": 2, "focus": "surface"})"));
  EXPECT_TRUE(loadShot(g).camera.camera.focusOnSurface) << "a glTF camera may focus on the surface it looks at";
}

}  // namespace gltf_shot_test
}  // namespace lacrima
