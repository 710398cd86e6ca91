// Liquid tears in shots ("tears" of type "liquid"): the flow path from the inner eye
// corner traced on the smoothed skin, beads as closed outward meshes on the posed skin that appear
// at the overflow and run down, frames independent of their order, the face's motion followed,
// falling drops as ringing meshes, the volume budget, and exact messages for bad input.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "lacrima/mesh/closest_point_grid.hpp"
#include "lacrima/mesh/surface_flow.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "liquid_tear_support.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace liquid_tear_shot_test {

using test::expectSingleError;
using test::ictFaceShot;
using test::writeShot;

// Wells from the right eye's inner corner at 10 uL/s; the meniscus overflows at 10 uL (1 s, frame
// 25) and sends 8 uL down the cheek.
const std::string kTear =
    R"("tears": [{"type": "liquid", "asset": "face", "part": "M_Face", "source": {"landmark": 39}, "material": "water",
       "rate": 10, "overflowVolume": 10, "spillVolume": 8}])";
constexpr int kFrames = 72;  // 3 s at 24 fps

std::string tearWith(const std::string& from, const std::string& to) { return test::replaced(kTear, from, to); }

Shot loadTearShot(const std::string& name, const std::string& tear = kTear, const std::string& cameraExtra = "",
                  const std::string& asset = "") {
  return loadShot(writeShot(name, ictFaceShot(tear, cameraExtra, asset, kFrames)));
}

using test::beadsOf;
using test::skinOf;

// The path traced from the tear's source straight on the (unsmoothed) skin.
FlowPath rawPath(const Shot& shot, const TriangleMesh& skin) {
  const ShotLiquidTear& tear = shot.liquidTears[0];
  const TriangleAdjacency adjacency = buildTriangleAdjacency(skin, findCoincidentVertices(skin));
  FlowPathOptions options;
  options.maxLength = tear.maxLength;
  return traceFlowPath(skin, adjacency, SurfacePoint{tear.sourcePoint.triangle, tear.sourcePoint.barycentric},
                       tear.gravity, options);
}

// The lowest height of a bead mesh's vertices (its tip on a cheek).
float lowestY(const TriangleMesh& mesh) {
  float y = std::numeric_limits<float>::infinity();
  for (const Vec3& p : mesh.positions) y = std::min(y, p.y());
  return y;
}

// The first frame with a bead, or 0.
int firstFrameWithABead(FrameBuilder& builder) {
  for (int f = 1; f <= kFrames; ++f)
    if (!builder.liquidTearStateAt(0, f).beads.empty()) return f;
  return 0;
}

TEST(LiquidTearShot, PathFromTheInnerEyeCornerRunsDownTheCheekThanksToTheSmoothing) {
  const Shot shot = loadTearShot("liquid_path.json");
  ASSERT_EQ(shot.liquidTears.size(), 1u);
  const ShotLiquidTear& tear = shot.liquidTears[0];
  const FlowPath& path = tear.path;
  ASSERT_GE(path.points.size(), 2u);
  EXPECT_NE(path.stop, FlowStop::Pit) << flowStopName(path.stop);
  EXPECT_LT(path.positions.back().y(), path.positions.front().y() - 0.03f);
  // Downhill on the real skin too, up to the small differences between it and the smoothed one.
  for (size_t i = 1; i < path.positions.size(); ++i)
    EXPECT_LT(path.positions[i].y(), path.positions[i - 1].y() + 2e-4f) << i;
  EXPECT_EQ(tear.input.path.size(), path.points.size());

  // From this corner the unsmoothed skin happens to carry the path as far (see the next test).
  const Frame firstFrame = buildFrame(shot, 1);
  const FlowPath raw = rawPath(shot, skinOf(firstFrame, shot));
  std::printf("[ liquid ] landmark 39: path length on the smoothed skin %.4f m (on the real skin %.4f m, stop: %s); "
              "traced on the unsmoothed skin %.4f m (stop: %s); drop in y %.4f m\n",
              tear.smoothedPathLength, path.length(), flowStopName(path.stop), raw.length(), flowStopName(raw.stop),
              path.positions.front().y() - path.positions.back().y());
}

