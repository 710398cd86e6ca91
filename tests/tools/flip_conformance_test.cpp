// `lacrima diff`'s FLIP against NVIDIA's own implementation (NVlabs/flip, commit 1eb247c, the C++
// tool with default settings): tests/data/flip holds 11 image pairs and expected.json with the
// values NVIDIA's code computes for each (see tests/data/flip/README.md). Each pair runs through the
// real binary (`lacrima diff A B --json`) and is compared: the mean within 1e-5 of NVIDIA's mean
// (its error map averaged in double), the maximum within 1e-4 at the same pixel, and for HDR the
// start and stop exposures within 1e-5 and the same number of exposures.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/run_command.hpp"

namespace lacrima {
namespace flip_conformance_test {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kFlipData = fs::path(LACRIMA_SOURCE_DIR) / "tests/data/flip";

// The tolerances the oracle is held to: lacrima's FLIP must give NVIDIA's mean within 1e-5, its
// HDR start and stop exposures within 1e-5 and its maximum within 1e-4 (docs/diff.md).
constexpr double kMeanTolerance = 1e-5, kExposureTolerance = 1e-5, kMaxTolerance = 1e-4;

json expectedPairs() {
  std::ifstream in(kFlipData / "expected.json");
  return json::parse(in);
}

std::vector<std::string> pairNames() {
  std::vector<std::string> names;
  for (const json& pair : expectedPairs()) names.push_back(pair.at("pair").get<std::string>());
  return names;
}

json expectedPair(const std::string& name) {
  for (const json& pair : expectedPairs())
    if (pair.at("pair") == name) return pair;
  return {};
}

// The "flip" object of `lacrima diff --json` for one pair; empty when the command failed.
json lacrimaFlip(const std::string& reference, const std::string& testImage, std::string& output) {
  // Thresholds wide open: only FLIP is of interest, and the verdict must not turn it into exit 2.
  const test::CommandResult run = test::runCommand(
      "(" + test::shellQuote(LACRIMA_BINARY) + " diff " + test::shellQuote((kFlipData / reference).string()) + " " +
      test::shellQuote((kFlipData / testImage).string()) + " --json --fail 1e30 --warn 1e30 2>/dev/null)");
  output = run.output;
  if (run.exitStatus != 0) return {};
  const json report = json::parse(run.output, nullptr, /*allow_exceptions=*/false);
  if (report.is_discarded() || report.at("pairs").empty() || !report["pairs"][0].contains("flip")) return {};
  return report["pairs"][0]["flip"];
}

class FlipConformance : public ::testing::TestWithParam<std::string> {};

TEST_P(FlipConformance, MatchesNvidiasImplementation) {
  const json expected = expectedPair(GetParam());
  ASSERT_FALSE(expected.is_null()) << GetParam();
  std::string output;
  const json flip = lacrimaFlip(expected.at("reference"), expected.at("test"), output);
  ASSERT_FALSE(flip.is_null()) << output;

  EXPECT_NEAR(flip.at("mean").get<double>(), expected.at("mean_flip").get<double>(), kMeanTolerance);
  EXPECT_NEAR(flip.at("max").get<double>(), expected.at("max_flip").get<double>(), kMaxTolerance);
  // Identical images have no largest error, so no pixel to compare.
  if (expected.at("max_flip").get<double>() > 0.0) {
    EXPECT_EQ(flip.at("maxPixel"), expected.at("max_pixel")) << "the largest error is at another pixel";
  }

  const bool hdr = expected.at("kind") == "hdr";
  EXPECT_EQ(flip.at("hdr").get<bool>(), hdr);
  if (!hdr) return;
  EXPECT_NEAR(flip.at("startExposure").get<double>(), expected.at("start_exposure").get<double>(), kExposureTolerance);
  EXPECT_NEAR(flip.at("stopExposure").get<double>(), expected.at("stop_exposure").get<double>(), kExposureTolerance);
  EXPECT_EQ(flip.at("exposures").get<int>(), expected.at("num_exposures").get<int>());
}

INSTANTIATE_TEST_SUITE_P(OraclePairs, FlipConformance, ::testing::ValuesIn(pairNames()),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '.') c = '_';
                           return name;
                         });

// The test cannot pass vacuously: all 11 pairs are there, LDR and HDR.
TEST(FlipConformanceData, HoldsElevenPairsOfBothKinds) {
  int ldr = 0, hdr = 0;
  for (const json& pair : expectedPairs()) {
    (pair.at("kind") == "hdr" ? hdr : ldr) += 1;
    EXPECT_TRUE(fs::exists(kFlipData / pair.at("reference").get<std::string>())) << pair.dump();
    EXPECT_TRUE(fs::exists(kFlipData / pair.at("test").get<std::string>())) << pair.dump();
  }
  EXPECT_EQ(ldr, 6);
  EXPECT_EQ(hdr, 5);
}

}  // namespace flip_conformance_test
}  // namespace lacrima
