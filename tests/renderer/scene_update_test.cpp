// Renderer keeps the Embree scene across the frames of a shot and refits it when only vertices
// move. A frame must come out bitwise the same whether it is rendered in a sequence (refitted
// scene) or alone (renderFrame, built scene): a farm node may render any frame on its own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "lacrima/mesh/shapes.hpp"
#include "lacrima/renderer/render.hpp"
#include "support/test_scenes.hpp"

namespace lacrima {
namespace scene_update_test {

using test::bitwiseEqual;

constexpr int kFrameCount = 4;

// Floor, a skin ellipsoid that breathes and wobbles from frame to frame (same triangles), a
// water drop and a soft box: every geometry kind the scene holds, one of them deforming.
Frame deformingScene(int frameIndex) {
  Frame frame;
  frame.materials.push_back(Material{"floor", DiffuseParams{Color(0.6f, 0.5f, 0.4f)}, Color::Zero()});
  frame.materials.push_back(Material{"water", SmoothDielectricParams{}, Color::Zero()});
  frame.materials.push_back(Material{"skin", SkinParams{}, Color::Zero()});
  frame.meshes.push_back(MeshInstance{makeRectangle(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 0, -4)), 0});
  MeshInstance blob{makeEllipsoid(Vec3(0.4f, 0.3f, 0), Mat3(Vec3(0.3f, 0.2f, 0.2f).asDiagonal()), 16, 32), 2};
  const float phase = 0.7f * float(frameIndex);
  for (Vec3& p : blob.mesh.positions) p += 0.05f * std::sin(8.0f * p.y() + phase) * Vec3(1, 0, 0);
  blob.mesh.normals.clear();  // geometric normals: the wobble would make stored normals wrong
  frame.meshes.push_back(blob);
  frame.spheres.push_back(Sphere{Vec3(-0.4f, 0.35f, 0.2f), 0.35f, 1});
  test::addTopLightAndView(frame);
  frame.settings.frameNumber = frameIndex + 1;
  return frame;
}

// The same deforming blob with deformation blur: it also moves during the shutter.
Frame deformingBlurredScene(int frameIndex) {
  Frame frame = deformingScene(frameIndex);
  const Frame next = deformingScene(frameIndex + 1);
  frame.meshes[1].positionsAtClose = next.meshes[1].mesh.positions;
  return frame;
}

void expectBitwiseEqualFilms(const Film& a, const Film& b, int frameIndex) {
  EXPECT_TRUE(bitwiseEqual(a.rgba, b.rgba)) << "frame index " << frameIndex;
  EXPECT_TRUE(bitwiseEqual(a.albedo, b.albedo)) << "frame index " << frameIndex;
  EXPECT_TRUE(bitwiseEqual(a.normal, b.normal)) << "frame index " << frameIndex;
  EXPECT_TRUE(bitwiseEqual(a.depth, b.depth)) << "frame index " << frameIndex;
}

template <typename MakeFrame>
void expectSequenceEqualsFramesRenderedAlone(MakeFrame makeFrame) {
  Renderer renderer;
  for (int i = 0; i < kFrameCount; ++i) {
    const Frame frame = makeFrame(i);
    RenderStats stats;
    const Film inSequence = renderer.render(frame, &stats);
    EXPECT_EQ(stats.sceneUpdate, i == 0 ? SceneUpdate::Build : SceneUpdate::Refit) << "frame index " << i;
    expectBitwiseEqualFilms(inSequence, renderFrame(frame), i);
  }
}

TEST(SceneUpdate, DeformingMeshSequenceEqualsFramesRenderedAlone) {
  expectSequenceEqualsFramesRenderedAlone(deformingScene);
}

TEST(SceneUpdate, DeformationBlurredSequenceEqualsFramesRenderedAlone) {
  expectSequenceEqualsFramesRenderedAlone(deformingBlurredScene);
}

TEST(SceneUpdate, TheDeformationIsVisible) {
  // Guards the equality tests: with a still blob they would prove nothing about refitting.
  EXPECT_FALSE(bitwiseEqual(renderFrame(deformingScene(0)).depth, renderFrame(deformingScene(2)).depth));
}

TEST(SceneUpdate, RendererCanBeFedFramesThatNoLongerExist) {
  // The scene holds no reference into a frame between render calls.
  Renderer renderer;
  renderer.render(deformingScene(0));
  const Film second = renderer.render(deformingScene(1));
  expectBitwiseEqualFilms(second, renderFrame(deformingScene(1)), 1);
}

TEST(SceneUpdate, MovingSphereAndLightAreRefitted) {
  Renderer renderer;
  renderer.render(deformingScene(0));
  Frame moved = deformingScene(0);
  moved.spheres[0].center += Vec3(0.1f, 0, 0);
  moved.spheres[0].radius = 0.3f;
  moved.lights[0].center += Vec3(0, 0.5f, 0);
  RenderStats stats;
  const Film film = renderer.render(moved, &stats);
  EXPECT_EQ(stats.sceneUpdate, SceneUpdate::Refit);
  expectBitwiseEqualFilms(film, renderFrame(moved), 1);
}

// Renders frame 0, then `changed`, through one Renderer: `changed` must be taken as an update
// that attaches and detaches the given numbers of geometries (the rest kept) and renders as it
// does alone; the frame after it refits again when its layout stays.
void expectUpdateThatRendersCorrectly(const Frame& changed, size_t attached, size_t detached) {
  Renderer renderer;
  renderer.render(deformingScene(0));
  RenderStats stats;
  const Film film = renderer.render(changed, &stats);
  EXPECT_EQ(stats.sceneUpdate, SceneUpdate::Update);
  EXPECT_EQ(stats.sceneGeometriesAttached, attached);
  EXPECT_EQ(stats.sceneGeometriesDetached, detached);
  expectBitwiseEqualFilms(film, renderFrame(changed), 1);
  renderer.render(changed, &stats);
  EXPECT_EQ(stats.sceneUpdate, SceneUpdate::Refit);
  EXPECT_EQ(stats.sceneGeometriesAttached, 0u);
}

MeshInstance smallDrop() {
  MeshInstance drop{makeEllipsoid(Vec3(0, 0.1f, 0.6f), 0.1f * Mat3::Identity(), 8, 16), 1};
  drop.mesh.name = "drop";
  return drop;
}

TEST(SceneUpdate, AnAddedMeshIsAttachedAndTheOthersKept) {
  Frame frame = deformingScene(1);
  frame.meshes.push_back(smallDrop());
  expectUpdateThatRendersCorrectly(frame, 1, 0);
}

TEST(SceneUpdate, AMeshAddedBeforeTheOthersLeavesTheirGeometries) {
  // A bead born in the middle of the frame's mesh list moves the meshes after it down the list:
  // they keep their geometries by name, and hits must map to their new indices.
  Frame before = deformingScene(0), after = deformingScene(1);
  before.meshes[0].mesh.name = after.meshes[0].mesh.name = "floor";
  before.meshes[1].mesh.name = after.meshes[1].mesh.name = "skin";
  after.meshes.insert(after.meshes.begin(), smallDrop());
  Renderer renderer;
  renderer.render(before);
  RenderStats stats;
  const Film film = renderer.render(after, &stats);
  EXPECT_EQ(stats.sceneUpdate, SceneUpdate::Update);
  EXPECT_EQ(stats.sceneGeometriesAttached, 1u);
  EXPECT_EQ(stats.sceneGeometriesDetached, 0u);
  expectBitwiseEqualFilms(film, renderFrame(after), 1);
}

TEST(SceneUpdate, ARemovedMeshIsDetachedAndTheOthersKept) {
  Frame frame = deformingScene(1);
  frame.meshes.erase(frame.meshes.begin() + 1);
  expectUpdateThatRendersCorrectly(frame, 0, 1);
}

TEST(SceneUpdate, AMeshThatComesAndGoesLeavesTheSceneAsBuiltForEachFrame) {
  Renderer renderer;
  for (int i = 0; i < kFrameCount; ++i) {
    Frame frame = deformingScene(i);
    if (i % 2 == 1) frame.meshes.push_back(smallDrop());
    RenderStats stats;
    const Film inSequence = renderer.render(frame, &stats);
    EXPECT_EQ(stats.sceneUpdate, i == 0 ? SceneUpdate::Build : SceneUpdate::Update) << "frame index " << i;
    expectBitwiseEqualFilms(inSequence, renderFrame(frame), i);
  }
}

TEST(SceneUpdate, ChangedTrianglesWithTheSameCountsAreReplaced) {
  Frame frame = deformingScene(1);
  std::swap(frame.meshes[1].mesh.indices[1], frame.meshes[1].mesh.indices[2]);  // flips one triangle
  expectUpdateThatRendersCorrectly(frame, 1, 1);
}

TEST(SceneUpdate, AChangedVertexCountIsReplaced) {
  Frame frame = deformingScene(1);
  frame.meshes[1].mesh = makeEllipsoid(Vec3(0.4f, 0.3f, 0), Mat3(Vec3(0.3f, 0.2f, 0.2f).asDiagonal()), 12, 24);
  expectUpdateThatRendersCorrectly(frame, 1, 1);
}

TEST(SceneUpdate, StartingDeformationBlurIsReplaced) {
  // Two time steps instead of one: another kind of Embree geometry.
  expectUpdateThatRendersCorrectly(deformingBlurredScene(1), 1, 1);
}

TEST(SceneUpdate, AMeshTurningDielectricIsReplaced) {
  // The dielectric BVH must hold exactly the dielectric geometries.
  Frame frame = deformingScene(1);
  frame.meshes[1].materialId = 1;  // water
  expectUpdateThatRendersCorrectly(frame, 1, 1);
}

TEST(SceneUpdate, AChangedLightShapeIsReplaced) {
  Frame frame = deformingScene(1);
  frame.lights[0].shape = AreaLight::Shape::Sphere;
  frame.lights[0].radius = 0.2f;
  expectUpdateThatRendersCorrectly(frame, 1, 1);
}

TEST(SceneUpdate, AStartingSphereMotionIsReplaced) {
  Frame frame = deformingScene(1);
  frame.spheres[0].centerAtClose = frame.spheres[0].center + Vec3(0.05f, 0, 0);
  expectUpdateThatRendersCorrectly(frame, 1, 1);
}

// A change of thread count needs another Embree device: the scene is built anew.
void expectRebuildThatRendersCorrectly(const Frame& changed) {
  Renderer renderer;
  renderer.render(deformingScene(0));
  RenderStats stats;
  const Film film = renderer.render(changed, &stats);
  EXPECT_EQ(stats.sceneUpdate, SceneUpdate::Build);
  expectBitwiseEqualFilms(film, renderFrame(changed), 1);
  renderer.render(changed, &stats);
  EXPECT_EQ(stats.sceneUpdate, SceneUpdate::Refit);
}

TEST(SceneUpdate, ChangedThreadCountRebuilds) {
  Frame frame = deformingScene(1);
  frame.settings.threads = frame.settings.threads == 1 ? 2 : 1;
  expectRebuildThatRendersCorrectly(frame);
}

TEST(SceneUpdate, OneAndTwoThreadSequencesAreBitwiseEqual) {
  Renderer oneThread, twoThreads;
  for (int i = 0; i < kFrameCount; ++i) {
    Frame frame = deformingBlurredScene(i);
    frame.settings.threads = 1;
    const Film one = oneThread.render(frame);
    frame.settings.threads = 2;
    const Film two = twoThreads.render(frame);
    expectBitwiseEqualFilms(one, two, i);
  }
}

TEST(SceneUpdate, StatsReportTheSceneUpdateTime) {
  RenderStats stats;
  renderFrame(deformingScene(0), &stats);
  EXPECT_GT(stats.sceneUpdateSeconds, 0.0);
  EXPECT_LT(stats.sceneUpdateSeconds, stats.seconds);
}

TEST(SceneUpdate, FailedFrameDoesNotPoisonTheRenderer) {
  Renderer renderer;
  renderer.render(deformingScene(0));
  Frame broken = deformingScene(1);
  broken.meshes[1].positionsAtClose.assign(3, Vec3::Zero());  // wrong count: cannot be built
  EXPECT_ANY_THROW(renderer.render(broken));
  RenderStats stats;
  const Film film = renderer.render(deformingScene(2), &stats);
  EXPECT_EQ(stats.sceneUpdate, SceneUpdate::Build);
  expectBitwiseEqualFilms(film, renderFrame(deformingScene(2)), 2);
}

}  // namespace scene_update_test
}  // namespace lacrima