TEST(LiquidTearShot, OnTheCheekTheSmoothedSkinCarriesThePathPastTessellationPits) {
  // The skin point nearest to (-0.03, -0.02, 0.12), on the right cheek below the eye.
  const Shot probe = loadTearShot("liquid_probe.json");
  const Frame probeFrame = buildFrame(probe, 1);
  const TriangleMesh& probeSkin = skinOf(probeFrame, probe);
  const Vec3 start = surfacePosition(probeSkin, ClosestPointGrid(probeSkin).closest(Vec3(-0.03f, -0.02f, 0.12f)));
  char point[96];
  std::snprintf(point, sizeof point, "[%.7f, %.7f, %.7f]", start.x(), start.y(), start.z());
  const Shot shot = loadTearShot("liquid_cheek.json", tearWith(R"({"landmark": 39})", point));
  const ShotLiquidTear& tear = shot.liquidTears[0];
  const Frame frame = buildFrame(shot, 1);
  const FlowPath raw = rawPath(shot, skinOf(frame, shot));
  std::printf("[ liquid ] cheek: path length on the smoothed skin %.4f m (stop: %s); on the unsmoothed skin %.4f m "
              "(stop: %s)\n",
              tear.smoothedPathLength, flowStopName(tear.path.stop), raw.length(), flowStopName(raw.stop));
  EXPECT_EQ(raw.stop, FlowStop::Pit);
  EXPECT_LT(raw.length(), 0.5f * tear.path.length());
  EXPECT_LT(tear.path.positions.back().y(), tear.path.positions.front().y() - 0.03f);
}

TEST(LiquidTearShot, BeadAppearsAtTheOverflowAndRunsDown) {
  const Shot shot = loadTearShot("liquid_run.json");
  FrameBuilder builder(shot);
  const int first = firstFrameWithABead(builder);
  ASSERT_GT(first, 1);
  EXPECT_TRUE(beadsOf(builder.build(first - 1)).empty());
  EXPECT_FALSE(beadsOf(builder.build(first)).empty());
  const LiquidTearState atFirst = builder.liquidTearStateAt(0, first);
  ASSERT_FALSE(atFirst.beads.empty());
  // 10 uL at 10 uL/s: the meniscus overflows at t = 1 s (to the 1 ms step); the first frame at or
  // after that shows the 8 uL bead.
  const double birth = atFirst.time - 1.0;  // the bead is younger than one frame
  EXPECT_GE(birth, -1e-9);
  EXPECT_LT(birth, 1.0 / 24.0 + 2e-3);
  EXPECT_LT(liquidTearSeconds(shot, shot.liquidTears[0], first - 1), 1.0 + 2e-3);
  EXPECT_NEAR(atFirst.beads[0].volume, 8e-9, 1e-12);

  float previous = std::numeric_limits<float>::infinity();
  int moved = 0;
  for (int f = first; f <= kFrames; f += 6) {
    const Frame frame = builder.build(f);
    const auto beads = beadsOf(frame);
    ASSERT_FALSE(beads.empty()) << f;
    float lowest = std::numeric_limits<float>::infinity();
    for (const MeshInstance* b : beads) lowest = std::min(lowest, lowestY(b->mesh));
    EXPECT_LE(lowest, previous) << f;
    if (lowest < previous - 1e-3f) ++moved;
    previous = lowest;
  }
  EXPECT_GE(moved, 2);
  const LiquidTearState end = builder.liquidTearStateAt(0, kFrames);
  double farthest = 0.0;
  for (const BeadView& b : end.beads) farthest = std::max(farthest, b.arcLength);
  std::printf("[ liquid ] first bead at frame %d (t = %.3f s); at t = %.3f s the farthest bead is %.4f m down the "
              "%.4f m path\n",
              first, liquidTearSeconds(shot, shot.liquidTears[0], first), end.time, farthest, shot.liquidTears[0].path.length());
  EXPECT_GT(farthest, 0.01);
}

