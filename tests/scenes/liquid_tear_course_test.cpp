// The course of a liquid tear's flow path follows the moving face (it is traced
// again as the face moves). On an analytic surface turned a little every frame (a test LiquidTearSurface):
// each frame's course is that pose's exact steepest descent, a bead's track bends as the surface
// turns, a frame alone equals the frame in a sequence, and the volume is conserved across the
// course changes. On the default shot, the course moves with the head.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "geometry/height_field_support.hpp"
#include "lacrima/mesh/surface_point.hpp"
#include "lacrima/scenes/frame_builder.hpp"
#include "lacrima/scenes/liquid_tear.hpp"
#include "shot_support.hpp"

namespace lacrima {
namespace liquid_tear_course_test {

constexpr double kDegree = std::numbers::pi / 180.0;
// Where the tear wells: near the middle of the sheet, which turns about this point.
const Vec3 kSource(0.0113f, 0.0071f, 0.0f);

// A vertical 0.3 m square sheet (the xy plane, normal +z) turned about kSource by
// degreesPerFrame x frame about its normal. The path needs no smoothing on a plane.
class TurningSheet final : public LiquidTearSurface {
 public:
  explicit TurningSheet(double degreesPerFrame)
      : rest_(test::heightFieldMesh(30, 0.15f, [](float, float) { return 0.0f; })), degreesPerFrame_(degreesPerFrame) {}

  double angle(int frame) const { return degreesPerFrame_ * kDegree * frame; }
  const TriangleMesh& rest() const { return rest_; }

  LiquidTearSkin at(int frame) const override {
    TriangleMesh skin = rest_;
    const Mat3 turn = Eigen::AngleAxisf(float(angle(frame)), Vec3::UnitZ()).toRotationMatrix();
    for (Vec3& p : skin.positions) p = kSource + turn * (p - kSource);
    return {skin, skin};
  }
  bool sameAsPrevious(int) const override { return degreesPerFrame_ == 0.0; }

