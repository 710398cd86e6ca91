// Moving the liquid onto a new course of its flow path (the path is traced again as the face
// moves): LiquidTearSimulation::reroute carries beads and film by an arc-length map and
// conserves the volume; FlowPathTransfer computes that map between two traced courses (exact on
// a plane: the projection of one straight course onto another).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/height_field_support.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/mesh/flow_path_transfer.hpp"
#include "lacrima/liquid/liquid_tear.hpp"

namespace lacrima {
namespace liquid_tear_reroute_test {

constexpr double kUl = kMicrolitre;

// A vertical wall (normal +z) with samples every millimetre straight down from the origin.
std::vector<LiquidPathSample> wallPath(double length) {
  std::vector<LiquidPathSample> path;
  const int count = int(std::lround(length / 1e-3));
  for (int i = 0; i <= count; ++i) path.push_back({i * 1e-3, Vec3d(0.0, -i * 1e-3, 0.0), Vec3d::UnitZ()});
  return path;
}

// Welling at 20 uL/s with 8 uL spills: beads slide down the wall and lay film.
LiquidTearInput wellingWall(double length) {
  LiquidTearInput input;
  input.path = wallPath(length);
  input.params.source.rate = 20.0 * kUl;
  input.params.source.overflowVolume = 8.0 * kUl;
  input.params.source.spillVolume = 8.0 * kUl;
  return input;
}

double filmVolume(const LiquidTearSimulation& simulation) {
  double sum = 0.0;
  for (double v : simulation.cellFilmVolume()) sum += v;
  return sum;
}

TEST(LiquidTearReroute, TheIdentityOntoTheSameCourseChangesNothing) {
  LiquidTearSimulation moved(wellingWall(0.1)), kept(wellingWall(0.1));
  moved.advanceTo(0.8);
  kept.advanceTo(0.8);
  ASSERT_GT(filmVolume(kept), 0.0);
  moved.reroute(kept.path(), [](double s) { return s; });
  ASSERT_EQ(moved.beads().size(), kept.beads().size());
  for (size_t i = 0; i < kept.beads().size(); ++i) {
    EXPECT_EQ(moved.beads()[i].arcLength, kept.beads()[i].arcLength);
    EXPECT_EQ(moved.beads()[i].phase, kept.beads()[i].phase);
  }
  for (size_t c = 0; c < kept.cellFilmVolume().size(); ++c)
    EXPECT_NEAR(moved.cellFilmVolume()[c], kept.cellFilmVolume()[c], 1e-12 * filmVolume(kept)) << c;
  moved.advanceTo(1.5);
  kept.advanceTo(1.5);
  for (size_t i = 0; i < kept.beads().size(); ++i) EXPECT_NEAR(moved.beads()[i].arcLength, kept.beads()[i].arcLength, 1e-9);
}

TEST(LiquidTearReroute, BeadsAndFilmFollowTheMapAndTheVolumeIsConservedThroughEverySwitch) {
  LiquidTearSimulation simulation(wellingWall(0.1));
  simulation.advanceTo(0.6);
  std::vector<double> before;
  for (const Bead& bead : simulation.beads()) before.push_back(bead.arcLength);
  const double film = filmVolume(simulation);
  ASSERT_GT(film, 0.0);
  const double thickness = simulation.filmThicknessAt(0.004);
  ASSERT_GT(thickness, 0.0);
  // The new course is the old one stretched by 10%: the same material point is 1.1 times as far.
  simulation.reroute(wallPath(0.11), [](double s) { return 1.1 * s; });
  for (size_t i = 0; i < before.size(); ++i) EXPECT_NEAR(simulation.beads()[i].arcLength, 1.1 * before[i], 1e-12) << i;
  EXPECT_NEAR(filmVolume(simulation), film, 1e-12 * film);
  EXPECT_NEAR(simulation.filmThicknessAt(1.1 * 0.004), thickness / 1.1, 0.02 * thickness);  // same volume, longer
  EXPECT_LT(simulation.budget().relativeImbalance(), 1e-9);
  // Then a switch every 1/24 s between a stretched, a shifted and the plain course for 3 s.
  for (int k = 1; k <= 72; ++k) {
    simulation.advanceTo(0.6 + k / 24.0);
    if (k % 3 == 0) simulation.reroute(wallPath(0.1), [](double s) { return s / 1.1; });
    if (k % 3 == 1) simulation.reroute(wallPath(0.105), [](double s) { return std::max(0.0, s - 0.002); });
    if (k % 3 == 2) simulation.reroute(wallPath(0.11), [](double s) { return 1.1 * (s + 0.002); });
    EXPECT_LT(simulation.budget().relativeImbalance(), 1e-6) << k;
  }
  // The liquid kept flowing across the switches: it ran about as far as on a course that never moved.
  LiquidTearSimulation plain(wellingWall(0.1));
  plain.advanceTo(simulation.time());
  const auto farthest = [](const LiquidTearSimulation& s) {
    double far = 0.0;
    for (const Bead& bead : s.beads()) far = std::max(far, bead.arcLength);
    return far;
  };
  std::printf("[ reroute ] farthest bead after 3.6 s: %.1f mm with 72 course changes, %.1f mm without\n",
              1e3 * farthest(simulation), 1e3 * farthest(plain));
  EXPECT_NEAR(farthest(simulation), farthest(plain), 0.2 * farthest(plain));
}

TEST(LiquidTearReroute, AHangingBeadIsReleasedWhenTheNewCourseRunsOnPastIt) {
  LiquidTearInput input;
  input.path = wallPath(0.03);
  input.params.source.rate = 0.0;
  input.params.initialBeads = {{0.01, 12.0 * kUl}};
  LiquidTearSimulation simulation(input);
  simulation.advanceTo(0.5);
  ASSERT_EQ(simulation.beads()[0].phase, BeadPhase::Hanging);
  const double hangingAt = simulation.beads()[0].arcLength;
  EXPECT_NEAR(hangingAt, 0.03, 1e-12);
  // The face turned: the course now runs on for another 5 cm below the same point.
  simulation.reroute(wallPath(0.08), [](double s) { return s; });
  EXPECT_EQ(simulation.beads()[0].phase, BeadPhase::Pinned);
  simulation.advanceTo(1.5);
  EXPECT_GT(simulation.beads()[0].arcLength, hangingAt + 0.01);
}

TEST(LiquidTearReroute, RejectsABadCourseOrMapAndKeepsItsState) {
  LiquidTearSimulation simulation(wellingWall(0.1));
  simulation.advanceTo(0.7);
  const std::vector<Bead> beads = simulation.beads();
  const std::vector<double> film = simulation.cellFilmVolume();
  try {
    simulation.reroute({wallPath(0.1).front()}, [](double s) { return s; });
    ADD_FAILURE() << "a one-sample course was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "liquid tear: the path needs at least 2 samples, got 1");
  }
  try {
    simulation.reroute(wallPath(0.1), [](double s) { return s > 0.01 ? std::nan("") : s; });
    ADD_FAILURE() << "a map giving NaN was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a finite length"), std::string::npos) << e.what();
  }
  ASSERT_EQ(simulation.beads().size(), beads.size());
  for (size_t i = 0; i < beads.size(); ++i) EXPECT_EQ(simulation.beads()[i].arcLength, beads[i].arcLength);
  EXPECT_EQ(simulation.cellFilmVolume(), film);
}

