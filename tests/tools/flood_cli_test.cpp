// `lacrima flood`: the real binary runs one of Schaffer et al.'s experiments for a simulated second and
// writes its trajectories, top-view plots and table; a scenario file of one's own runs too; bad
// options and bad scenario files write nothing.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/run_command.hpp"
#include "support/test_directory.hpp"

namespace lacrima {
namespace flood_cli_test {

namespace fs = std::filesystem;

test::CommandResult lacrimaFlood(const std::string& options) {
  return test::runCommand(test::shellQuote(LACRIMA_BINARY) + " flood " + options);
}

std::string contents(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(FloodCli, OneExperimentWritesTrajectoriesPlotsAndTheTable) {
  const fs::path dir = test::testDirectory("flood_cli", /*fresh=*/true);
  const auto run = lacrimaFlood("--experiments obstacle --duration 1 --out " + test::shellQuote(dir.string()));
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  // One crowd: the 50 crossing agents at tau 0.6, none there after a second.
  EXPECT_NE(run.output.find("obstacle: tau 0.6, v_F 1.5 m/s: not reached: 0 arrived, 0 lost, 50 still in the field"),
            std::string::npos)
      << run.output;
  const std::string csv = contents(dir / "obstacle_tau0.6.csv");
  EXPECT_EQ(csv.rfind("time,agent,x,z,state,hip_height,water_speed\n0.50,0,", 0), 0u) << csv.substr(0, 200);
  EXPECT_NE(csv.find("\n1.00,49,"), std::string::npos) << "every agent every half second";
  const auto plot = OIIO::ImageInput::open((dir / "obstacle_tau0.6.png").string());
  ASSERT_TRUE(plot);
  EXPECT_EQ(plot->spec().width, 800);  // the 100 x 50 m field at 8 pixels a metre
  EXPECT_EQ(plot->spec().height, 400);
  const std::string table = contents(dir / "table.md");
  EXPECT_NE(table.find("| obstacle: tau 0.6, v_F 1.5 m/s | not reached"), std::string::npos);
  EXPECT_NE(table.find("- obstacle: obstacle 0: the water in its lee "), std::string::npos) << table;
  const auto water = OIIO::ImageInput::open((dir / "obstacle_water.png").string());
  ASSERT_TRUE(water);
  EXPECT_EQ(water->spec().width, 800);  // half-metre cells at 4 pixels a cell
  EXPECT_EQ(water->spec().height, 400);
}

TEST(FloodCli, AScenarioFileOfOnesOwnRunsAndABadOneIsReportedAtItsPath) {
  const fs::path dir = test::testDirectory("flood_cli_own", /*fresh=*/true);
  const std::string scenario = R"({
  "version": 1,
  "field": {"min": [0, 0], "max": [20, 10]},
  "river": {"zMin": 3, "width": 4, "length": 20, "speed": 1},
  "duration": 2,
  "crowds": [{"name": "walkers", "endurance": [[0, 0.5]], "groups": [{"count": 3, "first": [8, 1], "goal": [10, 9]}]}]
})";
  // Its walkers drawn as the box figure of tests/data/figures (twelve triangles each).
  std::string withFigure = scenario;
  const std::string figure = std::string(LACRIMA_SOURCE_DIR) + "/tests/data/figures/box_figure.gltf";
  withFigure.replace(withFigure.find("\"name\": \"walkers\""), 17, "\"name\": \"walkers\", \"figure\": \"" + figure + "\"");
  std::ofstream(dir / "brook.json") << withFigure;
  const auto run = lacrimaFlood(test::shellQuote((dir / "brook.json").string()) + " --scene-at 1 --out " +
                                test::shellQuote((dir / "out").string()));
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  EXPECT_NE(run.output.find("walkers: not reached: 0 arrived, 0 lost, 3 still in the field"), std::string::npos) << run.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "brook_walkers.csv"));
  ASSERT_TRUE(fs::exists(dir / "out" / "brook_walkers_t1.json"));
  const auto info = test::runCommand(test::shellQuote(LACRIMA_BINARY) + " info " +
                                     test::shellQuote((dir / "out" / "brook_walkers_t1.glb").string()));
  ASSERT_EQ(info.exitStatus, 0) << info.output;
  for (const char* agent : {"agent 0", "agent 1", "agent 2"}) {
    const size_t line = info.output.find(agent);
    ASSERT_NE(line, std::string::npos) << agent << " in\n" << info.output;
    EXPECT_NE(info.output.substr(line, info.output.find('\n', line) - line).find(" 8 "), std::string::npos)
        << "the box's eight vertices: " << info.output.substr(line, 80);
  }
  std::string bad = scenario;
  bad.replace(bad.find("\"speed\""), 7, "\"sped\"");
  std::ofstream(dir / "bad.json") << bad;
  const auto failed = lacrimaFlood(test::shellQuote((dir / "bad.json").string()) + " --out " + test::shellQuote((dir / "bad").string()));
  EXPECT_EQ(failed.exitStatus, 2);
  EXPECT_NE(failed.output.find("bad.json:4:50: /river/sped: unknown key 'sped'; did you mean 'speed'?"), std::string::npos)
      << failed.output;
  EXPECT_FALSE(fs::exists(dir / "bad"));
}

TEST(FloodCli, AnUnknownExperimentIsABadOptionAndWritesNothing) {
  const fs::path dir = test::testDirectory("flood_cli_bad", /*fresh=*/true);
  const auto run = lacrimaFlood("--experiments table1-9 --out " + test::shellQuote((dir / "out").string()));
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_NE(run.output.find("lacrima flood: --experiments: unknown experiment 'table1-9' (expected some of "
                            "counter-stream, obstacle, table1-0.5, table1-1.5, table1-2.5)"),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_EQ(lacrimaFlood("--duration 0").exitStatus, 2) << "a duration must be at least a second";
}

}  // namespace flood_cli_test
}  // namespace lacrima
