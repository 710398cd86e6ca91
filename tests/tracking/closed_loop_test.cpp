// The tracker closed on itself (lacrima/tracking/performance_tracker.hpp): a known performance of
// the ICT face (a keyed blend of archetypal expressions; the head still for half a second, then
// turning and sliding) is captured by the synthetic depth sensor with a Kinect's noise and 68
// landmarks, tracked frame by frame, and compared with the truth: weights, vertices, head pose,
// and the jitter of a still head, with and without Weise et al.'s animation prior and pose filter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "lacrima/tracking/initial_pose.hpp"
#include "lacrima/tracking/performance_tracker.hpp"
#include "tracking/tracking_support.hpp"

namespace lacrima::tracking {
namespace closed_loop_test {

struct Errors {
  double weightRmse = 0.0, vertexMm = 0.0, poseDegrees = 0.0, poseMm = 0.0;
  double stillJitterMm = 0.0, stillJitterDegrees = 0.0;  // frame-to-frame pose change while the head is still
};

constexpr int kFrames = 40, kStillFrames = 15;

Eigen::Isometry3d truePose(int frame) {
  const double moving = std::max(0, frame - kStillFrames);
  return test::headPose(0.7, Vec3d(0.0, 0.5 * moving, 0.0), Vec3d(0.001 * moving, 0.0, 0.0));
}

Errors trackPerformance(const AnimationPrior* prior, bool filter, const WeightSequence& truth) {
  const BlendshapeModel& model = test::ictModel();
  TrackerParams params;
  params.filterPose = filter;
  params.upperFaceAbove = noseTipHeight(model);
  PerformanceTracker tracker(model, prior, params, truePose(0));
  Errors e;
  Eigen::Isometry3d last = truePose(0);
  int still = 0;
  for (int i = 0; i < kFrames; ++i) {
    const test::Capture c = test::capture(model, truth[size_t(i)], truePose(i), 1.0, 1.0, uint64_t(100 + i));
    const TrackedFrame t = tracker.track(c.depth, c.landmarks);
    e.weightRmse += (t.weights - truth[size_t(i)]).squaredNorm() / double(model.targetCount()) / kFrames;
    e.vertexMm += test::vertexRmsMm(model, t.weights, truth[size_t(i)]) / kFrames;
    e.poseDegrees += test::degreesBetween(t.pose, truePose(i)) / kFrames;
    e.poseMm += 1e3 * (t.pose.translation() - truePose(i).translation()).norm() / kFrames;
    if (i > 2 && i < kStillFrames) {
      e.stillJitterMm += std::pow(1e3 * (t.pose.translation() - last.translation()).norm(), 2);
      e.stillJitterDegrees += std::pow(test::degreesBetween(t.pose, last), 2);
      ++still;
    }
    last = t.pose;
  }
  e.weightRmse = std::sqrt(e.weightRmse);
  e.stillJitterMm = std::sqrt(e.stillJitterMm / still), e.stillJitterDegrees = std::sqrt(e.stillJitterDegrees / still);
  return e;
}

TEST(ClosedLoop, TheFirstFramesPoseComesFromTheLandmarksAndTheirDepth) {
  const Eigen::Isometry3d truth = test::headPose(0.65, Vec3d(-4, 10, 3), Vec3d(0.02, -0.01, 0.0));
  const test::Capture c = test::capture(test::ictModel(), Eigen::VectorXd::Zero(57), truth, 1.0, 1.0, 5);
  const auto pose = poseFromLandmarks(test::ictModel(), c.depth, c.landmarks);
  ASSERT_TRUE(pose);
  const double degrees = test::degreesBetween(*pose, truth), mm = 1e3 * (pose->translation() - truth.translation()).norm();
  TrackerParams params;
  params.upperFaceAbove = noseTipHeight(test::ictModel());
  PerformanceTracker tracker(test::ictModel(), nullptr, params, *pose);
  const TrackedFrame refined = tracker.track(c.depth, c.landmarks);
  const double refinedDegrees = test::degreesBetween(refined.rawPose, truth);
  const double refinedMm = 1e3 * (refined.rawPose.translation() - truth.translation()).norm();
  std::printf("[ closed loop ] the first pose from the inner landmarks: %.2f degrees, %.1f mm off; after ICP %.3f "
              "degrees, %.2f mm\n",
              degrees, mm, refinedDegrees, refinedMm);
  // Measured: 0.52 degrees and 0.9 mm, then 0.047 degrees and 0.10 mm after ICP.
  EXPECT_LT(degrees, 1.5) << "close enough for ICP to take over";
  EXPECT_LT(mm, 3.0);
  EXPECT_LT(refinedDegrees, 0.2);
  EXPECT_LT(refinedMm, 0.5);
}

TEST(ClosedLoop, ThePriorAndTheFilterMakeATrackedPerformanceCloserAndSteadier) {
  const BlendshapeModel& model = test::ictModel();
  const AnimationPrior prior = archetypalPrior(model.targetNames);
  const std::vector<Eigen::VectorXd> expressions = archetypalExpressions(model.targetNames);
  const WeightSequence truth = keyedPerformance(expressions, kFrames, 77);
  const Errors neither = trackPerformance(nullptr, false, truth), priorOnly = trackPerformance(&prior, false, truth);
  const Errors filterOnly = trackPerformance(nullptr, true, truth), both = trackPerformance(&prior, true, truth);
  for (const auto& [name, e] : {std::pair{"neither", neither}, std::pair{"prior only", priorOnly},
                                std::pair{"filter only", filterOnly}, std::pair{"prior and filter", both}})
    std::printf("[ closed loop ] %s: weight RMSE %.4f, vertices %.3f mm, head %.3f degrees %.3f mm off; still head "
                "jitter %.3f mm %.3f degrees a frame\n",
                name, e.weightRmse, e.vertexMm, e.poseDegrees, e.poseMm, e.stillJitterMm, e.stillJitterDegrees);
  // The prior recovers the weights better (measured: 0.071 -> 0.021 without the filter); the filter
  // steadies a still head (0.18 mm and 0.15 degrees a frame -> 0.03 mm and 0.03 degrees) but lags
  // a moving one (head 0.18 -> 0.50 mm off, which the fit absorbs: vertices 0.26 -> 0.35 mm with
  // both). Measured 2026-12-05 (second session); docs/tracking.md has the table.
  EXPECT_LT(priorOnly.weightRmse, 0.6 * neither.weightRmse);
  EXPECT_LT(both.weightRmse, 0.7 * neither.weightRmse);
  EXPECT_LT(filterOnly.stillJitterMm, 0.5 * neither.stillJitterMm);
  EXPECT_LT(filterOnly.stillJitterDegrees, 0.5 * neither.stillJitterDegrees);
  EXPECT_LT(both.stillJitterDegrees, 0.5 * neither.stillJitterDegrees);
  EXPECT_LT(both.poseDegrees, 0.5);
  EXPECT_LT(both.poseMm, 2.0);
}

// A blink as fast as the default shot's (lids shut in two frames, open in four) on a still, neutral
// face: the eyeBlink_L weight the tracker gives each frame, with `prior`.
std::vector<double> trackedBlink(const AnimationPrior& prior) {
  const BlendshapeModel& model = test::ictModel();
  const Eigen::VectorXd shut = blinkExpression(model.targetNames);
  const std::vector<double> closure = {0, 0, 0, 0, 0, 0, 0, 0, 0.5, 1, 1, 1, 0.8, 0.6, 0.4, 0.2, 0, 0};
  const long left = long(std::find(model.targetNames.begin(), model.targetNames.end(), "eyeBlink_L") - model.targetNames.begin());
  TrackerParams params;
  params.filterPose = false;
  params.upperFaceAbove = noseTipHeight(model);
  PerformanceTracker tracker(model, &prior, params, truePose(0));
  std::vector<double> blink;
  for (size_t i = 0; i < closure.size(); ++i) {
    const test::Capture c = test::capture(model, closure[i] * shut, truePose(0), 1.0, 1.0, uint64_t(300 + i));
    blink.push_back(tracker.track(c.depth, c.landmarks).weights[left]);
  }
  return blink;
}

TEST(ClosedLoop, ThePriorLetsAFastBlinkThrough) {
  const BlendshapeModel& model = test::ictModel();
  AnimationPriorParams seedVariance = archetypalPriorParams();
  seedVariance.keptVariance = 0.99;
  const std::vector<double> kept = trackedBlink(archetypalPrior(model.targetNames));
  const std::vector<double> dropped = trackedBlink(archetypalPrior(model.targetNames, seedVariance));
  std::printf("[ closed loop ] a blink (truth 0.5 1 1 1 0.8 0.6 0.4 0.2 0 from frame 9): 99.9 %% of the variance kept:");
  for (size_t i = 8; i < kept.size(); ++i) std::printf(" %.2f", kept[i]);
  std::printf("; 99 %%:");
  for (size_t i = 8; i < dropped.size(); ++i) std::printf(" %.2f", dropped[i]);
  std::printf("\n");
  const double keptPeak = *std::max_element(kept.begin(), kept.end());
  const double droppedPeak = *std::max_element(dropped.begin(), dropped.end());
  // Measured: 0.03 0.41 0.90 1.00 0.72 0.43 0.31 0.31 0.26 0.13 against 0.5 1 1 1 0.8 0.6 0.4 0.2 0 0
  // (a frame late at the onset, the lids shut), and 0.03 0.16 0.31 0.51 0.65 0.75 0.78 ... at 99 %.
  EXPECT_GT(keptPeak, 0.85);
  EXPECT_GT(kept[10], 0.7) << "shut by the blink's third frame";
  EXPECT_LT(kept.back(), 0.15) << "open again";
  // At Weise et al.'s 99 % the synthetic training's frame-to-frame changes fall among the dropped
  // directions, whose small variance holds the blink back (docs/tracking.md, "Training data").
  EXPECT_LT(droppedPeak, keptPeak - 0.1);
}

}  // namespace closed_loop_test
}  // namespace lacrima::tracking
