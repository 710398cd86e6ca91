// Valid shot files: every field lands in the Shot, and buildFrame gives the renderer what the
// shot says (counts, materials, camera aim, lights).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <variant>

#include "lacrima/renderer/camera.hpp"
#include "lacrima/renderer/environment.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace shot_load_test {

using test::sourcePath;

// The look-at point must land in the middle of the image.
void expectProjectsToImageCentre(const Camera& camera, const Vec3& point, int width, int height) {
  const Vec3 inCamera = camera.cameraToWorld.inverse(Eigen::Affine) * point;
  EXPECT_NEAR(inCamera.x(), 0.0f, 1e-5f);
  EXPECT_NEAR(inCamera.y(), 0.0f, 1e-5f);
  EXPECT_LT(inCamera.z(), 0.0f);  // in front: the camera looks down -Z
  const Vec4 ndc = worldToNdcMatrix(camera, width, height) * Vec4(point.x(), point.y(), point.z(), 1.0f);
  EXPECT_NEAR(ndc.x() / ndc.w(), 0.5f, 1e-5f);
  EXPECT_NEAR(ndc.y() / ndc.w(), 0.5f, 1e-5f);
}

TEST(LoadShot, FurnaceSphere) {
  const Shot shot = loadShot(sourcePath("scenes/shots/test_furnace_sphere.json"));
  EXPECT_EQ(shot.version, 1);
  EXPECT_EQ(shot.frameStart, 1);
  EXPECT_EQ(shot.frameEnd, 1);
  EXPECT_EQ(shot.fps, 24.0);
  EXPECT_EQ(shot.outputPattern, sourcePath("scenes/shots/renders/test_furnace_sphere.####.exr").string());
  EXPECT_TRUE(shot.ocioConfig.empty());
  EXPECT_EQ(shot.render.width, 32);
  EXPECT_EQ(shot.render.height, 32);
  EXPECT_EQ(shot.render.samplesPerPixel, 16);
  EXPECT_EQ(shot.render.maxDepth, 64);
  EXPECT_EQ(shot.render.seed, 1u);
  EXPECT_EQ(shot.render.threads, 0);
  EXPECT_FALSE(shot.render.floatOutput);
  EXPECT_FALSE(shot.environment.has_value());
  EXPECT_TRUE((shot.background == Color(1, 1, 1)).all());
  ASSERT_EQ(shot.materials.size(), 1u);
  EXPECT_EQ(shot.materials[0].name, "water");
  ASSERT_TRUE(std::holds_alternative<SmoothDielectricParams>(shot.materials[0].params));
  EXPECT_FLOAT_EQ(std::get<SmoothDielectricParams>(shot.materials[0].params).ior, 1.337f);

  const Frame frame = buildFrame(shot, 1);
  EXPECT_EQ(frame.meshes.size(), 0u);
  ASSERT_EQ(frame.spheres.size(), 1u);
  EXPECT_FLOAT_EQ(frame.spheres[0].radius, 0.5f);
  EXPECT_EQ(frame.spheres[0].materialId, 0u);
  EXPECT_EQ(frame.lights.size(), 0u);
  EXPECT_EQ(frame.environment, nullptr);
  EXPECT_TRUE((frame.uniformBackground == Color(1, 1, 1)).all());
  EXPECT_EQ(frame.camera.lensRadius, 0.0f);  // no fStop: pinhole
  EXPECT_NEAR(frame.camera.verticalFovRadians, degreesToRadians(30.0f), 1e-6f);
  EXPECT_EQ(frame.settings.frameNumber, 1);
  expectProjectsToImageCentre(frame.camera, Vec3(0, 0, 0), 32, 32);
}

