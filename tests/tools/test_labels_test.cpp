// The ctest labels (tests/test_labels.cmake): every test has one, and the cluster, slow and
// statistical selections hold what the README says they do. Asks ctest itself (-N lists, runs
// nothing) in this build's test folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "support/run_command.hpp"

namespace lacrima {
namespace test_labels_test {

// `ctest -N` in this build's tests folder with `selection` (e.g. "-L '^slow$'"): its output.
std::string listTests(const std::string& selection) {
  const std::filesystem::path testsFolder = std::filesystem::path(LACRIMA_TEST_OUTPUT_DIR).parent_path();
  const test::CommandResult r =
      test::runCommand("ctest --test-dir " + test::shellQuote(testsFolder.string()) + " -N " + selection);
  EXPECT_EQ(r.exitStatus, 0) << r.output;
  return r.output;
}

int totalOf(const std::string& listing) {
  std::smatch m;
  if (!std::regex_search(listing, m, std::regex("Total Tests: ([0-9]+)"))) return -1;
  return std::stoi(m[1]);
}

bool lists(const std::string& listing, const std::string& test) {
  return listing.find(": " + test + "\n") != std::string::npos;
}

TEST(TestLabels, EveryTestHasALabel) {
  const int all = totalOf(listTests(""));
  ASSERT_GT(all, 800);
  EXPECT_EQ(totalOf(listTests("-L '^(unit|statistical|render|slow|cluster)$'")), all);
}

TEST(TestLabels, SelectionsHoldWhatTheyPromise) {
  const std::string cluster = listTests("-L '^cluster$'");
  EXPECT_EQ(totalOf(cluster), 1) << cluster;
  EXPECT_TRUE(lists(cluster, "FarmCluster.SixFramesInThreeChunksMatchALocalRenderBitwise")) << cluster;
  const std::string slow = listTests("-L '^slow$'");
  EXPECT_TRUE(lists(slow, "DefaultShotStory.TheMeniscusOverflowsWhileTheCameraIsOnTheEye")) << slow;
  const std::string statistical = listTests("-L '^statistical$'");
  EXPECT_TRUE(lists(statistical, "AnalyticScenes.CameraInsideEmittingSphereSeesEmissionOverOneMinusAlbedo"));
  EXPECT_NE(statistical.find(": AllBsdfs/BsdfChi2.SampleMatchesPdf/"), std::string::npos) << statistical;
  const std::string unit = listTests("-L '^unit$'");
  EXPECT_TRUE(lists(unit, "Fresnel.NormalIncidenceTearIsAboutTwoPercent")) << unit;
  EXPECT_FALSE(lists(unit, "FarmCluster.SixFramesInThreeChunksMatchALocalRenderBitwise"));
  EXPECT_FALSE(lists(unit, "AnalyticScenes.CameraInsideEmittingSphereSeesEmissionOverOneMinusAlbedo"));
  // A quick run without the slow and cluster tests leaves out exactly those.
  EXPECT_EQ(totalOf(listTests("-LE '^(slow|cluster)$'")), totalOf(listTests("")) - totalOf(slow));
}

}  // namespace test_labels_test
}  // namespace lacrima
