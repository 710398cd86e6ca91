// Flood scenario files (lacrima/scenes/flood_scenario.hpp): Schaffer et al.'s experiments in
// scenes/floods load as the experiments docs/crowd.md describes, and bad input is reported at its
// JSON path.
#include <gtest/gtest.h>

#include <string>

#include "lacrima/scenes/flood_scenario.hpp"
#include "lacrima/scenes/shot.hpp"
#include "scenes/shot_support.hpp"

namespace lacrima {
namespace flood_scenario_test {

using test::replaced;
using test::writeShot;

const std::string kFloods = std::string(LACRIMA_SOURCE_DIR) + "/scenes/floods/";

TEST(FloodScenario, TheSeedsTable1RowIsFourCrowdsCrossingOneRiver) {
  const FloodScenario s = loadFloodScenario(kFloods + "table1-1.5.json");
  EXPECT_EQ(s.name, "table1-1.5");
  EXPECT_EQ(s.params.river.speed, 1.5);
  EXPECT_EQ(s.params.river.width, 27.0);
  EXPECT_EQ(s.params.coupledDensity, 80.0);
  EXPECT_EQ(s.duration, 300.0);
  ASSERT_EQ(s.params.crowds.size(), 4u);
  EXPECT_EQ(s.labels[1], "S5: tau 0.2, v_F 1.5 m/s");
  const crowd::FloodCrowd& strong = s.params.crowds[1];
  EXPECT_EQ(strong.endurance, (std::vector<std::pair<double, double>>{{0.0, 0.2}}));
  ASSERT_EQ(strong.agents.size(), 50u);
  // Two rows of 25 on the near bank, 0.8 m apart, for one goal on the far bank.
  EXPECT_TRUE(strong.agents[24].position == crowd::Vec2d(40.0 + 24 * 0.8, 3.0));
  EXPECT_TRUE(strong.agents[25].position == crowd::Vec2d(40.0, 4.2));
  EXPECT_TRUE(strong.agents[49].goal == crowd::Vec2d(50.0, 47.0));
  EXPECT_EQ(strong.agents[0].maxSpeed, 1.3);
  EXPECT_EQ(strong.agentMass, 65.0);
}

TEST(FloodScenario, TheCounterStreamGroupWalksUpstreamAndTheObstacleStandsInTheRiver) {
  const FloodScenario counter = loadFloodScenario(kFloods + "counter-stream.json");
  ASSERT_EQ(counter.params.crowds.size(), 1u);
  const std::vector<crowd::Agent>& agents = counter.params.crowds[0].agents;
  ASSERT_EQ(agents.size(), 100u);
  for (size_t a = 50; a < 100; ++a) {
    EXPECT_EQ(agents[a].goal.x(), 98.0) << a;
    EXPECT_EQ(agents[a].goal.y(), agents[a].position.y()) << "upstream along its own line";
  }
  const FloodScenario obstacle = loadFloodScenario(kFloods + "obstacle.json");
  ASSERT_EQ(obstacle.params.river.obstacles.size(), 1u);
  EXPECT_TRUE(obstacle.params.river.obstacles[0].contains(crowd::Vec2d(50, 25)));
  EXPECT_EQ(obstacle.params.river.obstacleHeight, 1.0);
}

// A small scenario with one crowd; `extra` is spliced into its crowd.
std::string smallScenario(const std::string& crowdExtra = "") {
  return R"({
  "version": 1,
  "field": {"min": [0, 0], "max": [20, 10]},
  "river": {"zMin": 3, "width": 4, "length": 20, "speed": 1},
  "crowds": [{"name": "walkers", "endurance": [[0, 0.2], [5, 0.8]],
              "groups": [{"count": 4, "first": [2, 1], "along": [1, 0], "goal": [10, 9]}])" +
         crowdExtra + R"(}]
})";
}

// The problems a scenario text has, each "pointer: first line of the message".
std::vector<std::string> problemsOf(const std::string& name, const std::string& text) {
  try {
    loadFloodScenario(writeShot(name, text));
  } catch (const ShotError& e) {
    std::vector<std::string> problems;
    for (const Diagnostic& d : e.diagnostics()) problems.push_back(d.jsonPath + ": " + d.message.substr(0, d.message.find('\n')));
    return problems;
  }
  return {};
}

TEST(FloodScenario, ASmallScenarioLoadsWithItsEnduranceKeys) {
  const FloodScenario s = loadFloodScenario(writeShot("flood_small.json", smallScenario()));
  ASSERT_EQ(s.params.crowds.size(), 1u);
  EXPECT_EQ(s.labels[0], "walkers") << "the name when there is no label";
  EXPECT_EQ(s.params.crowds[0].agents.size(), 4u);
  EXPECT_TRUE(s.params.crowds[0].agents[3].position == crowd::Vec2d(5, 1));
  EXPECT_EQ(s.params.river.depth, 1.0) << "Schaffer et al.'s by default";
}

TEST(FloodScenario, BadInputIsReportedAtItsPath) {
  using V = std::vector<std::string>;
  EXPECT_EQ(problemsOf("flood_typo.json", replaced(smallScenario(), R"("speed": 1)", R"("sped": 1)")),
            V{"/river/sped: unknown key 'sped'; did you mean 'speed'?"});
  EXPECT_EQ(problemsOf("flood_tau.json", replaced(smallScenario(), "[5, 0.8]", "[5, 1.8]")),
            V{"/crowds/0/endurance/1/1: expected tau in [0, 1], found 1.8"});
  EXPECT_EQ(problemsOf("flood_keys.json", replaced(smallScenario(), "[5, 0.8]", "[0, 0.8]")),
            V{"/crowds/0/endurance/1/0: key times must increase: 0 after 0"});
  EXPECT_EQ(problemsOf("flood_goals.json", replaced(smallScenario(), R"("goal": [10, 9])", R"("goal": [10, 9], "goalOffset": [0, 8])")),
            V{"/crowds/0/groups/0/goalOffset: give one of 'goal' (a point [x, z] for every agent) and 'goalOffset' (from "
              "each agent's start)"});
  EXPECT_EQ(problemsOf("flood_outside.json", replaced(smallScenario(), R"("first": [2, 1])", R"("first": [19, 1])")),
            V{"/crowds/0/groups/0/first: agent 2 of the group starts at [21, 1], outside the field"});
  EXPECT_EQ(problemsOf("flood_no_crowds.json", replaced(smallScenario(), R"("crowds")", R"("crowd_list")")).size(), 2u)
      << "the unknown key and the missing 'crowds'";
  EXPECT_EQ(problemsOf("flood_fine.json", replaced(smallScenario(), R"("speed": 1)", R"("speed": 1, "depth": 3, "particleRadius": 0.05)")),
            V{"/river/particleRadius: the river would hold 2.4e+05 particles at particleRadius 0.05 m, more than the "
              "200,000 allowed (about 100 s of computing a simulated second)"});
  EXPECT_EQ(problemsOf("flood_syntax.json", "{\"version\": 1,").size(), 1u);
  EXPECT_EQ(problemsOf("flood_start.json", replaced(smallScenario(), R"("speed": 1)", R"("speed": 1, "start": "dry")")),
            V{"/river/start: unknown start 'dry' (expected 'full': the river flowing at the start, or 'empty': a dry bed "
              "the water enters at the upstream end)"});
  const auto missing = problemsOf("flood_figure.json", smallScenario(R"(, "figure": "no_such_figure.glb")"));
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(missing[0].rfind("/crowds/0/figure: cannot load the figure: ", 0), 0u) << missing[0];
  EXPECT_NE(missing[0].find("no_such_figure.glb"), std::string::npos) << "names the file: " << missing[0];
}

TEST(FloodScenario, TheRiverStartsFullOrDry) {
  EXPECT_TRUE(loadFloodScenario(writeShot("flood_full.json", smallScenario())).params.river.startsFull) << "the default";
  const std::string dry = replaced(smallScenario(), R"("speed": 1)", R"("speed": 1, "start": "empty")");
  EXPECT_FALSE(loadFloodScenario(writeShot("flood_dry.json", dry)).params.river.startsFull);
}

TEST(FloodScenario, ACrowdNamesAGltfFigureRelativeToTheFile) {
  EXPECT_EQ(loadFloodScenario(writeShot("flood_built_in.json", smallScenario())).figures.at(0).triangleCount(), 0u)
      << "no triangles: the built-in articulated figure";
  const std::string figure = std::string(LACRIMA_SOURCE_DIR) + "/tests/data/figures/box_figure.gltf";
  const FloodScenario s = loadFloodScenario(writeShot("flood_box.json", smallScenario(R"(, "figure": ")" + figure + R"(")")));
  ASSERT_EQ(s.figures.size(), 1u);
  EXPECT_EQ(s.figures[0].triangleCount(), 12u) << "the box figure's twelve triangles";
  EXPECT_EQ(s.figures[0].normals.size(), s.figures[0].positions.size());
}

}  // namespace flood_scenario_test
}  // namespace lacrima