TEST(LoadShot, DropsOnAPlane) {
  const Shot shot = loadShot(sourcePath("scenes/shots/test_drops.json"));
  EXPECT_EQ(shot.render.width, 64);
  EXPECT_EQ(shot.render.height, 48);
  EXPECT_EQ(shot.render.seed, 7u);

  // Camera: 50 mm on a 24 mm sensor at f/8, focused on the look-at point.
  const ShotCamera& cam = shot.camera;
  EXPECT_EQ(cam.kind, ShotCamera::Kind::LookAt);
  EXPECT_FALSE(cam.fovDegrees.has_value());
  EXPECT_EQ(cam.focalLengthMm, 50.0f);
  EXPECT_EQ(cam.sensorHeightMm, 24.0f);
  EXPECT_EQ(cam.fStop, 8.0f);
  EXPECT_NEAR(cam.camera.verticalFovRadians, 2.0f * std::atan(12.0f / 50.0f), 1e-6f);
  EXPECT_NEAR(cam.camera.lensRadius, 0.050f / 16.0f, 1e-7f);
  const Vec3 position(0, 0.06f, 0.12f), lookAt(0, 0.004f, 0);
  EXPECT_NEAR(cam.camera.focusDistance, (lookAt - position).norm(), 1e-6f);

  ASSERT_TRUE(shot.environment.has_value());
  EXPECT_EQ(shot.environment->file, sourcePath("scenes/assets/hdri/studio.exr"));
  EXPECT_FLOAT_EQ(shot.environment->intensity, 0.5f);
  EXPECT_FLOAT_EQ(shot.environment->rotationDegrees, 90.0f);
  ASSERT_NE(shot.environment->map, nullptr);
  EXPECT_EQ(shot.environment->map->width(), 1024);
  // studio.exr has a few negative texels: loaded, set to 0, and reported as a warning.
  ASSERT_EQ(shot.warnings.size(), 1u);
  EXPECT_EQ(shot.warnings[0].jsonPath, "/environment/file");
  EXPECT_EQ(shot.warnings[0].message, "warning: " + sourcePath("scenes/assets/hdri/studio.exr").string() +
                                          ": 3 texels were NaN, infinite or negative, set to 0");

  ASSERT_EQ(shot.materials.size(), 3u);
  EXPECT_EQ(shot.materials[0].name, "plane");  // file order
  EXPECT_EQ(shot.materials[1].name, "water");
  EXPECT_EQ(shot.materials[2].name, "rough_water");
  ASSERT_TRUE(std::holds_alternative<RoughDielectricParams>(shot.materials[2].params));
  EXPECT_FLOAT_EQ(std::get<RoughDielectricParams>(shot.materials[2].params).roughness, 0.05f);

  // The rectangle light faces its look-at point; power 5 W over 0.01 m^2, one-sided.
  ASSERT_EQ(shot.lights.size(), 1u);
  const AreaLight& light = shot.lights[0].light;
  EXPECT_EQ(light.shape, AreaLight::Shape::Rectangle);
  const Vec3 normal = light.edgeU.cross(light.edgeV);
  EXPECT_NEAR(normal.norm(), 0.01f, 1e-7f);
  EXPECT_NEAR(normal.normalized().dot((Vec3(0, 0, 0) - light.center).normalized()), 1.0f, 1e-6f);
  EXPECT_NEAR(light.edgeU.norm(), 0.1f, 1e-7f);
  EXPECT_NEAR(light.radiance.x(), 5.0f / (kPi * 0.01f), 1e-2f);
  EXPECT_FALSE(light.twoSided);

  ASSERT_EQ(shot.shapes.size(), 3u);
  EXPECT_EQ(shot.shapes[0].type, ShotShape::Type::Rectangle);
  EXPECT_NEAR(shot.shapes[0].edgeU.cross(shot.shapes[0].edgeV).normalized().y(), 1.0f, 1e-6f);
  EXPECT_EQ(shot.shapes[2].type, ShotShape::Type::Ellipsoid);
  EXPECT_EQ(shot.shapes[2].materialId, 2u);

  const Frame frame = buildFrame(shot, 1);
  EXPECT_EQ(frame.materials.size(), 3u);
  EXPECT_EQ(frame.meshes.size(), 2u);  // plane + ellipsoid
  EXPECT_EQ(frame.spheres.size(), 1u);
  EXPECT_EQ(frame.lights.size(), 1u);
  EXPECT_EQ(frame.environment, shot.environment->map);  // loaded once, shared
  EXPECT_EQ(frame.meshes[0].materialId, 0u);
  EXPECT_EQ(frame.meshes[1].materialId, 2u);
  EXPECT_EQ(frame.spheres[0].materialId, 1u);
  expectProjectsToImageCentre(frame.camera, lookAt, 64, 48);
  // The ellipsoid is flattened: 1.5 mm high around y = 1.5 mm.
  float top = -1.0f;
  for (const Vec3& p : frame.meshes[1].mesh.positions) top = std::max(top, p.y());
  EXPECT_NEAR(top, 0.003f, 1e-5f);
}

