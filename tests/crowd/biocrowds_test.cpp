// BioCrowds (biocrowds.hpp) against the method's stated properties: markers go to the closest agent
// within R, a lone agent walks straight to its goal at its desired speed, crowding slows agents,
// agents never come closer than the markers allow nor enter obstacles, and two groups walking
// through each other form lanes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "lacrima/crowd/biocrowds.hpp"

namespace lacrima::crowd {
namespace biocrowds_test {

GroundRect rect(double x0, double z0, double x1, double z1) { return {Vec2d(x0, z0), Vec2d(x1, z1)}; }

TEST(BioCrowds, MarkersFillTheGroundAtTheirDensityAndNeverAnObstacle) {
  CrowdParams params;
  const GroundRect ground = rect(0, 0, 20, 10);
  const std::vector<GroundRect> obstacles{rect(5, 2, 9, 6)};
  const std::vector<Vec2d> markers = scatterMarkers(ground, obstacles, params);
  // One marker per 0.5 m cell: 40 x 20 cells, minus the 8 x 8 under the obstacle (give or take
  // a jittered marker at its edge).
  EXPECT_NEAR(double(markers.size()), 40.0 * 20.0 - 64.0, 12.0);
  for (const Vec2d& m : markers) {
    EXPECT_TRUE(ground.contains(m));
    EXPECT_FALSE(obstacles[0].contains(m)) << m.transpose();
  }
  EXPECT_EQ(scatterMarkers(ground, obstacles, params), markers) << "the same seed scatters the same markers";
  params.seed = 2;
  EXPECT_NE(scatterMarkers(ground, obstacles, params), markers);
}

TEST(BioCrowds, EachMarkerGoesToTheClosestAgentWithinThePersonalSpace) {
  std::vector<Agent> agents;
  for (int a = 0; a < 30; ++a)
    agents.push_back({Vec2d(2.0 + 0.53 * a, 3.0 + 2.0 * std::sin(1.7 * a)), Vec2d(18, 5)});
  const BioCrowds crowd(CrowdParams{}, rect(0, 0, 20, 10), {}, agents);
  const std::vector<int> owner = crowd.markerOwners();
  const double R = crowd.params().personalSpace;
  for (size_t k = 0; k < crowd.markers().size(); ++k) {
    int closest = -1;
    double best = std::numeric_limits<double>::infinity();
    for (size_t a = 0; a < agents.size(); ++a) {
      const double d = (crowd.markers()[k] - agents[a].position).norm();
      if (d < R && d < best) best = d, closest = int(a);
    }
    ASSERT_EQ(owner[k], closest) << "marker " << k;
  }
}

TEST(BioCrowds, ALoneAgentsMarkersPullItAsFarAsTheFreeMotionLengthSays) {
  // Dense markers (400 per square metre) make the sums of eqs. 1-3 close to their integrals.
  CrowdParams params;
  params.markerDensity = 400.0;
  for (double R : {1.0, 1.5, 3.0}) {
    params.personalSpace = R;
    const BioCrowds crowd(params, rect(0, 0, 10, 10), {}, {Agent{Vec2d(5, 5), Vec2d(9, 5), 1.0}});
    // |m| over m_free sets the speed, so at the free length the agent walks at exactly S_max; half
    // the markers (a wall of obstacle ahead would do) would slow it. Measured through eq. 1 here.
    const std::vector<int> owner = crowd.markerOwners();
    Vec2d m = Vec2d::Zero();
    double weights = 0.0;
    for (size_t k = 0; k < owner.size(); ++k) {
      if (owner[k] != 0) continue;
      const Vec2d y = crowd.markers()[k] - Vec2d(5, 5);
      const double w = (1.0 + y.x() / y.norm()) / (1.0 + y.norm());
      m += w * y, weights += w;
    }
    m /= weights;
    EXPECT_NEAR(m.norm() / freeMotionLength(R), 1.0, 0.02) << "R " << R;
    EXPECT_NEAR(m.y(), 0.0, 0.02 * R) << "towards the goal";
    EXPECT_NEAR(crowd.walkingVelocities()[0].norm(), 1.0, 0.02);
  }
}

TEST(BioCrowds, ALoneAgentWalksStraightToItsGoalAtItsDesiredSpeed) {
  BioCrowds crowd(CrowdParams{}, rect(0, 0, 50, 10), {}, {Agent{Vec2d(5, 5), Vec2d(45, 5), 1.3}});
  const double dt = 1.0 / 30.0;
  double time = 0.0, widest = 0.0;
  while (!crowd.agents()[0].arrived && time < 100.0) {
    crowd.step(dt);
    time += dt;
    widest = std::max(widest, std::abs(crowd.agents()[0].position.y() - 5.0));
  }
  std::printf("[ biocrowds ] lone agent: 39 m in %.2f s (%.3f m/s), strays %.3f m off the line\n", time, 39.0 / time,
              widest);
  ASSERT_TRUE(crowd.agents()[0].arrived);
  // The jittered markers (28 in its personal space) make its speed and heading waver a little
  // about 1.3 m/s and the line.
  EXPECT_NEAR(39.0 / time, 1.3, 0.1);
  EXPECT_LT(widest, 0.5);
}

// Two groups of `perGroup` agents in a corridor 40 m long and 10 m wide walking through each
// other: group A from the left end to the right, group B from the right to the left, in columns
// of five across the corridor, 1.2 m apart.
std::vector<Agent> counterFlow(int perGroup) {
  std::vector<Agent> agents;
  for (int group = 0; group < 2; ++group)
    for (int n = 0; n < perGroup; ++n) {
      const double x = 2.0 + 1.2 * (n / 5), z = 2.0 + 1.5 * (n % 5) + 0.4 * group;
      Agent agent;
      agent.position = group == 0 ? Vec2d(x, z) : Vec2d(40.0 - x, z);
      agent.goal = group == 0 ? Vec2d(39.0, z) : Vec2d(1.0, z);
      agents.push_back(agent);
    }
  return agents;
}

// The lane order where the groups pass through each other: for each agent with agents of both
// groups within 3 m along the corridor (anywhere across it), among the other agents within 3 m
// along and 0.6 m across, the share in its own group (`group[a]`); averaged. Shuffling the group
// labels over the same positions (no lanes by construction) gives the level without lanes; lanes
// raise it towards 1.
struct LaneOrder {
  double sum = 0.0;  // of the shares
  int counted = 0;   // agents
};
void addLaneOrder(const std::vector<Agent>& agents, const std::vector<int>& group, LaneOrder& order) {
  double& sum = order.sum;
  int& counted = order.counted;
  for (size_t a = 0; a < agents.size(); ++a) {
    if (agents[a].arrived) continue;
    const Vec2d p = agents[a].position;
    int same = 0, others = 0;
    bool facesTheOtherGroup = false;
    for (size_t b = 0; b < agents.size(); ++b) {
      if (b == a || agents[b].arrived) continue;
      const Vec2d d = agents[b].position - p;
      if (std::abs(d.x()) > 3.0) continue;
      facesTheOtherGroup = facesTheOtherGroup || group[a] != group[b];
      if (std::abs(d.y()) > 0.6) continue;
      ++others;
      if (group[a] == group[b]) ++same;
    }
    if (others == 0 || !facesTheOtherGroup) continue;
    sum += double(same) / double(others);
    ++counted;
  }
}

TEST(BioCrowds, GroupsWalkingThroughEachOtherKeepApartSlowDownAndFormLanes) {
  const int perGroup = 25;
  BioCrowds crowd(CrowdParams{}, rect(0, 0, 40, 10), {}, counterFlow(perGroup));
  const double dt = 1.0 / 30.0;
  std::vector<int> group(2 * perGroup), shuffled(2 * perGroup);
  for (int a = 0; a < 2 * perGroup; ++a) group[size_t(a)] = a < perGroup ? 0 : 1;
  shuffled = group;
  for (size_t a = shuffled.size() - 1; a > 0; --a) std::swap(shuffled[a], shuffled[(a * 7919 + 13) % (a + 1)]);
  double closest = std::numeric_limits<double>::infinity();
  LaneOrder laneSums, mixedSums;
  int arrived = 0;
  double slowest = 10.0;
  for (int step = 0; step < 30 * 90; ++step) {
    const std::vector<Vec2d> v = crowd.walkingVelocities();
    for (size_t a = 0; a < v.size(); ++a)
      if (!crowd.agents()[a].arrived) slowest = std::min(slowest, v[a].norm());
    crowd.move(v, dt);
    const std::vector<Agent>& agents = crowd.agents();
    for (size_t a = 0; a < agents.size(); ++a)
      for (size_t b = a + 1; b < agents.size(); ++b)
        if (!agents[a].arrived && !agents[b].arrived)
          closest = std::min(closest, (agents[a].position - agents[b].position).norm());
    if (step % 15 == 0) addLaneOrder(agents, group, laneSums), addLaneOrder(agents, shuffled, mixedSums);
  }
  for (const Agent& a : crowd.agents()) arrived += a.arrived ? 1 : 0;
  const double lanes = laneSums.sum / laneSums.counted, mixed = mixedSums.sum / mixedSums.counted;
  std::printf("[ biocrowds ] counter-flow of 2 x %d: closest approach %.3f m, slowest %.3f m/s, lane order %.2f (%.2f "
              "with the groups shuffled), %d arrived in 90 s\n",
              perGroup, closest, slowest, lanes, mixed, arrived);
  EXPECT_EQ(arrived, 2 * perGroup) << "every agent gets through";
  EXPECT_GT(closest, 0.3) << "agents never walk into each other";
  EXPECT_LT(slowest, 0.7) << "in the crossing the crowd slows down";
  EXPECT_GT(lanes, mixed + 0.15) << "lanes form (measured: 0.62 against 0.41)";
}

TEST(BioCrowds, AgentsWalkAroundAnObstacleNeverIntoIt) {
  const GroundRect wall = rect(18, 2, 22, 8);
  std::vector<Agent> agents;
  for (int n = 0; n < 10; ++n) agents.push_back({Vec2d(3.0, 3.0 + 0.45 * n), Vec2d(37.0, 5.0)});
  BioCrowds crowd(CrowdParams{}, rect(0, 0, 40, 10), {wall}, agents);
  for (int step = 0; step < 30 * 80; ++step) {
    crowd.step(1.0 / 30.0);
    for (const Agent& a : crowd.agents()) ASSERT_FALSE(wall.contains(a.position)) << "step " << step;
  }
  for (const Agent& a : crowd.agents()) EXPECT_TRUE(a.arrived) << a.position.transpose();
}

}  // namespace biocrowds_test
}  // namespace lacrima::crowd