 private:
  TriangleMesh rest_;
  double degreesPerFrame_;
};

Shot shotAt24Fps() {
  Shot shot;
  shot.fps = 24.0;
  shot.frameStart = 0;
  shot.frameEnd = 72;
  return shot;
}

// A liquid tear on the sheet from frame 0: welling at `rate` uL/s, 8 uL beads; initial beads as given.
// Resolved as loadShot resolves a tear: its surface, source, and the first course's path and input.
ShotLiquidTear tearOn(const Shot& shot, const std::shared_ptr<const TurningSheet>& sheet, double rate,
                      std::vector<InitialBead> initialBeads = {}) {
  ShotLiquidTear tear;
  tear.pointer = "/tears/0";
  tear.simulationStartFrame = 0.0;
  tear.maxLength = 0.1f;
  tear.params.source.rate = rate * kMicrolitre;
  tear.params.source.overflowVolume = 8.0 * kMicrolitre;
  tear.params.source.spillVolume = 8.0 * kMicrolitre;
  tear.params.initialBeads = std::move(initialBeads);
  tear.surface = sheet;
  const SurfacePoint source = closestSurfacePoint(sheet->rest(), kSource);
  tear.sourcePoint.triangle = source.triangle;
  tear.sourcePoint.barycentric = source.barycentric;
  const std::shared_ptr<const LiquidTearCourse> first = liquidTearCoursesOf(shot, tear)->at(0);
  tear.path = first->path;
  tear.input.path = first->samples;
  tear.input.gravityDirection = tear.gravity.cast<double>();
  tear.input.params = tear.params;
  return tear;
}

// The material point of a course's point at arc length s: where it lies on the unturned sheet.
Vec3 restPosition(const TurningSheet& sheet, const FlowPath& course, double s) {
  return surfacePosition(sheet.rest(), liquidTearPathPoint(course, s));
}

// The material direction of straight down (world -y) on the sheet turned by `angle`.
Vec3 restDownAt(double angle) { return Vec3(float(std::sin(-angle)), float(-std::cos(-angle)), 0.0f); }

TEST(LiquidTearCourse, EachFramesCourseIsTheSteepestDescentOfThatFramesPose) {
  const Shot shot = shotAt24Fps();
  const auto sheet = std::make_shared<const TurningSheet>(2.0);
  const std::shared_ptr<const LiquidTearCourses> courses = liquidTearCoursesOf(shot, tearOn(shot, sheet, 0.0));
  for (int frame : {0, 4, 9, 20}) {
    const LiquidTearCourse& course = *courses->at(frame);
    EXPECT_EQ(course.frame, frame);
    EXPECT_NEAR(course.path.length(), 0.1f, 1e-6f) << frame;
    // Straight down the turned sheet: every point of the course right below the source ...
    for (const Vec3& p : course.path.positions) {
      EXPECT_NEAR(p.x(), kSource.x(), 2e-6f) << frame;
      EXPECT_LE(p.y(), kSource.y() + 1e-6f) << frame;
    }
    // ... which on the sheet itself is a direction turned back by the sheet's angle.
    const Vec3 along = (restPosition(*sheet, course.path, 0.08) - kSource).normalized();
    EXPECT_GT(along.dot(restDownAt(sheet->angle(frame))), 1.0f - 1e-6f) << frame;
  }
  EXPECT_EQ(courses->tracedCount(), 21u);  // frames 0 to 20, each traced once
}

// The bead's sliding frames: the angle (radians) of its material point below the source on the
// unturned sheet, and whether it lies on the steepest descent of the frame's pose.
struct Track {
  std::vector<int> frames;
  std::vector<double> restAngles;
  double worstOffCourse = 0.0;  // m, largest |x - source x| of the bead on the turned sheet
};

Track slidingTrack(const std::shared_ptr<const TurningSheet>& sheet) {
  const Shot shot = shotAt24Fps();
  const ShotLiquidTear tear = tearOn(shot, sheet, 0.0, {{0.004, 14.0 * kMicrolitre}});
  const std::shared_ptr<const LiquidTearCourses> courses = liquidTearCoursesOf(shot, tear);
  Track track;
  for (int frame = 1; frame <= 24; ++frame) {
    LiquidTearRun run(shot, tear, *courses);
    run.advanceTo(frame);
    const LiquidTearState state = run.state(frame);
    if (state.beads.empty() || state.beads[0].phase != BeadPhase::Sliding) continue;
    const SurfacePoint at = liquidTearPathPoint(run.course().path, state.beads[0].arcLength);
    const Vec3 onTurned = surfacePosition(sheet->at(frame).skin, at);
    track.worstOffCourse = std::max(track.worstOffCourse, double(std::abs(onTurned.x() - kSource.x())));
    const Vec3 onRest = surfacePosition(sheet->rest(), at) - kSource;
    track.frames.push_back(frame);
    track.restAngles.push_back(std::atan2(double(onRest.x()), -double(onRest.y())));
  }
  return track;
}

TEST(LiquidTearCourse, ABeadsTrackOnTheSkinBendsAsTheSurfaceTurns) {
  const Track turning = slidingTrack(std::make_shared<const TurningSheet>(3.0));
  const Track still = slidingTrack(std::make_shared<const TurningSheet>(0.0));
  ASSERT_GE(turning.frames.size(), 4u);
  ASSERT_GE(still.frames.size(), 4u);
  // On the still sheet the bead runs straight down; on the turning one it stays on each frame's
  // steepest descent, so on the skin its track turns back by the sheet's turn (3 degrees a frame).
  EXPECT_LT(still.worstOffCourse, 2e-6);
  EXPECT_NEAR(still.restAngles.back() - still.restAngles.front(), 0.0, 1e-6);
  EXPECT_LT(turning.worstOffCourse, 2e-6);
  const double frames = turning.frames.back() - turning.frames.front();
  const double bend = turning.restAngles.back() - turning.restAngles.front();
  std::printf("[ course ] bead slid frames %d-%d; its track on the skin turned by %.2f degrees (sheet: %.1f)\n",
              turning.frames.front(), turning.frames.back(), bend / kDegree, 3.0 * frames);
  EXPECT_NEAR(bend, -3.0 * kDegree * frames, 0.05 * kDegree);
}

// The shot of one liquid tear on the sheet (the frame builder's liquid tear 0).
Shot shotOfTearOn(const std::shared_ptr<const TurningSheet>& sheet, double rate) {
  Shot shot = shotAt24Fps();
  shot.liquidTears.push_back(tearOn(shot, sheet, rate));
  return shot;
}

void expectSameLiquid(const LiquidTearSimulation& a, const LiquidTearSimulation& b) {
  ASSERT_FALSE(a.beads().empty());
  ASSERT_EQ(a.beads().size(), b.beads().size());
  for (size_t i = 0; i < a.beads().size(); ++i) {
    EXPECT_EQ(a.beads()[i].arcLength, b.beads()[i].arcLength) << i;
    EXPECT_EQ(a.beads()[i].volume, b.beads()[i].volume) << i;
    EXPECT_EQ(a.beads()[i].phase, b.beads()[i].phase) << i;
  }
  EXPECT_EQ(a.cellFilmVolume(), b.cellFilmVolume());
}

TEST(LiquidTearCourse, AFrameAloneEqualsTheSameFrameInASequence) {
  const Shot shot = shotOfTearOn(std::make_shared<const TurningSheet>(1.5), 20.0);
  const ShotLiquidTear& tear = shot.liquidTears[0];
  const std::shared_ptr<const LiquidTearCourses> aloneCourses = liquidTearCoursesOf(shot, tear);
  LiquidTearRun once(shot, tear, *aloneCourses);
  once.advanceTo(40.0);
  FrameBuilder sequence(shot);
  for (double f : {3.0, 12.5, 20.0, 33.25}) sequence.liquidTearStateAt(0, f);  // fills the builder's courses
  LiquidTearRun stepwise(shot, tear, sequence.liquidTearCourses(0));
  for (double f : {5.0, 17.75, 30.0, 40.0}) stepwise.advanceTo(f);
  ASSERT_GT(once.reroutes(), 30);
  EXPECT_EQ(once.reroutes(), stepwise.reroutes());
  EXPECT_EQ(once.course().frame, 40);
  EXPECT_EQ(stepwise.course().frame, 40);
  expectSameLiquid(once.simulation(), stepwise.simulation());
  EXPECT_EQ(once.course().path.positions, stepwise.course().path.positions);
}

// The builder continues the run it advanced last when asked for a later time and starts again when
// asked for an earlier one: either way the state of a run from the start.
TEST(LiquidTearCourse, ABuildersStateIsARunFromTheStartWhateverWasAskedBefore) {
  const Shot shot = shotOfTearOn(std::make_shared<const TurningSheet>(1.5), 20.0);
  const ShotLiquidTear& tear = shot.liquidTears[0];
  FrameBuilder builder(shot);
  for (double f : {20.0, 40.0, 10.0, 10.5}) {
    const LiquidTearState kept = builder.liquidTearStateAt(0, f);
    const std::shared_ptr<const LiquidTearCourses> courses = liquidTearCoursesOf(shot, tear);
    LiquidTearRun fresh(shot, tear, *courses);
    fresh.advanceTo(f);
    const LiquidTearState expected = fresh.state(f);
    ASSERT_FALSE(expected.beads.empty()) << f;
    ASSERT_EQ(kept.beads.size(), expected.beads.size()) << f;
    for (size_t i = 0; i < expected.beads.size(); ++i) {
      EXPECT_EQ(kept.beads[i].arcLength, expected.beads[i].arcLength) << f << " bead " << i;
      EXPECT_EQ(kept.beads[i].volume, expected.beads[i].volume) << f << " bead " << i;
    }
    EXPECT_EQ(kept.sampleFilmThickness, expected.sampleFilmThickness) << f;
    EXPECT_EQ(builder.liquidTearCourseAt(0, f)->path.positions, fresh.course().path.positions) << f;
  }
}

TEST(LiquidTearCourse, TheVolumeIsConservedAcrossTheCourseChanges) {
  const Shot shot = shotAt24Fps();
  const ShotLiquidTear tear = tearOn(shot, std::make_shared<const TurningSheet>(2.0), 20.0);
  const std::shared_ptr<const LiquidTearCourses> courses = liquidTearCoursesOf(shot, tear);
  for (int frame : {12, 24, 48, 72}) {
    LiquidTearRun run(shot, tear, *courses);
    run.advanceTo(frame);
    const VolumeBudget budget = run.simulation().budget();
    EXPECT_NEAR(budget.source, 20e-9 * frame / 24.0, 1e-12) << frame;
    EXPECT_LT(budget.relativeImbalance(), 1e-6) << frame;
    EXPECT_EQ(run.reroutes(), frame) << frame;  // one course per frame, from frame 0
    if (frame == 72) {
      EXPECT_GT(budget.film, 0.0);
    }
  }
}

TEST(LiquidTearCourse, AStillSurfaceKeepsOneCourseAndNeverReroutes) {
  const Shot shot = shotAt24Fps();
  const ShotLiquidTear tear = tearOn(shot, std::make_shared<const TurningSheet>(0.0), 20.0);
  const std::shared_ptr<const LiquidTearCourses> courses = liquidTearCoursesOf(shot, tear);
  LiquidTearRun run(shot, tear, *courses);
  run.advanceTo(60.0);
  EXPECT_EQ(run.reroutes(), 0);
  EXPECT_EQ(courses->tracedCount(), 1u);
  EXPECT_EQ(courses->at(60), courses->at(0));
  // Bitwise the simulation on the single path, as before courses moved.
  LiquidTearSimulation fixed(tear.input);
  fixed.advanceTo(liquidTearSeconds(shot, tear, 60.0));
  ASSERT_EQ(fixed.beads().size(), run.simulation().beads().size());
  for (size_t i = 0; i < fixed.beads().size(); ++i) EXPECT_EQ(fixed.beads()[i].arcLength, run.simulation().beads()[i].arcLength);
  EXPECT_EQ(fixed.cellFilmVolume(), run.simulation().cellFilmVolume());
}

// The default shot: the head nods (head.rx 6 -> 7.2 -> 6.8 degrees, the sobs add up to 1.5) and turns
// (head.ry to -0.8) and the face cries, so the hero eye's liquid tear runs down a slightly different
// course at the last frame. Measured over the length both courses share (frame 72's stops earlier,
// in a pit under the jaw).
TEST(LiquidTearCourse, OnTheDefaultShotTheCourseMovesWithTheHead) {
  const Shot shot = loadShot(test::sourcePath("scenes/shots/tear_closeup.json"));
  ASSERT_EQ(shot.liquidTears.size(), 1u);
  const FrameBuilder builder(shot);
  const LiquidTearCourses& courses = builder.liquidTearCourses(0);
  const auto start = std::chrono::steady_clock::now();
  const std::shared_ptr<const LiquidTearCourse> first = courses.at(1), last = courses.at(72);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_NE(first, last);
  // Both courses as material points on the last frame's skin: how far the re-routing moved the course.
  const TriangleMesh skin = courses.surface().at(72).skin;
  const FlowPathTransfer transfer(first->path, last->path, skin);
  double widest = 0.0, widestAt = 0.0;
  const double shared = std::min(first->path.length(), last->path.length());
  for (double s = 0.0; s <= shared; s += 5e-4)
    if (transfer.sidewaysStep(s) > widest) widest = transfer.sidewaysStep(s), widestAt = s;
  const double endStep = transfer.sidewaysStep(first->path.length());
  const double worldEnd = (first->path.positions.back() - last->path.positions.back()).norm();
  std::printf("[ course ] default shot: %zu courses traced for frames %d-72 in %.2f s; frame 1: %.1f mm long, "
              "frame 72: %.1f mm (stop: %s); on the frame-72 skin the course moved by up to %.2f mm (at s = %.0f mm), "
              "%.2f mm at its end; the end moved %.2f mm in space\n",
              courses.tracedCount(), courses.firstFrame(), seconds, 1e3 * first->path.length(),
              1e3 * last->path.length(), flowStopName(last->path.stop), 1e3 * widest, 1e3 * widestAt, 1e3 * endStep,
              1e3 * worldEnd);
  EXPECT_GT(widest, 2e-4);  // re-routed by the head's turn, not only carried along by the skin
  EXPECT_LT(widest, 5e-3);  // a degree of turn: millimetres, not a different course
  EXPECT_GT(worldEnd, 1e-3);
}

}  // namespace liquid_tear_course_test
}  // namespace lacrima