TEST(LoadShot, FaceWithBindingsBlendshapesAndHiddenParts) {
  const Shot shot = loadShot(sourcePath("scenes/shots/test_face.json"));
  EXPECT_EQ(shot.frameEnd, 3);
  ASSERT_EQ(shot.assets.size(), 1u);
  const ShotAsset& face = shot.assets[0];
  EXPECT_EQ(face.name, "face");
  ASSERT_NE(face.gltf, nullptr);
  ASSERT_EQ(face.weights.size(), face.gltf->targetNames.size());
  EXPECT_FLOAT_EQ(face.weights[size_t(face.gltf->findTarget("browInnerUp_L"))], 0.6f);
  EXPECT_FLOAT_EQ(face.weights[size_t(face.gltf->findTarget("mouthFrown_R"))], 0.4f);
  EXPECT_FLOAT_EQ(face.weights[size_t(face.gltf->findTarget("jawOpen"))], 0.0f);
  EXPECT_EQ(face.hide, (std::vector<std::string>{"M_GumsTongue", "M_Teeth", "M_EyeOcclusion"}));
  ASSERT_EQ(face.primitiveMaterials.size(), face.gltf->primitives.size());

  size_t visible = 0;
  for (size_t i = 0; i < face.gltf->primitives.size(); ++i) {
    const std::string& part = face.gltf->primitives[i].part;
    const int id = face.primitiveMaterials[i];
    if (part == "M_GumsTongue" || part == "M_Teeth" || part == "M_EyeOcclusion") {
      EXPECT_EQ(id, -1) << part;
      continue;
    }
    ++visible;
    if (part == "M_Face" || part == "M_BackHead") {
      EXPECT_EQ(id, shot.findMaterial("skin")) << part;
    } else if (part == "M_LacrimalFluid") {
      EXPECT_EQ(id, shot.findMaterial("tear")) << part;
    } else if (part == "M_IrisLeft") {
      EXPECT_EQ(shot.frameMaterials()[size_t(id)].name, "face/M_IrisLeft");
    }
  }
  // Unbound visible glTF materials are mapped automatically, after the shot's own materials.
  EXPECT_EQ(shot.materials.size(), 3u);
  std::vector<std::string> automatic;
  for (const Material& m : shot.assetMaterials) automatic.push_back(m.name);
  EXPECT_EQ(automatic,
            (std::vector<std::string>{"face/M_IrisLeft", "face/M_IrisRight", "face/M_EyeBlend", "face/M_EyeLashes"}));
  for (const Material& m : shot.assetMaterials) EXPECT_TRUE(std::holds_alternative<DiffuseParams>(m.params)) << m.name;

  const Frame frame = buildFrame(shot, 2);
  EXPECT_EQ(frame.settings.frameNumber, 2);
  EXPECT_EQ(frame.materials.size(), 7u);
  EXPECT_EQ(frame.meshes.size(), visible + 1);  // + the ellipsoid drop
  EXPECT_EQ(frame.spheres.size(), 0u);
  ASSERT_EQ(frame.lights.size(), 1u);
  EXPECT_EQ(frame.lights[0].shape, AreaLight::Shape::Sphere);
  // 40 W from a 5 cm sphere: L = P / (pi * 4 pi r^2).
  EXPECT_NEAR(frame.lights[0].radiance.y(), 40.0f / (kPi * 4.0f * kPi * 0.0025f), 1e-2f);

  // The static expression moved the face: the brow vertices differ from the neutral mesh.
  const GltfPrimitive& neutral = face.gltf->primitives[0];
  ASSERT_EQ(neutral.part, "M_Face");
  const TriangleMesh& posed = frame.meshes[0].mesh;
  ASSERT_EQ(posed.positions.size(), neutral.mesh.positions.size());
  float largestMove = 0.0f;
  for (size_t v = 0; v < posed.positions.size(); ++v)
    largestMove = std::max(largestMove, (posed.positions[v] - neutral.mesh.positions[v]).norm());
  EXPECT_GT(largestMove, 1e-3f);
  expectProjectsToImageCentre(frame.camera, Vec3(0, 0, 0.08f), 64, 64);
}

TEST(BuildFrame, FrameOutsideTheShotRangeIsAnInputError) {
  const Shot shot = loadShot(sourcePath("scenes/shots/test_furnace_sphere.json"));
  EXPECT_THROW(buildFrame(shot, 2), InputError);
  EXPECT_THROW(buildFrame(shot, 0), InputError);
}

}  // namespace shot_load_test
}  // namespace lacrima

namespace lacrima {
namespace shot_load_test {

// The complete example of docs/shot-format.md must stay a valid shot.
TEST(ShotFormatDoc, CompleteExampleLoadsAndBuilds) {
  std::ifstream in(test::sourcePath("docs/shot-format.md"));
  ASSERT_TRUE(in) << "docs/shot-format.md not found";
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t section = doc.find("## Complete example");
  ASSERT_NE(section, std::string::npos);
  const size_t begin = doc.find("```jsonc\n", section);
  ASSERT_NE(begin, std::string::npos);
  const size_t end = doc.find("\n```", begin + 9);
  std::string example = doc.substr(begin + 9, end - begin - 9);
  // The example lives in scenes/shots/; the test writes it elsewhere, so anchor its data paths.
  for (const std::string from : {"\"../assets/", "\"../ocio/"}) {
    const std::string to = "\"" + test::sourcePath("scenes").string() + "/" + from.substr(4);
    for (size_t at = example.find(from); at != std::string::npos; at = example.find(from, at + to.size()))
      example.replace(at, from.size(), to);
  }
  const Shot shot = loadShot(test::writeShot("doc_example.json", example));
  EXPECT_EQ(shot.frameEnd, 48);
  EXPECT_EQ(shot.materials.size(), 7u);
  EXPECT_EQ(shot.lights.size(), 3u);
  EXPECT_EQ(shot.shapes.size(), 3u);
  EXPECT_TRUE(shot.assetMaterials.empty());  // every visible part of the face is bound
  const Frame frame = buildFrame(shot, 12);
  EXPECT_EQ(frame.spheres.size(), 1u);
  EXPECT_EQ(frame.lights.size(), 3u);
  EXPECT_NE(frame.environment, nullptr);
  EXPECT_GT(frame.camera.lensRadius, 0.0f);
}

}  // namespace shot_load_test
}  // namespace lacrima
