// Time to quality (tools/src/quality_curve.*, `lacrima bench --quality`): RMSE, the fitted
// RMSE-vs-spp slope and the samples and seconds to reach a target, on curves with known answers;
// and the command itself on a small diffuse scene (cached reference, a slope steeper than -0.5).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "quality_curve.hpp"
#include "support/test_directory.hpp"
#include "tools/lacrima_cli_support.hpp"

namespace lacrima::cli {
namespace quality_curve_test {

namespace fs = std::filesystem;

// An ideal Monte Carlo curve: rmse = c * spp^slope, seconds = 0.01 s a sample.
std::vector<QualityPoint> powerLaw(double c, double slope, int maxSpp) {
  std::vector<QualityPoint> points;
  for (int spp = 1; spp <= maxSpp; spp *= 2) points.push_back({spp, 0.01 * spp, c * std::pow(double(spp), slope)});
  return points;
}

TEST(QualityCurve, RootMeanSquareError) {
  EXPECT_DOUBLE_EQ(rootMeanSquareError({1, 2, 3, 4}, {1, 2, 3, 4}), 0.0);
  EXPECT_DOUBLE_EQ(rootMeanSquareError({0, 0, 0, 0}, {1, -1, 1, -1}), 1.0);
  EXPECT_DOUBLE_EQ(rootMeanSquareError({0, 0}, {3, 4}), std::sqrt(12.5));
}

TEST(QualityCurve, SlopeOfAPowerLawIsItsExponent) {
  EXPECT_NEAR(rmseSlope(powerLaw(0.4, -0.5, 256)), -0.5, 1e-12);
  EXPECT_NEAR(rmseSlope(powerLaw(0.4, -0.75, 64)), -0.75, 1e-12);
  EXPECT_TRUE(std::isnan(rmseSlope({{1, 0.1, 0.3}})));  // one point has no slope
}

TEST(QualityCurve, TimeToReachInterpolatesInLogLog) {
  // 0.4 / sqrt(spp) = 0.05 at spp = 64 exactly, and 0.0566 at 50.
  const std::vector<QualityPoint> points = powerLaw(0.4, -0.5, 256);
  const auto at64 = timeToReach(points, 0.05);
  ASSERT_TRUE(at64);
  EXPECT_NEAR(at64->spp, 64.0, 1e-9);
  EXPECT_NEAR(at64->seconds, 0.64, 1e-9);
  EXPECT_FALSE(at64->extrapolated);
  const auto at50 = timeToReach(points, 0.4 / std::sqrt(50.0));
  ASSERT_TRUE(at50);
  EXPECT_NEAR(at50->spp, 50.0, 1e-9);
  EXPECT_NEAR(at50->seconds, 0.5, 1e-9);
}

// Adaptive sampling: the seconds are measured, not proportional to the maximum spp. Between 32
// (1 s) and 64 (1.5 s) max spp, halfway in log error: halfway in log seconds, sqrt(1.5) s.
TEST(QualityCurve, TimeToReachInterpolatesTheMeasuredSeconds) {
  const std::vector<QualityPoint> points = {{16, 0.6, 0.08}, {32, 1.0, 0.04}, {64, 1.5, 0.02}};
  const auto halfway = timeToReach(points, std::sqrt(0.04 * 0.02));
  ASSERT_TRUE(halfway);
  EXPECT_NEAR(halfway->spp, std::sqrt(32.0 * 64.0), 1e-9);
  EXPECT_NEAR(halfway->seconds, std::sqrt(1.5), 1e-9);
  EXPECT_NEAR(timeToReach(points, 0.1)->seconds, 0.6, 1e-12);
}

TEST(QualityCurve, TargetsBeyondTheCurveAreExtrapolatedOrRefused) {
  const auto far = timeToReach(powerLaw(0.4, -0.5, 16), 0.01);  // 1600 spp on the same law
  ASSERT_TRUE(far);
  EXPECT_NEAR(far->spp, 1600.0, 1e-6);
  EXPECT_TRUE(far->extrapolated);
  const auto first = timeToReach(powerLaw(0.4, -0.5, 16), 1.0);  // already met at 1 spp
  ASSERT_TRUE(first);
  EXPECT_DOUBLE_EQ(first->spp, 1.0);
  // An error that does not fall cannot be extrapolated.
  EXPECT_FALSE(timeToReach(powerLaw(0.4, 0.1, 16), 0.01));
}

// A diffuse ball under a sphere light and a sky: no caustics, so the single-run RMSE follows the
// Monte Carlo law closely.
fs::path writeDiffuseShot(const fs::path& dir) {
  const fs::path path = dir / "diffuse.json";
  std::ofstream(path) << R"({"version": 1, "frames": {"start": 1, "end": 2}, "output": "out/d.####.exr",
    "render": {"width": 16, "height": 9, "spp": 1, "maxDepth": 6, "seed": 3},
    "camera": {"position": [0, 0, 3], "lookAt": [0, 0, 0], "fov": 30}, "background": [0.3, 0.35, 0.4],
    "materials": {"grey": {"type": "diffuse", "albedo": [0.5, 0.5, 0.5]}},
    "lights": [{"type": "sphere", "center": [1, 1.5, 2], "radius": 0.2, "power": 40}],
    "shapes": [{"type": "sphere", "center": [0.1, -0.1, -0.3], "radius": 0.6, "material": "grey"}]})";
  return path;
}