// The bead's flat side lies 20 um under the skin (liquid_tear_frame.hpp): the skin under a bead is
// inside the water, as on a face, so light reaches it through the dome alone; with the base above
// the skin an air gap under the bead totally reflected most of it (docs/peers.md).
TEST(LiquidTearShot, BeadMeshesAreClosedOutwardAndWetTheSkinTheyLieOn) {
  const Shot shot = loadTearShot("liquid_closed.json");
  FrameBuilder builder(shot);
  for (int f : {30, 45, 60, 72}) {
    const Frame frame = builder.build(f);
    const TriangleMesh& skin = skinOf(frame, shot);
    const ClosestPointGrid locator(skin);
    const auto beads = beadsOf(frame);
    ASSERT_FALSE(beads.empty()) << f;
    for (const MeshInstance* bead : beads) {
      EXPECT_EQ(findMeshDefect(bead->mesh), "") << f;
      EXPECT_EQ(findWeldedClosedMeshDefect(bead->mesh), "") << f;
      EXPECT_GT(signedVolume(bead->mesh), 0.0) << f;
      EXPECT_EQ(bead->materialId, uint32_t(shot.findMaterial("water")));
      float lowest = std::numeric_limits<float>::infinity();
      for (const Vec3& v : bead->mesh.positions) {
        const SurfacePoint nearest = locator.closest(v);
        lowest = std::min(lowest, (v - surfacePosition(skin, nearest)).dot(triangleNormal(skin, nearest.triangle)));
      }
      EXPECT_GE(lowest, -3e-5f) << "frame " << f << ": a bead vertex lies " << -lowest << " m under the skin";
      EXPECT_LE(lowest, -1e-5f) << "frame " << f << ": the base lies " << lowest << " m above the skin";
    }
  }
}

TEST(LiquidTearShot, AFrameAloneEqualsTheSameFrameInASequence) {
  const Shot shot = loadTearShot("liquid_alone.json");
  const Frame alone = buildFrame(shot, 40);
  FrameBuilder sequence(shot);
  for (int f : {10, 30, 50}) sequence.build(f);
  const Frame inSequence = sequence.build(40);
  const auto a = beadsOf(alone), b = beadsOf(inSequence);
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i]->mesh.positions, b[i]->mesh.positions);
    EXPECT_EQ(a[i]->mesh.normals, b[i]->mesh.normals);
    EXPECT_EQ(a[i]->mesh.indices, b[i]->mesh.indices);
  }
}

// The same on a face that moves (its course re-traced every frame): the bead meshes and the wet
// trail of frame 60 built alone are bitwise those built after other frames of a sequence.
TEST(LiquidTearShot, AFrameAloneEqualsTheSameFrameInASequenceWhenTheFaceMoves) {
  const std::string roll = R"("rig": {"preset": "ict"}, "joints": {"head.rz": {"keys": [[1, 0], [60, 6]]}})";
  const Shot shot = loadTearShot("liquid_moving_alone.json", kTear, "", roll);
  const Frame alone = buildFrame(shot, 60);
  FrameBuilder sequence(shot);
  for (int f : {12, 27, 50}) sequence.build(f);
  const Frame inSequence = sequence.build(60);
  EXPECT_GT(sequence.liquidTearCourses(0).tracedCount(), 55u);  // the head's roll moved the course every frame
  const auto a = beadsOf(alone), b = beadsOf(inSequence);
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i]->mesh.positions, b[i]->mesh.positions);
  const std::string name = "face/" + shot.assets[0].gltf->primitives[shot.liquidTears[0].sourcePoint.primitive].name;
  const auto wetness = [&name](const Frame& frame) {
    for (const MeshInstance& m : frame.meshes)
      if (m.mesh.name == name) return m.wetness;
    return std::vector<float>();
  };
  EXPECT_FALSE(wetness(alone).empty());
  EXPECT_EQ(wetness(alone), wetness(inSequence));
}

