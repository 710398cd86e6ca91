// Playing an asset's glTF animation in a shot ("animation" member of an asset): morph weights
// channels and node TRS through loadShot/buildFrame, on a small GLB written by the test.
//   node 0 "root": child node 1, no mesh
//   node 1 "tri":  mesh "Tri", one triangle (0,0,0) (1,0,0) (0,1,0), target "open" lifts vertex 0 by +z
//   animation "wave": over 1 s, open 0 -> 0.5 and node 1 translation (0,0,0) -> (1,0,0)
//   animation "idle": one key, open 0
#include <gtest/gtest.h>

#include <string>

#include "geometry/gltf_builder_support.hpp"
#include "geometry/gltf_skin_support.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace gltf_animation_shot_test {

using test::shotErrorOf;
using test::expectSingleError;
using test::firstLineOf;
using test::writeShot;

std::filesystem::path writeAnimatedGlb(const std::filesystem::path& dir, bool withAnimations = true) {
  test::GltfBuilder b;
  b.addMesh("Tri", {0, 0, 0, 1, 0, 0, 0, 1, 0}, {"open"}, {{0, 0, 1, 0, 0, 0, 0, 0, 0}});
  b.json()["scenes"] = {{{"nodes", {0}}}};
  b.json()["nodes"] = {{{"name", "root"}, {"children", {1}}}, {{"name", "tri"}, {"mesh", 0}}};
  if (withAnimations) {
    const int wave = b.addAnimation("wave");
    b.addChannel(wave, 1, "weights", {0, 1}, {0, 0.5f}, "SCALAR");
    b.addChannel(wave, 1, "translation", {0, 1}, {0, 0, 0, 1, 0, 0}, "VEC3");
    const int idle = b.addAnimation("idle");
    b.addChannel(idle, 1, "weights", {0}, {0}, "SCALAR");
  }
  const auto path = dir / (withAnimations ? "animated.glb" : "static.glb");
  b.write(path);
  return path;
}

// Frames 1-5 at 4 fps (frame f plays (f - 1) / 4 s); the asset sits at z = -1.
std::string animatedShot(const std::filesystem::path& glb, const std::string& asset, const std::string& cameraExtra = "") {
  return "{\n  \"version\": 1,\n  \"frames\": {\"start\": 1, \"end\": 5, \"fps\": 4},\n"
         "  \"output\": \"out.####.exr\",\n  \"render\": {\"width\": 8, \"height\": 8, \"spp\": 1},\n"
         "  \"camera\": {\"position\": [0, 0, 2], \"lookAt\": [0, 0, 0], \"fov\": 30" + cameraExtra + "},\n"
         "  \"assets\": [{\"name\": \"tri\", \"file\": \"" + glb.string() + "\", \"transform\": {\"translate\": [0, 0, -1]}" +
         (asset.empty() ? "" : ", " + asset) + "}]\n}\n";
}

std::filesystem::path shotDir() { return writeShot("placeholder.json", "").parent_path(); }

const MeshInstance& triMesh(const Frame& frame) {
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name.rfind("tri/", 0) == 0) return m;
  ADD_FAILURE() << "no mesh of asset 'tri'";
  return frame.meshes.front();
}

// The world positions of the triangle with weight `open` and node translation x = `slide`.
std::vector<Vec3> expectedTriangle(float open, float slide) {
  return {Vec3(slide, 0, open - 1), Vec3(1 + slide, 0, -1), Vec3(slide, 1, -1)};
}

void expectPositionsNear(const std::vector<Vec3>& a, const std::vector<Vec3>& b, float tolerance = 1e-5f) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i)
    EXPECT_LE((a[i] - b[i]).norm(), tolerance) << "vertex " << i << ": " << a[i].transpose() << " vs "
                                               << b[i].transpose();
}