// Two courses on a flat sheet (the xy plane) under gravities `a` degrees apart: straight lines from
// the same start. A material point at s on the first lies s cos a along the second and s sin a off it.
TEST(FlowPathTransfer, OnAPlaneTheImageIsTheProjectionOntoTheNewCourse) {
  const TriangleMesh sheet = test::heightFieldMesh(20, 0.1f, [](float, float) { return 0.0f; });
  const TriangleAdjacency adjacency = buildTriangleAdjacency(sheet);
  const SurfacePoint start = closestSurfacePoint(sheet, Vec3(0.013f, 0.085f, 0.0f));
  FlowPathOptions options;
  options.maxLength = 0.12f;
  const double a = 25.0 * std::numbers::pi / 180.0;
  const FlowPath down = traceFlowPath(sheet, adjacency, start, Vec3(0, -1, 0), options);
  const FlowPath turned = traceFlowPath(sheet, adjacency, start, Vec3(float(std::sin(a)), -float(std::cos(a)), 0), options);
  ASSERT_NEAR(down.length(), 0.12f, 1e-6f);
  ASSERT_NEAR(turned.length(), 0.12f, 1e-6f);
  const FlowPathTransfer transfer(down, turned, sheet);
  for (double s : {0.0, 0.01, 0.037, 0.08, 0.1}) {
    EXPECT_NEAR(transfer(s), s * std::cos(a), 2e-6) << s;
    EXPECT_NEAR(transfer.sidewaysStep(s), s * std::sin(a), 2e-6) << s;
  }
  // Back the other way the same holds; and a course onto itself is the identity.
  const FlowPathTransfer back(turned, down, sheet), same(down, down, sheet);
  EXPECT_NEAR(back(0.05), 0.05 * std::cos(a), 2e-6);
  EXPECT_NEAR(same(0.0437), 0.0437, 1e-6);
  EXPECT_THROW(FlowPathTransfer(FlowPath{}, down, sheet), InputError);
}

}  // namespace liquid_tear_reroute_test
}  // namespace lacrima
