// Image regression: tiny shots rendered at fixed seeds by the real `lacrima` binary, compared
// with committed reference EXRs through OIIO's ImageBufAlgo::compare with explicit thresholds.
// On failure the render and a difference image (x10) are left in the build tree.
// Regenerate references with tools/update_references.sh "<reason>" (see README).
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "support/run_command.hpp"

namespace lacrima {
namespace {

namespace fs = std::filesystem;

struct RegressionCase {
  std::string name;
  float failThreshold;       // per-channel absolute difference that makes a pixel fail
  double maxFailingPercent;  // of pixels
  double maxMeanError;
};

std::ostream& operator<<(std::ostream& os, const RegressionCase& c) { return os << c.name; }

OIIO::ImageBuf readBeauty(const fs::path& path) {
  OIIO::ImageBuf image(path.string());
  image.read(0, 0, true, OIIO::TypeDesc::FLOAT);
  // Compare the beauty only (R,G,B,A); AOVs hold inf depth on background pixels.
  return OIIO::ImageBufAlgo::channels(image, 4, {0, 1, 2, 3});
}

class ImageRegression : public ::testing::TestWithParam<RegressionCase> {};

TEST_P(ImageRegression, MatchesReference) {
  const RegressionCase& c = GetParam();
  const fs::path shot = fs::path(LACRIMA_SOURCE_DIR) / "tests/data/regression" / (c.name + ".json");
  const fs::path reference = fs::path(LACRIMA_SOURCE_DIR) / "tests/data/references" / (c.name + ".exr");
  const fs::path outputDir = fs::path(LACRIMA_TEST_OUTPUT_DIR) / "regression";
  fs::create_directories(outputDir);
  const fs::path rendered = outputDir / (c.name + ".exr");
  fs::remove(rendered);

  const auto run = test::runCommand(std::string(LACRIMA_BINARY) + " render --quiet " + test::shellQuote(shot.string()) +
                                    " --out " + test::shellQuote(rendered.string()));
  ASSERT_EQ(run.exitStatus, 0) << run.output;
  ASSERT_TRUE(fs::exists(reference)) << "no reference " << reference << "; see tools/update_references.sh";

  const OIIO::ImageBuf a = readBeauty(rendered), b = readBeauty(reference);
  const auto result = OIIO::ImageBufAlgo::compare(a, b, c.failThreshold, c.failThreshold / 10.0f);
  const double pixels = double(a.spec().width) * a.spec().height;
  const double failingPercent = 100.0 * double(result.nfail) / pixels;
  const bool pass = !result.error && failingPercent <= c.maxFailingPercent && result.meanerror <= c.maxMeanError;
  if (!pass) {
    const OIIO::ImageBuf diff = OIIO::ImageBufAlgo::mul(OIIO::ImageBufAlgo::absdiff(a, b), 10.0f);
    diff.write((outputDir / (c.name + ".diff_x10.exr")).string());
  }
  EXPECT_TRUE(pass) << c.name << ": " << result.nfail << " pixels (" << failingPercent << "%) differ by more than "
                    << c.failThreshold << ", mean error " << result.meanerror << ", max " << result.maxerror
                    << " at (" << result.maxx << "," << result.maxy << ") channel " << result.maxc
                    << "; render and diff image in " << outputDir;
}

// Thresholds: renders are deterministic, so the same build reproduces references bit for bit;
// the margins absorb float differences between compilers/CPUs (FMA, libm) that move a few
// fireflies, while any change of light transport moves the mean error by far more.
INSTANTIATE_TEST_SUITE_P(Shots, ImageRegression,
                         ::testing::Values(RegressionCase{"drops_on_plane", 0.05f, 0.5, 2e-3},
                                           RegressionCase{"water_sphere_furnace", 0.01f, 0.1, 1e-4},
                                           RegressionCase{"face_cheek_drop", 0.05f, 0.5, 2e-3},
                                           RegressionCase{"face_shedding_tear", 0.05f, 0.5, 2e-3},
                                           RegressionCase{"face_dripping_tear", 0.05f, 0.5, 2e-3},
                                           RegressionCase{"face_liquid_tear", 0.05f, 0.5, 2e-3},
                                           RegressionCase{"face_eye", 0.05f, 0.5, 2e-3}),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace lacrima
