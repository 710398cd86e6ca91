// The wet trail of liquid tears on the skin mesh (MeshInstance::wetness, liquid_tear_film.hpp):
// dry before the first bead, film along the path behind a sliding bead and none far from it,
// drying after the bead has passed, edges that wander, and frames independent of their order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lacrima/mesh/surface_point.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "frame/liquid_tear_film.hpp"  // scenes/src: the film and its definition evaluated directly
#include "shot_support.hpp"

namespace lacrima {
namespace liquid_tear_film_test {

using test::ictFaceShot;
using test::writeShot;

// One overflow at 1 s (frame 25; welling stops at frame 26): 14 uL run 7 cm down the cheek within
// half a second and hang there; the film dries in 2 s so that drying shows within the shot.
const std::string kTear =
    R"("tears": [{"type": "liquid", "asset": "face", "part": "M_Face", "source": {"landmark": 39}, "material": "water",
       "rate": 14, "overflowVolume": 14, "spillVolume": 14, "wellEnd": 26, "dryingTime": 2}])";
constexpr int kFrames = 72;

Shot loadFilmShot(const std::string& name) { return loadShot(writeShot(name, ictFaceShot(kTear, "", "", kFrames))); }

// The skin the tear runs over, as rendered in the frame.
const MeshInstance& skinOf(const Frame& frame, const Shot& shot) {
  const std::string name = "face/" + shot.assets[0].gltf->primitives[shot.liquidTears[0].sourcePoint.primitive].name;
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name == name) return m;
  ADD_FAILURE() << "no mesh " << name;
  return frame.meshes.front();
}

// The skin vertex nearest to a point.
size_t nearestVertex(const TriangleMesh& mesh, const Vec3& p) {
  size_t best = 0;
  float bestDistance = std::numeric_limits<float>::infinity();
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const float d = (mesh.positions[v] - p).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = v;
    }
  }
  return best;
}

// Arc length of the single bead at a frame (the test tear has one), or -1 without one.
double beadArcLength(FrameBuilder& builder, int frame) {
  const LiquidTearState state = builder.liquidTearStateAt(0, frame);
  return state.beads.empty() ? -1.0 : state.beads.front().arcLength;
}

// A frame in which the bead has run at least 2 cm down the path.
int frameAfterTheBeadRan(FrameBuilder& builder) {
  for (int f = 25; f <= kFrames; ++f)
    if (beadArcLength(builder, f) > 0.02) return f;
  ADD_FAILURE() << "the bead never ran 2 cm";
  return kFrames;
}

TEST(LiquidTearFilm, SkinIsDryBeforeTheFirstBead) {
  const Shot shot = loadFilmShot("film_dry.json");
  FrameBuilder builder(shot);
  ASSERT_LT(beadArcLength(builder, 20), 0.0);
  EXPECT_TRUE(skinOf(builder.build(20), shot).wetness.empty());
}