TEST(GltfAnimationShot, WeightsAndNodeTranslationPlayAtTheShotFrames) {
  const auto glb = writeAnimatedGlb(shotDir());
  const Shot shot = loadShot(writeShot("wave.json", animatedShot(glb, R"("animation": {"name": "wave"})")));
  ASSERT_TRUE(shot.assets[0].gltfAnimation.has_value());
  EXPECT_TRUE(shot.assets[0].animated());
  // Frame 1 = 0 s: the rest pose. Frame 3 = 0.5 s: open 0.25, x + 0.5. Frame 5 = 1 s: the last key.
  expectPositionsNear(triMesh(buildFrame(shot, 1)).mesh.positions, expectedTriangle(0, 0));
  expectPositionsNear(triMesh(buildFrame(shot, 3)).mesh.positions, expectedTriangle(0.25f, 0.5f));
  expectPositionsNear(triMesh(buildFrame(shot, 5)).mesh.positions, expectedTriangle(0.5f, 1.0f));
}

TEST(GltfAnimationShot, AnimationWeightsAddToStaticBlendshapesAndAreClamped) {
  const auto glb = writeAnimatedGlb(shotDir());
  const Shot shot = loadShot(writeShot(
      "added.json", animatedShot(glb, R"("blendshapes": {"open": 0.1}, "animation": {"name": "wave"})")));
  expectPositionsNear(triMesh(buildFrame(shot, 3)).mesh.positions, expectedTriangle(0.35f, 0.5f));
  const Shot clamped = loadShot(writeShot(
      "clamped.json", animatedShot(glb, R"("blendshapes": {"open": 0.8}, "animation": {"name": "wave"})")));
  expectPositionsNear(triMesh(buildFrame(clamped, 5)).mesh.positions, expectedTriangle(1.0f, 1.0f));
}

TEST(GltfAnimationShot, StartFrameSpeedAndLoopMapFramesToSeconds) {
  const auto glb = writeAnimatedGlb(shotDir());
  const Shot held = loadShot(writeShot("held.json", animatedShot(glb, R"("animation": {"index": 0, "startFrame": 3})")));
  const ShotGltfAnimation& h = *held.assets[0].gltfAnimation;
  EXPECT_EQ(h.index, 0u);
  EXPECT_DOUBLE_EQ(h.duration, 1.0);
  EXPECT_DOUBLE_EQ(h.secondsAt(1), 0.0);   // before startFrame: held at 0 s
  EXPECT_DOUBLE_EQ(h.secondsAt(4), 0.25);
  EXPECT_DOUBLE_EQ(h.secondsAt(20), 1.0);  // held at the end
  expectPositionsNear(triMesh(buildFrame(held, 5)).mesh.positions, expectedTriangle(0.25f, 0.5f));

  const Shot looped = loadShot(writeShot(
      "looped.json", animatedShot(glb, R"("animation": {"name": "wave", "speed": 2, "loop": true})")));
  const ShotGltfAnimation& l = *looped.assets[0].gltfAnimation;
  EXPECT_DOUBLE_EQ(l.secondsAt(2), 0.5);
  EXPECT_DOUBLE_EQ(l.secondsAt(3), 0.0);  // 1 s wraps to 0
  EXPECT_DOUBLE_EQ(l.secondsAt(4), 0.5);
  EXPECT_DOUBLE_EQ(l.secondsAt(1.5), 0.25);
  expectPositionsNear(triMesh(buildFrame(looped, 4)).mesh.positions, expectedTriangle(0.25f, 0.5f));
}

TEST(GltfAnimationShot, ShutterCloseUsesTheFractionalFrame) {
  const auto glb = writeAnimatedGlb(shotDir());
  const Shot shot = loadShot(writeShot(
      "blur.json", animatedShot(glb, R"("animation": {"name": "wave"})", R"(, "shutter": {"open": 0, "close": 0.5})")));
  const Frame frame = buildFrame(shot, 2);  // open at 0.25 s, close at frame 2.5 = 0.375 s
  const MeshInstance& m = triMesh(frame);
  expectPositionsNear(m.mesh.positions, expectedTriangle(0.125f, 0.25f));
  ASSERT_TRUE(m.moves());
  expectPositionsNear(m.positionsAtClose, expectedTriangle(0.1875f, 0.375f));
}

