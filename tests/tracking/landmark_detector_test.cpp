// The synthetic landmark detector (lacrima/tracking/synthetic_capture.hpp): without errors it is
// the exact projection; its jaw-line drift slides the contour points along the contour, slowly,
// and leaves the others; it drops the landmarks a turned head hides, but the jaw line (on the
// outline).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lacrima/tracking/synthetic_capture.hpp"
#include "tracking/tracking_support.hpp"

namespace lacrima::tracking {
namespace landmark_detector_test {

const Eigen::VectorXd& neutral() {
  static const Eigen::VectorXd weights = Eigen::VectorXd::Zero(test::ictModel().targetCount());
  return weights;
}

std::vector<Eigen::Vector2d> detect(const LandmarkDetectorErrors& errors, const Eigen::Isometry3d& pose, int frame,
                                    const DepthFrame* seen = nullptr) {
  return detectLandmarks(test::ictModel(), neutral(), pose, PinholeCamera{}, errors, 5, frame, frame / 30.0, seen);
}

TEST(LandmarkDetector, WithoutErrorsItIsTheExactProjection) {
  const Eigen::Isometry3d pose = test::headPose(0.7, Vec3d(3, -5, 2));
  const std::vector<Eigen::Vector2d> exact = projectLandmarks(test::ictModel(), neutral(), pose, PinholeCamera{}, 0.0, 1);
  const std::vector<Eigen::Vector2d> detected = detect({0.0, 0.0, false}, pose, 3);
  int seen = 0;
  for (size_t l = 0; l < 68; ++l) {
    if (!exact[l].allFinite()) continue;
    EXPECT_LT((detected[l] - exact[l]).norm(), 1e-12) << l;
    ++seen;
  }
  EXPECT_EQ(seen, 68) << "the ICT face carries all 68 on its skin";
}

TEST(LandmarkDetector, TheJawLineDriftsAlongItselfSlowlyAndTheRestStays) {
  const Eigen::Isometry3d pose = test::headPose(0.7);
  const std::vector<Eigen::Vector2d> exact = detect({0.0, 0.0, false}, pose, 0);
  double largestAlong = 0.0, largestAcross = 0.0, largestStep = 0.0;
  std::vector<Eigen::Vector2d> previous;
  for (int frame = 0; frame < 150; ++frame) {
    const std::vector<Eigen::Vector2d> drifted = detect({0.0, 4.0, false}, pose, frame);
    for (size_t l = 0; l < 68; ++l) {
      const Eigen::Vector2d offset = drifted[l] - exact[l];
      if (l > 16) {
        EXPECT_LT(offset.norm(), 1e-12) << "landmark " << l << " is not on the jaw line";
        continue;
      }
      const Eigen::Vector2d along = (exact[l == 16 ? 16 : l + 1] - exact[l == 16 ? 15 : l]).normalized();
      largestAlong = std::max(largestAlong, std::abs(offset.dot(along)));
      largestAcross = std::max(largestAcross, std::abs(offset.x() * along.y() - offset.y() * along.x()));
      if (!previous.empty()) largestStep = std::max(largestStep, (drifted[l] - previous[l]).norm());
    }
    previous = drifted;
  }
  std::printf("[ detector ] jaw-line drift over 5 s: up to %.2f px along the contour, %.2g across, %.3f px a frame\n",
              largestAlong, largestAcross, largestStep);
  EXPECT_GT(largestAlong, 3.5);
  EXPECT_LE(largestAlong, 4.0 + 1e-9);
  EXPECT_LT(largestAcross, 1e-9);
  EXPECT_LT(largestStep, 2.0 * std::numbers::pi * 4.0 / (2.0 * 30.0) + 1e-9) << "a sine of period >= 2 s at 30 fps";
}

TEST(LandmarkDetector, ATurnedHeadsHiddenLandmarksAreDroppedButTheJawLine) {
  const BlendshapeModel& model = test::ictModel();
  const auto hidden = [&](const Eigen::Isometry3d& pose, bool withDepth) {
    const DepthFrame depth = captureDepth(model, neutral(), pose, PinholeCamera{}, 0.0, 1);
    const std::vector<Eigen::Vector2d> points = detect({0.0, 0.0, true}, pose, 0, withDepth ? &depth : nullptr);
    std::vector<size_t> out;
    for (size_t l = 0; l < 68; ++l)
      if (!points[l].allFinite()) out.push_back(l);
    return out;
  };
  EXPECT_TRUE(hidden(test::headPose(0.7), true).empty()) << "a frontal face shows every landmark";
  // Turned 50 degrees: the far eye's outer corner goes behind the nose, the far brow's end and lip
  // corner turn away; the jaw line stays (on the outline).
  const Eigen::Isometry3d turned = test::headPose(0.7, Vec3d(0, 50, 0));
  const std::vector<size_t> byNormal = hidden(turned, false), byDepth = hidden(turned, true);
  std::printf("[ detector ] turned 50 degrees: %zu landmarks turned away, %zu with those behind the nose:",
              byNormal.size(), byDepth.size());
  for (size_t l : byDepth) std::printf(" %zu", l);
  std::printf("\n");
  ASSERT_GT(byDepth.size(), byNormal.size()) << "the depth map hides some the normals do not";
  EXPECT_GE(byNormal.size(), 2u);
  for (size_t l : byDepth) EXPECT_GT(l, 16u) << "the jaw line is never hidden";
  // All on the far side: the same side of the face's midline, none on it.
  const auto sideOf = [&](size_t l) { return model.neutral.positions[size_t(model.landmarkVertices[l])].x(); };
  for (size_t l : byDepth) {
    EXPECT_GT(std::abs(sideOf(l)), 0.005f) << "landmark " << l << " is near the midline";
    EXPECT_EQ(sideOf(l) > 0, sideOf(byDepth.front()) > 0) << "landmark " << l << " is on the near side";
  }
}

}  // namespace landmark_detector_test
}  // namespace lacrima::tracking