TEST(LiquidTearFilm, TrailBehindTheBeadIsWetAndFarSkinDry) {
  const Shot shot = loadFilmShot("film_trail.json");
  FrameBuilder builder(shot);
  const int f = frameAfterTheBeadRan(builder);
  const Frame frame = builder.build(f);
  const MeshInstance& skin = skinOf(frame, shot);
  ASSERT_EQ(skin.wetness.size(), skin.mesh.vertexCount());
  const ShotLiquidTear& tear = shot.liquidTears[0];
  const LiquidTearState state = builder.liquidTearStateAt(0, f);
  // Skin vertices on the trail, 0.5 to 1.5 cm behind the bead: wet, about as thick as the film.
  const double bead = beadArcLength(builder, f);
  int onTrail = 0;
  for (double s = bead - 0.015; s < bead - 0.005; s += 0.002) {
    const size_t v = nearestVertex(skin.mesh, surfacePosition(skin.mesh, liquidTearPathPoint(tear, s)));
    const double distance = (skin.mesh.positions[v] - surfacePosition(skin.mesh, liquidTearPathPoint(tear, s))).norm();
    if (distance > 1e-3) continue;  // the vertex is too far off the path to be in the film's flat part
    ++onTrail;
    EXPECT_GT(skin.wetness[v], 5e-6f) << "s " << s;
    EXPECT_LE(skin.wetness[v], float(tear.params.filmThickness) * 1.0001f) << "s " << s;
  }
  EXPECT_GE(onTrail, 2);
  // Skin more than 2 cm from every point of the path is dry.
  std::vector<Vec3> path;
  for (double s = 0.0; s <= tear.path.length(); s += 5e-4) path.push_back(surfacePosition(skin.mesh, liquidTearPathPoint(tear, s)));
  int far = 0, wetCount = 0;
  for (size_t v = 0; v < skin.mesh.positions.size(); ++v) {
    if (skin.wetness[v] > 0.0f) ++wetCount;
    float nearest = std::numeric_limits<float>::infinity();
    for (const Vec3& p : path) nearest = std::min(nearest, (skin.mesh.positions[v] - p).norm());
    if (nearest < 0.02f) continue;
    ++far;
    EXPECT_EQ(skin.wetness[v], 0.0f) << "vertex " << v;
  }
  EXPECT_GT(far, 1000);
  EXPECT_GT(wetCount, 5);
  std::printf("[ film ] frame %d: bead at s = %.1f mm, %d wet skin vertices, film %.1f um at the source\n", f,
              bead * 1e3, wetCount, state.sampleFilmThickness.front() * 1e6);
}

TEST(LiquidTearFilm, TrailDriesAfterTheBeadHasPassed) {
  const Shot shot = loadFilmShot("film_drying.json");
  FrameBuilder builder(shot);
  const int f = frameAfterTheBeadRan(builder);
  const Frame firstFrame = builder.build(f);
  const MeshInstance& first = skinOf(firstFrame, shot);
  ASSERT_FALSE(first.wetness.empty());
  const size_t v = size_t(std::max_element(first.wetness.begin(), first.wetness.end()) - first.wetness.begin());
  float previous = first.wetness[v];
  for (int later = f + 6; later <= std::min(f + 30, kFrames); later += 6) {
    const Frame frame = builder.build(later);
    const float now = skinOf(frame, shot).wetness.at(v);
    EXPECT_GT(now, 0.0f) << "frame " << later;
    EXPECT_LT(now, previous) << "frame " << later;
    previous = now;
  }
  // Drying is exp(-t / 2 s): after up to 1.25 s clearly thinner, not gone.
  EXPECT_LT(previous, 0.8f * first.wetness[v]);
}

// Per 1 mm of arc length along the trail, the distance from the path of its farthest wet vertex:
// where the trail's edge lies there.
std::vector<float> edgeDistances(const Shot& shot, const Frame& frame, double from, double to) {
  const MeshInstance& skin = skinOf(frame, shot);
  const ShotLiquidTear& tear = shot.liquidTears[0];
  std::vector<Vec3> path;
  std::vector<double> arc;
  for (double s = 0.0; s <= tear.path.length(); s += 2.5e-4) {
    path.push_back(surfacePosition(skin.mesh, liquidTearPathPoint(tear, s)));
    arc.push_back(s);
  }
  std::vector<float> edge(size_t((to - from) / 1e-3), 0.0f);
  for (size_t v = 0; v < skin.wetness.size(); ++v) {
    if (!(skin.wetness[v] > 0.0f)) continue;
    size_t nearest = 0;
    float distance = std::numeric_limits<float>::infinity();
    for (size_t i = 0; i < path.size(); ++i) {
      const float d = (skin.mesh.positions[v] - path[i]).norm();
      if (d < distance) distance = d, nearest = i;
    }
    if (arc[nearest] < from || arc[nearest] >= to) continue;
    float& bin = edge[std::min(edge.size() - 1, size_t((arc[nearest] - from) / 1e-3))];
    bin = std::max(bin, distance);
  }
  return edge;
}

double relativeSpread(const std::vector<float>& values) {
  double sum = 0.0, sum2 = 0.0;
  for (float v : values) sum += v, sum2 += double(v) * v;
  const double mean = sum / double(values.size());
  return std::sqrt(std::max(0.0, sum2 / double(values.size()) - mean * mean)) / mean;
}