TEST(GltfAnimationShot, WithoutAnAnimationMemberTheAssetIsStill) {
  const auto glb = writeAnimatedGlb(shotDir());
  const Shot shot = loadShot(writeShot("still.json", animatedShot(glb, "")));
  EXPECT_FALSE(shot.assets[0].gltfAnimation.has_value());
  EXPECT_FALSE(shot.assets[0].animated());
  expectPositionsNear(triMesh(buildFrame(shot, 5)).mesh.positions, expectedTriangle(0, 0), 0.0f);
}

// The skinned strip of gltf_skin_support.hpp (asset "tri" here, so triMesh finds it), at z - 1.
TEST(GltfAnimationShot, SkinnedAnimationPlaysThroughBuildFrame) {
  test::GltfBuilder b = test::skinnedStrip();
  const auto glb = shotDir() / "skinned.glb";
  b.write(glb);
  const auto shifted = [](std::vector<Vec3> points) {
    for (Vec3& p : points) p.z() -= 1.0f;
    return points;
  };
  const std::vector<Vec3> rest = {Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(1, 2.5f, 0), Vec3(2, 2.5f, 0), Vec3(1, 4, 0), Vec3(2, 4, 0)};
  // Without an animation: the baked rest pose, exactly.
  const Shot still = loadShot(writeShot("skin_still.json", animatedShot(glb, "")));
  expectPositionsNear(triMesh(buildFrame(still, 5)).mesh.positions, shifted(rest), 0.0f);

  // "bend": frame 1 = 0 s is the rest pose; frame 5 = 1 s has the knee turned 90 degrees
  // (see gltf_skin_test.cpp for the hand computation); the strip node's own slide is ignored.
  const Shot bend = loadShot(writeShot("skin_bend.json", animatedShot(glb, R"("animation": {"name": "bend"})")));
  expectPositionsNear(triMesh(buildFrame(bend, 1)).mesh.positions, shifted(rest), 1e-6f);
  expectPositionsNear(triMesh(buildFrame(bend, 5)).mesh.positions,
                      shifted({Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(1, 2.5f, 0), Vec3(1.5f, 3, 0), Vec3(-1, 2, 0), Vec3(-1, 3, 0)}));

  // "lift": the morph target moves vertex 4 to where vertex 5 is before skinning, then the knee turns.
  const Shot lift = loadShot(writeShot("skin_lift.json", animatedShot(glb, R"("animation": {"name": "lift"})")));
  const std::vector<Vec3> lifted = triMesh(buildFrame(lift, 5)).mesh.positions;
  expectPositionsNear({lifted[4], lifted[5]}, shifted({Vec3(-1, 3, 0), Vec3(-1, 3, 0)}));
}


TEST(GltfAnimationShot, BadAnimationMembersGetExactMessages) {
  const auto dir = shotDir();
  const auto glb = writeAnimatedGlb(dir);
  expectSingleError("name.json", animatedShot(glb, R"("animation": {"name": "wve"})"),
              "/assets/0/animation/name: unknown glTF animation 'wve'; did you mean 'wave'?");
  expectSingleError("index.json", animatedShot(glb, R"("animation": {"index": 2})"),
              "/assets/0/animation/index: animation index 2 does not exist (asset 'tri' has 2 animations)");
  expectSingleError("speed.json", animatedShot(glb, R"("animation": {"name": "wave", "speed": 0})"),
              "/assets/0/animation/speed: expected a number > 0, found 0");
  expectSingleError("both.json", animatedShot(glb, R"("animation": {"name": "wave", "index": 0})"),
              "/assets/0/animation/index: give the animation's 'name' or its 'index', not both");
  expectSingleError("neither.json", animatedShot(glb, R"("animation": {"loop": true})"),
              "/assets/0/animation: missing required key 'name' (the glTF animation to play, or its 'index')");
  const auto still = writeAnimatedGlb(dir, false);
  expectSingleError("none.json", animatedShot(still, R"("animation": {"name": "wave"})"),
              "/assets/0/animation: asset 'tri' has no glTF animations (static.glb defines none)");
}

}  // namespace gltf_animation_shot_test
}  // namespace lacrima
