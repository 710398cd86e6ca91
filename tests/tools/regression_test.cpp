// Image regression: each shot of tests/data/regression rendered by `lacrima test-suite`, which
// compares it with tests/data/references/<shot>.exr using tests/data/regression/thresholds.json
// (the one place the thresholds live). One test per shot, so that ctest runs them in parallel.
// On failure the render, |A-B| EXR and FLIP PNG stay in the build tree.
// Regenerate references with tools/update_references.sh "<reason>" (see README).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "support/regression_shots.hpp"
#include "support/run_command.hpp"

namespace lacrima {
namespace regression_test {

namespace fs = std::filesystem;

const fs::path& kRegressionDir = test::regressionDir();

class ImageRegression : public ::testing::TestWithParam<std::string> {};

TEST_P(ImageRegression, MatchesReference) {
  const std::string name = GetParam();
  const fs::path outputDir = fs::path(LACRIMA_TEST_OUTPUT_DIR) / "regression";
  const auto run = test::runCommand(std::string(LACRIMA_BINARY) + " test-suite " + test::shellQuote(kRegressionDir) +
                                    " --shot " + name + " --out " + test::shellQuote(outputDir.string()));
  // 1 is a warning: a few more pixels than usual moved, still within the failure thresholds.
  EXPECT_LE(run.exitStatus, 1) << run.output;
  if (run.exitStatus == 1) std::printf("%s", run.output.c_str());
}

INSTANTIATE_TEST_SUITE_P(Shots, ImageRegression, ::testing::ValuesIn(test::regressionShots()),
                         [](const auto& info) { return info.param; });

}  // namespace regression_test
}  // namespace lacrima