// The simulation runs beside the posing of the assets (buildFrame): on one thread, where the two
// run one after the other, a frame of a moving face is bitwise the frame built on all cores.
TEST(LiquidTearShot, AFrameOnOneThreadEqualsTheFrameOnAllCores) {
  const std::string roll = R"("rig": {"preset": "ict"}, "joints": {"head.rz": {"keys": [[1, 0], [60, 6]]}})";
  const Shot shot = loadTearShot("liquid_threads_all.json", kTear, "", roll);
  const Frame allCores = buildFrame(shot, 45);
  Frame oneThread;
  tbb::task_arena arena(1);
  arena.execute([&] { oneThread = buildFrame(shot, 45); });
  const auto a = beadsOf(allCores), b = beadsOf(oneThread);
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i]->mesh.positions, b[i]->mesh.positions);
  ASSERT_EQ(allCores.meshes.size(), oneThread.meshes.size());
  bool wet = false;
  for (size_t m = 0; m < allCores.meshes.size(); ++m) {
    EXPECT_EQ(allCores.meshes[m].mesh.positions, oneThread.meshes[m].mesh.positions) << allCores.meshes[m].mesh.name;
    EXPECT_EQ(allCores.meshes[m].wetness, oneThread.meshes[m].wetness) << allCores.meshes[m].mesh.name;
    wet = wet || !allCores.meshes[m].wetness.empty();
  }
  EXPECT_TRUE(wet) << "the trail's film is part of what is compared";
}

TEST(LiquidTearShot, SimulationCostPerFrameIsSmall) {
  const Shot shot = loadTearShot("liquid_cost.json");
  FrameBuilder builder(shot);
  const auto start = std::chrono::steady_clock::now();
  const LiquidTearState state = builder.liquidTearStateAt(0, kFrames);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ liquid ] simulating the 3 s shot to its last frame: %.2f ms\n", ms);
  EXPECT_GE(state.time, 2.95);
  const auto frameStart = std::chrono::steady_clock::now();
  const Frame frame = builder.build(kFrames);
  const double frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count();
  std::printf("[ liquid ] buildFrame of that frame (face posing, %zu bead meshes, simulation): %.1f ms\n",
              beadsOf(frame).size(), frameMs);
}

TEST(LiquidTearShot, BeadsFollowTheDeformingFace) {
  const std::string smile = R"("blendshapes": {"cheekRaiser_R": {"keys": [[1, 0], [40, 1]], "interpolation": "linear"}})";
  const Shot shot = loadTearShot("liquid_smile.json", kTear, "", smile);
  const Shot still = loadTearShot("liquid_still.json");
  const int f = 40;
  FrameBuilder smiling(shot), resting(still);
  const Frame movingFrame = smiling.build(f), restingFrame = resting.build(f);
  const auto moving = beadsOf(movingFrame), restingBeads = beadsOf(restingFrame);
  ASSERT_EQ(moving.size(), restingBeads.size());
  ASSERT_FALSE(moving.empty());
  // The smile re-routes the course (it is traced again on each frame's pose), so the liquid state
  // differs a little ...
  const LiquidTearState a = smiling.liquidTearStateAt(0, f), b = resting.liquidTearStateAt(0, f);
  ASSERT_EQ(a.beads.size(), b.beads.size());
  const FlowPath& course = smiling.liquidTearCourseAt(0, f)->path;
  const FlowPath& stillCourse = resting.liquidTearCourseAt(0, f)->path;
  EXPECT_EQ(stillCourse.positions, still.liquidTears[0].path.positions);  // the still face keeps its first course
  EXPECT_NE(course.positions, shot.liquidTears[0].path.positions);
  EXPECT_NEAR(a.beads[0].arcLength, b.beads[0].arcLength, 0.005);
  // ... and the bead sits at its course point on the smiling skin, which moved.
  const Frame& frame = movingFrame;
  const TriangleMesh& skin = skinOf(frame, shot);
  const Vec3 onSkin = surfacePosition(skin, liquidTearPathPoint(course, a.beads[0].arcLength));
  const Vec3 onStill = surfacePosition(skinOf(restingFrame, still), liquidTearPathPoint(stillCourse, b.beads[0].arcLength));
  EXPECT_GT((onSkin - onStill).norm(), 5e-4f);
  const TriangleMesh& bead = beadsOf(frame)[0]->mesh;
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : bead.positions) centre += p / float(bead.positions.size());
  EXPECT_LT((centre - onSkin).norm(), 0.004f);
  EXPECT_GT((centre - onStill).norm(), (onSkin - onStill).norm() * 0.5f);
}