TEST(LiquidTearFilm, TheTrailsEdgeWandersAndReachesNoFurtherThanBefore) {
  Shot shot = loadFilmShot("film_edge.json");
  const ShotLiquidTear& tear = shot.liquidTears[0];
  FrameBuilder builder(shot);
  const Frame firstFrame = builder.build(shot.frameStart);
  const MeshInstance& firstSkin = skinOf(firstFrame, shot);
  ASSERT_EQ(tear.filmEdgeVariation.size(), firstSkin.mesh.vertexCount());  // one value per vertex, fixed
  for (float v : tear.filmEdgeVariation) ASSERT_TRUE(v >= -1.0f && v <= 1.0f);
  const int f = frameAfterTheBeadRan(builder);
  const double bead = beadArcLength(builder, f);
  const std::vector<float> wandering = edgeDistances(shot, builder.build(f), 0.004, bead - 0.004);
  shot.liquidTears[0].filmEdgeVariation.clear();  // the straight-edged trail, for comparison (the builder reads it)
  const std::vector<float> straight = edgeDistances(shot, builder.build(f), 0.004, bead - 0.004);
  ASSERT_GE(wandering.size(), 8u);
  const double spreadWandering = relativeSpread(wandering), spreadStraight = relativeSpread(straight);
  std::printf("[ film ] edge distance from the path over %zu mm: spread %.3f wandering, %.3f straight\n",
              wandering.size(), spreadWandering, spreadStraight);
  EXPECT_GT(spreadWandering, 1.3 * spreadStraight);
  EXPECT_GT(spreadWandering, 0.05);
  // The wandering edge stays within the straight trail's reach (1.5 half widths, where the trail's
  // skin refinement ends), up to a vertex spacing.
  const float straightReach = *std::max_element(straight.begin(), straight.end());
  EXPECT_LE(*std::max_element(wandering.begin(), wandering.end()), straightReach * (1.5f / 1.1f) + 3e-4f);
}

// addLiquidTearFilm finds each vertex's pieces through a grid, measures a cell's vertices in one
// vectorised loop, skips pieces too thin or too far for a vertex's edge, and stops early: none of
// that may change the film, which must equal the maximum over every piece at every vertex, bitwise,
// with the wandering edge and without it, while the bead runs and while the trail dries.
TEST(LiquidTearFilm, EqualsItsDefinitionOverEveryPieceAtEveryVertex) {
  Shot shot = loadFilmShot("film_definition.json");
  FrameBuilder builder(shot);
  const int running = frameAfterTheBeadRan(builder);
  for (const int f : {running, std::min(running + 12, kFrames)}) {
    const TriangleMesh skin = skinOf(builder.build(f), shot).mesh;
    for (const bool wandering : {true, false}) {
      ShotLiquidTear tear = shot.liquidTears[0];
      if (!wandering) tear.filmEdgeVariation.clear();
      LiquidTearRun run(shot, tear, builder.liquidTearCourses(0));
      run.advanceTo(double(f));
      std::vector<float> film, definition;
      shotfile::addLiquidTearFilm(tear, run.coursePointer()->path, run.simulation(), skin, film);
      shotfile::addLiquidTearFilmOverEveryPiece(tear, run.coursePointer()->path, run.simulation(), skin, definition);
      ASSERT_EQ(film.size(), skin.vertexCount()) << "frame " << f;
      const long wet = std::count_if(film.begin(), film.end(), [](float w) { return w > 0.0f; });
      EXPECT_GT(wet, 100) << "frame " << f;
      EXPECT_TRUE(film == definition) << "frame " << f << (wandering ? ", wandering edge" : ", straight edge");
    }
  }
}

TEST(LiquidTearFilm, AFrameAloneEqualsTheSameFrameInASequence) {
  const Shot shot = loadFilmShot("film_alone.json");
  const std::vector<float> alone = skinOf(buildFrame(shot, 40), shot).wetness;
  ASSERT_FALSE(alone.empty());
  FrameBuilder sequence(shot);
  for (int f : {10, 30, 35}) sequence.build(f);
  EXPECT_EQ(skinOf(sequence.build(40), shot).wetness, alone);
}

}  // namespace liquid_tear_film_test
}  // namespace lacrima
