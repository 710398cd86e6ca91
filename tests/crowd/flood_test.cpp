// The flood scenario (flood.hpp) at a small size: a 12 m river of SPH water keeps flowing (fed
// upstream, drained at its end, neither emptied nor thrown about), a vulnerable agent is carried
// downstream and over the end where a strong one walks across, and the run is bitwise the same with
// one thread or all. Schaffer et al.'s experiments at full size are `lacrima flood` (docs/crowd.md).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>

#include "lacrima/crowd/flood.hpp"
#include "lacrima/crowd/water_speed_field.hpp"

namespace lacrima::crowd {
namespace flood_test {

// A river across a field from the origin to `fieldMax`, as long as the field, from z = `nearBank`,
// `width` wide and 1 m deep, flowing at 1.5 m/s towards -x.
FloodParams channel(const Vec2d& fieldMax, double nearBank, double width) {
  FloodParams params;
  params.field = GroundRect{Vec2d(0, 0), fieldMax};
  params.river.zMin = nearBank;
  params.river.width = width;
  params.river.length = fieldMax.x();
  params.river.speed = 1.5;
  return params;
}

// A river 12 m long, 4 m wide and 1 m deep (384 particles of 0.25 m) across a 12 x 10 m field,
// flowing at 1.5 m/s towards -x, and one agent per endurance on the near bank at x = 9 walking to
// the far bank.
FloodParams smallRiver(const std::vector<double>& endurances) {
  FloodParams params = channel(Vec2d(12, 10), 3.0, 4.0);
  for (double tau : endurances) {
    FloodCrowd crowd;
    crowd.name = "tau";
    crowd.agents = {Agent{Vec2d(9.0, 1.0), Vec2d(9.0, 9.0), 1.3}};
    crowd.endurance = {{0.0, tau}};
    params.crowds.push_back(crowd);
  }
  return params;
}

TEST(Flood, TheRiverKeepsFlowingFedUpstreamAndDrainedAtItsEnd) {
  FloodSimulation flood(smallRiver({}));
  const size_t start = flood.liquid().positions().size();
  for (int frame = 0; frame < 50; ++frame) flood.advanceFrame();
  const std::vector<Vec3d>& x = flood.liquid().positions();
  double highest = 0.0, meanSpeed = 0.0;
  for (const Vec3d& p : x) highest = std::max(highest, p.y());
  for (const Vec3d& v : flood.liquid().velocities()) meanSpeed += -v.x() / double(x.size());
  std::printf("[ flood ] small river after 5 s: %zu particles of %zu at the start, %zu emitted, mean speed %.2f m/s, "
              "highest %.2f m\n",
              x.size(), start, flood.particlesEmitted(), meanSpeed, highest);
  // In 5 s the water moves 7.5 m of the river's 12: much of it has left at the end and been
  // replaced by the inflow (measured: 190 particles fed, 352 in the river; the emitter fills a
  // little less than the whole depth).
  EXPECT_GT(double(flood.particlesEmitted()), 0.4 * double(start));
  EXPECT_GT(double(x.size()), 0.7 * double(start)) << "the river must not drain";
  EXPECT_LT(double(x.size()), 1.1 * double(start));
  EXPECT_NEAR(meanSpeed, 1.5, 0.5) << "it flows at about the inflow's speed";
  EXPECT_LT(highest, 1.5) << "no water thrown out of the channel";
}

// Schaffer et al.'s runs start with a dry bed the water enters (its figures 7 and 8): the front leaves the
// emitter and runs downstream no faster than the inflow plus Ritter's dam-break front (2 sqrt(g h),
// Ritter 1892) and no slower than half the inflow.
TEST(Flood, ADryRiverFillsFromItsUpstreamEnd) {
  FloodParams params = smallRiver({});
  params.river.startsFull = false;
  FloodSimulation flood(params);
  EXPECT_EQ(flood.liquid().positions().size(), 0u) << "dry at the start";
  const double ritter = 2.0 * std::sqrt(9.81 * params.river.depth);
  for (int frame = 1; frame <= 40; ++frame) {
    flood.advanceFrame();
    if (frame % 10 != 0) continue;
    double front = params.river.length;
    for (const Vec3d& p : flood.liquid().positions()) front = std::min(front, p.x());
    const double run = params.river.length - front, t = flood.time();
    std::printf("[ flood ] dry start: at %.1f s the front is %.2f m from the upstream end, %zu particles\n", t, run,
                flood.liquid().positions().size());
    if (front <= 0.0) break;  // it reached the end of the river
    EXPECT_GT(run, 0.5 * params.river.speed * t);
    EXPECT_LT(run, (params.river.speed + ritter) * t + 1.0);
  }
  EXPECT_GT(flood.particlesEmitted(), 0u);
}

// A block in the stream shelters the water behind it (Schaffer et al.'s section 4.3): a river 20 m long
// and 8 m wide with a 2 x 2 x 1 m block in its middle; averaged over 4-10 s, the water in the
// block's lee runs slower than the water beside the lee.
TEST(Flood, ABlockInTheStreamSheltersTheWaterBehindIt) {
  FloodParams params = channel(Vec2d(20, 12), 2.0, 8.0);
  const GroundRect block{Vec2d(11, 5), Vec2d(13, 7)};
  params.river.obstacles = {block};
  FloodSimulation flood(params);
  WaterSpeedField field(params.field, 0.5);
  for (int frame = 1; frame <= 100; ++frame) {
    flood.advanceFrame();
    if (frame > 40) field.add(flood.liquid().positions(), flood.liquid().velocities());
  }
  const double lee = field.meanSpeedIn(leeOf(block)), beside = field.meanSpeedIn(besideLeeOf(block, 2.0, 10.0));
  std::printf("[ flood ] behind a 2 m block: %.2f m/s in its lee, %.2f m/s beside it\n", lee, beside);
  ASSERT_GT(lee, 0.0) << "water in the lee";
  EXPECT_LT(lee, 0.7 * beside);
}

TEST(Flood, TheStreamCarriesAVulnerableAgentOverTheEndWhereAStrongOneCrosses) {
  FloodParams params = smallRiver({0.0, 1.0});
  FloodSimulation flood(params);
  for (int frame = 0; frame < 120 && !flood.settled(); ++frame) flood.advanceFrame();
  const AgentOutcome strong = flood.outcomes(0)[0], vulnerable = flood.outcomes(1)[0];
  std::printf("[ flood ] tau 0: arrived at %.1f s; tau 1: lost at %.1f s\n", strong.arrivalTime, vulnerable.lostTime);
  // tau = 0 walks 8 m across at 1.3 m/s, less the goal radius (about 5.4 s).
  EXPECT_NEAR(strong.arrivalTime, 7.0 / 1.3, 0.6);
  EXPECT_LT(strong.lostTime, 0.0);
  // tau = 1 against the SPH particles' own mass (125 kg, about ten colliding): carried at nearly
  // the stream's speed the 9 m to the end of the river.
  EXPECT_LT(vulnerable.arrivalTime, 0.0);
  ASSERT_GT(vulnerable.lostTime, 0.0);
  EXPECT_LT(vulnerable.lostTime, 12.0);
}

TEST(Flood, TheSameRunWithOneThreadOrAll) {
  const auto run = [] {
    FloodSimulation flood(smallRiver({0.6}));
    for (int frame = 0; frame < 30; ++frame) flood.advanceFrame();
    return std::make_pair(flood.liquid().positions(), flood.crowd(0).agents()[0].position);
  };
  std::pair<std::vector<Vec3d>, Vec2d> one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = run();
  }
  const auto all = run();
  ASSERT_EQ(one.first.size(), all.first.size());
  for (size_t i = 0; i < one.first.size(); ++i) ASSERT_TRUE(one.first[i] == all.first[i]) << "particle " << i;
  EXPECT_TRUE(one.second == all.second);
}

}  // namespace flood_test
}  // namespace lacrima::crowd