// The centroid of a mesh's vertices.
Vec3d vertexCentroid(const std::vector<Vec3>& positions) {
  Vec3d sum = Vec3d::Zero();
  for (const Vec3& p : positions) sum += p.cast<double>();
  return sum / double(positions.size());
}

TEST(LiquidTearShot, DetachedDropsAreRingingMeshesUnderAShutter) {
  // The path beside the nose turns under it (a drip site: the skin faces down); the bead hangs
  // there and, held on a small contact circle (Tate's limit for r = 0.2 mm is 5.6 uL), falls within
  // the shot.
  const std::string drip = tearWith(R"("spillVolume": 8)", R"("spillVolume": 8, "hangingContactRadius": 0.0002)");
  const std::string shutter = R"(, "shutter": {"open": -0.25, "close": 0.25})";
  const Shot shot = loadTearShot("liquid_drip.json", drip, shutter);
  FrameBuilder builder(shot);
  int withDrops = 0;
  for (int f = 25; f <= kFrames; ++f) {
    const LiquidTearState state = builder.liquidTearStateAt(0, f - 0.25);
    if (state.drops.empty()) continue;
    const Frame frame = builder.build(f);
    const LiquidTearState atClose = builder.liquidTearStateAt(0, f + 0.25);
    EXPECT_TRUE(frame.spheres.empty()) << "a fresh drop rings visibly: a mesh";
    std::vector<const MeshInstance*> drops;
    for (const MeshInstance& m : frame.meshes)
      if (m.mesh.name == "falling drop") drops.push_back(&m);
    ASSERT_EQ(drops.size(), state.drops.size()) << f;
    for (size_t i = 0; i < state.drops.size(); ++i) {
      const MeshInstance& drop = *drops[i];
      EXPECT_LT((vertexCentroid(drop.mesh.positions) - state.drops[i].centre).norm(), 1e-6);
      EXPECT_NEAR(signedVolume(drop.mesh), state.drops[i].volume, 1e-3 * state.drops[i].volume);
      EXPECT_EQ(findClosedMeshDefect(drop.mesh), "");
      ASSERT_EQ(drop.positionsAtClose.size(), drop.mesh.positions.size()) << "deformation blur";
      const Vec3d closeCentre = vertexCentroid(drop.positionsAtClose);
      EXPECT_LT((closeCentre - atClose.drops[i].centre).norm(), 1e-6);
      EXPECT_LT(closeCentre.y(), state.drops[i].centre.y()) << "falls";
      EXPECT_NE(state.drops[i].amplitude, atClose.drops[i].amplitude) << "rings during the shutter";
    }
    ++withDrops;
    break;
  }
  std::printf("[ liquid ] drip test: %s\n", withDrops ? "a drop fell within the shot" : "no drop fell");
  EXPECT_EQ(withDrops, 1);
}

TEST(LiquidTearShot, SlidingBeadsAreMotionBlurredUnderAShutter) {
  const std::string shutter = R"(, "shutter": {"open": -0.25, "close": 0.25})";
  const Shot shot = loadTearShot("liquid_bead_blur.json", kTear, shutter);
  FrameBuilder builder(shot);
  int blurred = 0;
  for (int f = 25; f <= kFrames && blurred == 0; ++f) {
    const LiquidTearState state = builder.liquidTearStateAt(0, f - 0.25);
    if (state.beads.empty() || state.beads[0].phase != BeadPhase::Sliding) continue;
    const Frame frame = builder.build(f);  // kept: beadsOf points into it (ASan: use after free)
    const auto beads = beadsOf(frame);
    ASSERT_FALSE(beads.empty());
    const MeshInstance& bead = *beads[0];
    ASSERT_EQ(bead.positionsAtClose.size(), bead.mesh.positions.size()) << f;
    Vec3 open = Vec3::Zero(), close = Vec3::Zero();
    for (size_t i = 0; i < bead.mesh.positions.size(); ++i) {
      open += bead.mesh.positions[i];
      close += bead.positionsAtClose[i];
    }
    EXPECT_LT(close.y(), open.y()) << "frame " << f << ": the bead runs down during the shutter";
    ++blurred;
  }
  EXPECT_EQ(blurred, 1);
  // A bead at rest on a still face does not move within the shutter.
  FrameBuilder restingBuilder(shot);
  EXPECT_EQ(restingBuilder.liquidTearStateAt(0, 29.75).beads[0].phase, BeadPhase::Pinned);
  const Frame restingFrame = restingBuilder.build(30);  // kept: beadsOf points into it
  const auto resting = beadsOf(restingFrame);
  ASSERT_FALSE(resting.empty());
  EXPECT_TRUE(resting[0]->positionsAtClose.empty());
}

