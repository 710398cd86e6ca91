// The flood's agent figures (crowd/figure.hpp): the built-in figure stands 1.8 m tall on its feet
// and is closed; walking turns it to the way it goes and advances its walk cycle by the distance
// over the stride; carried, it turns about all three axes at the water's speed plus a per-agent
// rate in [0.1, 0.5] (Schaffer et al. 2020's ragdoll), its hip at the water's height.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "lacrima/crowd/figure.hpp"

namespace lacrima::crowd {
namespace figure_test {

std::pair<float, float> heightRange(const TriangleMesh& mesh) {
  float lo = 1e9f, hi = -1e9f;
  for (const Vec3& p : mesh.positions) lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
  return {lo, hi};
}

FigurePose standing(double phase) {
  FigurePose pose;
  pose.hip = Vec3d(0.0, FigurePose::kHipHeight, 0.0);
  pose.walkPhase = phase;
  return pose;
}

TEST(Figure, TheBuiltInFigureStandsOnItsFeetAndIsAboutOnePointEightMetresTall) {
  for (double phase : {0.0, 0.25, 0.5, 0.75}) {
    const auto [lo, hi] = heightRange(articulatedFigure(standing(phase)));
    EXPECT_NEAR(lo, 0.0, 0.06) << "a foot on the ground at phase " << phase;
    EXPECT_NEAR(hi, 1.76, 0.05) << "the top of the head at phase " << phase;
  }
}

TEST(Figure, TheBuiltInFigureIsClosed) {
  // Every edge of a closed, consistently oriented surface is used once in each direction.
  const TriangleMesh mesh = articulatedFigure(standing(0.3));
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int e = 0; e < 3; ++e) ++edges[{mesh.indices[3 * t + e], mesh.indices[3 * t + (e + 1) % 3]}];
  for (const auto& [edge, count] : edges) {
    ASSERT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    ASSERT_EQ(edges.count({edge.second, edge.first}), 1u) << "edge " << edge.first << "-" << edge.second << " has no twin";
  }
  EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
}

TEST(Figure, AWalkerFacesTheWayItGoesAndStepsOnceAStride) {
  const std::vector<Agent> agents{Agent{Vec2d(0, 0), Vec2d(0, 10), 1.3}};
  FigureAnimator animator(agents, 7);
  const Vec3d facing0 = animator.poses()[0].orientation * Vec3d::UnitZ();
  EXPECT_NEAR(facing0.z(), 1.0, 1e-9) << "towards its goal at the start";
  // 2.8 m along +x in 20 frames of 0.1 s on the bank (the ground 1 m up).
  for (int f = 1; f <= 20; ++f) {
    FigureAnimator::AgentFrame frame;
    frame.position = Vec2d(0.14 * f, 0.0);
    frame.groundHeight = 1.0;
    animator.advance({frame}, 0.1);
  }
  const FigurePose& pose = animator.poses()[0];
  const Vec3d facing = pose.orientation * Vec3d::UnitZ();
  EXPECT_NEAR(facing.x(), 1.0, 1e-9);
  EXPECT_NEAR(pose.walkPhase, 2.8 / FigureAnimator::kStrideLength, 1e-9);
  EXPECT_NEAR(pose.hip.y(), 1.0 + FigurePose::kHipHeight, 1e-12) << "standing on the raised ground";
  EXPECT_FALSE(pose.carried);
  // A glTF figure is placed so that its hip sits where the built-in one's does.
  const Eigen::Affine3d root = figureRootTransform(pose);
  EXPECT_LT((root * Vec3d(0.0, FigurePose::kHipHeight, 0.0) - pose.hip).norm(), 1e-12);
  EXPECT_LT((root * Vec3d(0.0, 0.0, 1.0) - root * Vec3d::Zero() - Vec3d(1.0, 0.0, 0.0)).norm(), 1e-9) << "front to +x";
}

TEST(Figure, ACarriedFigureTurnsAtTheWatersSpeedPlusItsOwnRate) {
  std::vector<Agent> agents;
  for (int a = 0; a < 200; ++a) agents.push_back(Agent{Vec2d(a, 0), Vec2d(a, 10), 1.3});
  FigureAnimator animator(agents, 3);
  double lowest = 1.0, highest = 0.0;
  for (size_t a = 0; a < agents.size(); ++a)
    lowest = std::min(lowest, animator.extraTurnRate(a)), highest = std::max(highest, animator.extraTurnRate(a));
  EXPECT_GE(lowest, 0.1);
  EXPECT_LE(highest, 0.5);
  EXPECT_GT(highest - lowest, 0.3) << "spread over Schaffer et al.'s range";
  EXPECT_EQ(FigureAnimator(agents, 3).extraTurnRate(17), animator.extraTurnRate(17)) << "the same for the same seed";

  // Agent 0 carried for one 0.05 s frame in water of 2.5 m/s: each axis turns by (2.5 + rate) 0.05.
  std::vector<FigureAnimator::AgentFrame> frame(agents.size());
  for (size_t a = 0; a < agents.size(); ++a) frame[a].position = agents[a].position;
  frame[0].carried = true, frame[0].hipHeight = 0.55, frame[0].waterSpeed = 2.5;
  animator.advance(frame, 0.05);
  const FigurePose& pose = animator.poses()[0];
  EXPECT_TRUE(pose.carried);
  EXPECT_EQ(pose.hip.y(), 0.55) << "the hip at the colliding particles' mean height";
  const double turn = (2.5 + animator.extraTurnRate(0)) * 0.05;
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(0.0, Vec3d::UnitY()) * Eigen::AngleAxisd(turn, Vec3d::UnitZ()) *
                                    Eigen::AngleAxisd(turn, Vec3d::UnitY()) * Eigen::AngleAxisd(turn, Vec3d::UnitX()))
                                       .toRotationMatrix();
  EXPECT_LT((pose.orientation - expected).norm(), 1e-12);
  // Back on its feet when the water lets go.
  frame[0].carried = false;
  animator.advance(frame, 0.05);
  EXPECT_LT((animator.poses()[0].orientation - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

}  // namespace figure_test
}  // namespace lacrima::crowd