// The RMSE column of the table (rows "spp mean-spp seconds RMSE").
std::vector<std::string> rmseColumn(const std::string& output) {
  std::vector<std::string> column;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream row(line);
    int spp = 0;
    double meanSpp = 0, seconds = 0;
    std::string rmse, rest;
    if (row >> spp >> meanSpp >> seconds >> rmse && !(row >> rest)) column.push_back(rmse);
  }
  return column;
}

TEST(BenchQuality, ReportsTheSlopeAndReusesTheCachedReference) {
  const fs::path dir = test::testDirectory("bench_quality", /*fresh=*/true);
  const std::vector<std::string> args = {"bench", "--quality", writeDiffuseShot(dir).string(), "--width", "48",
                                         "--height", "27", "--reference-spp", "4096", "--max-spp", "64",
                                         "--frame", "2", "--target", "0.004", "--cache", (dir / "cache").string()};
  const auto first = test::lacrima(args);
  ASSERT_EQ(first.exitStatus, 0) << first.output;
  EXPECT_NE(first.output.find("(rendered in"), std::string::npos) << first.output;
  const size_t at = first.output.find("RMSE-vs-spp slope");
  ASSERT_NE(at, std::string::npos) << first.output;
  const double slope = std::stod(first.output.substr(at + 17));
  // The default Sobol sampler: steeper than independent samples' -0.5 (measured -0.69; the
  // independent baseline is checked in tests/renderer/sampler_convergence_test.cpp).
  EXPECT_LT(slope, -0.58) << first.output;
  EXPECT_GT(slope, -1.0) << first.output;  // no faster than a smooth 2D integrand allows
  EXPECT_NE(first.output.find("RMSE 0.004"), std::string::npos) << first.output;

  const auto second = test::lacrima(args);
  ASSERT_EQ(second.exitStatus, 0) << second.output;
  EXPECT_NE(second.output.find("(cached)"), std::string::npos) << second.output;
  // Renders are deterministic: the same RMSE column (the seconds differ).
  const std::vector<std::string> rmse = rmseColumn(first.output);
  EXPECT_EQ(rmse.size(), 7u) << first.output;  // 1, 2, 4, ..., 64 spp
  EXPECT_EQ(rmseColumn(second.output), rmse);
}

TEST(BenchQuality, AFrameOutsideTheShotIsBadInput) {
  const fs::path dir = test::testDirectory("bench_quality", /*fresh=*/true);
  const auto run = test::lacrima({"bench", "--quality", writeDiffuseShot(dir).string(), "--frame", "9", "--cache",
                                  (dir / "cache").string()});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_NE(run.output.find("--frame 9: the shot's frames are 1-2"), std::string::npos) << run.output;
}

// --caustics renders the curve in another mode while the reference keeps the shot's (MNEE): the
// second mode finds the first's reference cached, and its curve differs (brute force is far
// noisier on the drop's focused caustic).
TEST(BenchQuality, CausticsModeChangesTheMeasuredRendersNotTheReference) {
  const fs::path dir = test::testDirectory("bench_quality_caustics", /*fresh=*/true);
  const std::string shot = std::string(LACRIMA_SOURCE_DIR) + "/scenes/shots/caustic_drop.json";
  const auto run = [&](const std::string& mode) {
    return test::lacrima({"bench", "--quality", shot, "--width", "32", "--height", "18", "--reference-spp", "256",
                          "--max-spp", "16", "--caustics", mode, "--cache", (dir / "cache").string()});
  };
  const auto mnee = run("mnee");
  ASSERT_EQ(mnee.exitStatus, 0) << mnee.output;
  EXPECT_NE(mnee.output.find("caustics mnee"), std::string::npos) << mnee.output;
  EXPECT_NE(mnee.output.find("(rendered in"), std::string::npos) << mnee.output;
  const auto bruteForce = run("off");
  ASSERT_EQ(bruteForce.exitStatus, 0) << bruteForce.output;
  EXPECT_NE(bruteForce.output.find("caustics off"), std::string::npos) << bruteForce.output;
  EXPECT_NE(bruteForce.output.find("(cached)"), std::string::npos) << bruteForce.output;
  EXPECT_EQ(rmseColumn(mnee.output).size(), 5u) << mnee.output;  // 1, 2, 4, 8, 16 spp
  EXPECT_NE(rmseColumn(bruteForce.output), rmseColumn(mnee.output));

  const auto unknown = run("focused");
  EXPECT_EQ(unknown.exitStatus, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("--caustics"), std::string::npos) << unknown.output;
}

}  // namespace quality_curve_test
}  // namespace lacrima::cli