TEST(LiquidTearShot, VolumeBudgetIsBalanced) {
  const Shot shot = loadTearShot("liquid_budget.json");
  for (double t : {0.5, 1.2, 2.0, 3.0}) {
    const VolumeBudget budget = liquidTearVolumeBudget(shot.liquidTears[0].input, t);
    EXPECT_NEAR(budget.source, 10e-9 * t, 1e-11) << t;
    EXPECT_LT(budget.relativeImbalance(), 1e-6) << t;
  }
}

TEST(LiquidTearShot, FilmThicknessAlongThePathIsAvailable) {
  const Shot shot = loadTearShot("liquid_film.json");
  const ShotLiquidTear& tear = shot.liquidTears[0];
  FrameBuilder builder(shot);
  const LiquidTearState before = builder.liquidTearStateAt(0, 20);
  ASSERT_EQ(before.sampleFilmThickness.size(), tear.path.points.size());
  for (double h : before.sampleFilmThickness) EXPECT_EQ(h, 0.0);
  const LiquidTearState after = builder.liquidTearStateAt(0, kFrames);
  ASSERT_EQ(after.sampleFilmThickness.size(), tear.path.points.size());
  double wettest = 0.0;
  for (double h : after.sampleFilmThickness) wettest = std::max(wettest, h);
  EXPECT_GT(wettest, 1e-6);
  EXPECT_LE(wettest, tear.params.filmThickness * (1.0 + 1e-9));
}

TEST(LiquidTearShot, KeysAreConvertedToSIUnits) {
  const Shot shot = loadTearShot("liquid_keys.json",
                                 tearWith(R"("spillVolume": 8)", R"("spillVolume": 8, "wellStart": 13, "wellEnd": 49,
       "contactAngles": [100, 70], "filmThickness": 1e-5, "dryingTime": 12, "viscosity": 0.002, "gravity": [0, -2, 0],
       "skinTemperature": 34, "airTemperature": 18, "humidity": 0.3)"));
  const ShotLiquidTear& tear = shot.liquidTears[0];
  EXPECT_DOUBLE_EQ(tear.params.source.rate, 10e-9);
  EXPECT_DOUBLE_EQ(tear.params.source.overflowVolume, 10e-9);
  EXPECT_DOUBLE_EQ(tear.params.source.spillVolume, 8e-9);
  EXPECT_DOUBLE_EQ(tear.params.source.start, 0.5);
  EXPECT_DOUBLE_EQ(tear.params.source.end, 2.0);
  EXPECT_NEAR(tear.params.contactAngles.advancing, 100.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_NEAR(tear.params.contactAngles.receding, 70.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(tear.params.filmThickness, 1e-5);
  EXPECT_DOUBLE_EQ(tear.params.filmDryingTime, 12.0);
  EXPECT_DOUBLE_EQ(tear.params.viscosity, 0.002);
  EXPECT_DOUBLE_EQ(tear.params.air.skinTemperature, 34.0);
  EXPECT_DOUBLE_EQ(tear.params.air.airTemperature, 18.0);
  EXPECT_DOUBLE_EQ(tear.params.air.relativeHumidity, 0.3);
  EXPECT_EQ(tear.gravity, Vec3(0, -2, 0));
  EXPECT_FLOAT_EQ(tear.maxLength, 0.12f);
  EXPECT_EQ(tear.simulationStartFrame, 1.0);
}

TEST(LiquidTearShot, AnEarlierWellStartStartsTheSimulationBeforeTheShot) {
  // Welling from frame -23 (1 s before the shot): frame 1 shows what frame 25 of a shot welling
  // from frame 1 shows.
  const Shot early = loadTearShot("liquid_early.json", tearWith(R"("spillVolume": 8)", R"("spillVolume": 8, "wellStart": -23)"));
  const Shot late = loadTearShot("liquid_late.json");
  EXPECT_EQ(early.liquidTears[0].simulationStartFrame, -23.0);
  EXPECT_EQ(early.liquidTears[0].params.source.start, 0.0);
  FrameBuilder earlyBuilder(early), lateBuilder(late);
  for (int f : {1, 10, 40}) {
    const LiquidTearState a = earlyBuilder.liquidTearStateAt(0, f);
    const LiquidTearState b = lateBuilder.liquidTearStateAt(0, f + 24);
    EXPECT_EQ(a.time, b.time) << f;
    ASSERT_EQ(a.beads.size(), b.beads.size()) << f;
    for (size_t i = 0; i < a.beads.size(); ++i) EXPECT_EQ(a.beads[i].arcLength, b.beads[i].arcLength) << f;
  }
}

TEST(LiquidTearShot, BadKeysGiveExactMessages) {
  auto expect = [](const std::string& name, const std::string& from, const std::string& to, const std::string& message) {
    expectSingleError(name, ictFaceShot(tearWith(from, to), "", "", kFrames), message);
  };
  expect("lq_rate.json", R"("rate": 10)", R"("rate": -1)", "/tears/0/rate: expected a number >= 0, found -1");
  expect("lq_spill.json", R"("spillVolume": 8)", R"("spillVolume": 12)",
         "/tears/0/spillVolume: the spill volume (12 uL) must not exceed the overflow volume (10 uL)");
  expect("lq_angles.json", R"("spillVolume": 8)", R"("spillVolume": 8, "contactAngles": [60, 80])",
         "/tears/0/contactAngles: the receding angle (80 degrees) must not exceed the advancing angle (60 degrees)");
  expect("lq_angles_range.json", R"("spillVolume": 8)", R"("spillVolume": 8, "contactAngles": [190, 80])",
         "/tears/0/contactAngles/0: expected a number in (0, 180), found 190");
  expect("lq_well.json", R"("spillVolume": 8)", R"("spillVolume": 8, "wellStart": 20, "wellEnd": 10)",
         "/tears/0/wellEnd: welling must end at or after it starts: wellEnd 10 < wellStart 20");
  expect("lq_gravity.json", R"("spillVolume": 8)", R"("spillVolume": 8, "gravity": [0, 0, 0])",
         "/tears/0/gravity: the gravity direction must not be zero");
  expect("lq_humidity.json", R"("spillVolume": 8)", R"("spillVolume": 8, "humidity": 1.2)",
         "/tears/0/humidity: expected a number in [0, 1], found 1.2");
  expect("lq_air.json", R"("spillVolume": 8)", R"("spillVolume": 8, "airTemperature": 80)",
         "/tears/0/airTemperature: expected a number in [-20, 50], found 80");
  expect("lq_film.json", R"("spillVolume": 8)", R"("spillVolume": 8, "filmThickness": 0)",
         "/tears/0/filmThickness: expected a number > 0, found 0");
  expect("lq_typo.json", R"("spillVolume": 8)", R"("spillVolume": 8, "viscosty": 0.002)",
         "/tears/0/viscosty: unknown key 'viscosty'; did you mean 'viscosity'?");
  expect("lq_source.json", R"("source": {"landmark": 39}, )", "",
         "/tears/0: missing required key 'source' (a point [x, y, z] near the skin, {\"landmark\": i}, {\"vertex\": i} "
         "or {\"uv\": [u, v]})");
  expect("lq_short.json", R"("spillVolume": 8)", R"("spillVolume": 8, "gravity": [0, 1, 0], "maxLength": 0.001)",
         "/tears/0/source: the flow path from the source runs only 0.000887 m over part 'M_Face' before it stops (max "
         "length); a liquid tear needs at least 0.002 m (move the source or change gravity)");
}

}  // namespace liquid_tear_shot_test
}  // namespace lacrima
