// Metrics, thresholds, pairing and thresholds.json of the image comparison behind `lacrima diff`
// and `lacrima test-suite` (tools/src/diff), on synthetic images with known answers.
#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "diff/image_diff.hpp"
#include "diff/image_pairs.hpp"
#include "diff/suite_thresholds.hpp"
#include "lacrima/base/error.hpp"
#include "support/test_directory.hpp"

namespace lacrima::diff {
namespace image_diff_test {

namespace fs = std::filesystem;

// 4 x 3 pixels, channels R G B A Z, all 0 (Z 1).
Image blank(const std::string& path) {
  Image image;
  image.path = path;
  image.width = 4;
  image.height = 3;
  image.channels = {"R", "G", "B", "A", "Z"};
  image.values.assign(4 * 3 * 5, 0.0f);
  for (size_t i = 4; i < image.values.size(); i += 5) image.values[i] = 1.0f;
  image.highDynamicRange = true;
  return image;
}

void set(Image& image, int x, int y, const std::string& channel, float value) {
  image.values[(size_t(y) * size_t(image.width) + size_t(x)) * image.channels.size() +
               size_t(image.channelIndex(channel))] = value;
}

const GroupMetrics& group(const Comparison& c, const std::string& name) {
  for (const GroupMetrics& g : c.groups)
    if (g.name == name) return g;
  throw std::runtime_error("no group " + name);
}

CompareOptions withThresholds(Thresholds t) {
  CompareOptions o;
  o.thresholds = t;
  o.flip = false;
  return o;
}

TEST(ImageDiff, ChannelGroups) {
  const std::vector<ChannelGroup> groups =
      channelGroups({"R", "G", "B", "A", "Z", "N.X", "N.Y", "N.Z", "albedo.R", "albedo.G", "albedo.B"});
  ASSERT_EQ(groups.size(), 4u);
  EXPECT_EQ(groups[0].name, "beauty");
  EXPECT_EQ(groups[0].channels, (std::vector<std::string>{"R", "G", "B", "A"}));
  EXPECT_EQ(groups[1].name, "Z");
  EXPECT_EQ(groups[2].name, "N");
  EXPECT_EQ(groups[2].channels.size(), 3u);
  EXPECT_EQ(groups[3].name, "albedo");
}

TEST(ImageDiff, SingleChangedPixelGivesExactMetrics) {
  const Image a = blank("a.exr");
  Image b = blank("b.exr");
  set(b, 2, 1, "G", 0.5f);
  const Comparison c = compareImages(a, b, withThresholds({0.1, 0.0, 0.1, 0.0, {}}));
  const GroupMetrics& beauty = group(c, "beauty");
  EXPECT_DOUBLE_EQ(beauty.maxError, 0.5);
  EXPECT_EQ(beauty.maxX, 2);
  EXPECT_EQ(beauty.maxY, 1);
  EXPECT_EQ(beauty.maxChannel, "G");
  // 12 pixels x 4 channels = 48 values, one of them 0.5 off.
  EXPECT_DOUBLE_EQ(beauty.meanError, 0.5 / 48.0);
  EXPECT_DOUBLE_EQ(beauty.rmsError, std::sqrt(0.25 / 48.0));
  EXPECT_NEAR(beauty.psnr, 10.0 * std::log10(1.0 / (0.25 / 48.0)), 1e-12);  // peak 1.0
  EXPECT_EQ(beauty.failPixels, 1u);
  EXPECT_DOUBLE_EQ(beauty.failPercent, 100.0 / 12.0);
  EXPECT_EQ(beauty.verdict, Verdict::Fail);
  const GroupMetrics& z = group(c, "Z");
  EXPECT_EQ(z.maxError, 0.0);
  EXPECT_TRUE(std::isinf(z.psnr));
  EXPECT_EQ(z.verdict, Verdict::Pass);
  EXPECT_EQ(c.verdict, Verdict::Fail);
}

struct ThresholdCase {
  Thresholds thresholds;
  Verdict expected;
};

TEST(ImageDiff, ThresholdMatrix) {
  // One pixel of 12 (8.33 %) differs by 0.5 in one channel; mean error 0.5 / 48 = 0.0104.
  const Image a = blank("a.exr");
  Image b = blank("b.exr");
  set(b, 2, 1, "G", 0.5f);
  const ThresholdCase cases[] = {
      {{1e-6, 0.0, 1e-6, 0.0, {}}, Verdict::Fail},   // idiff defaults: identical or fail
      {{0.6, 0.0, 1e-6, 0.0, {}}, Verdict::Warn},    // under fail, over warn
      {{0.6, 0.0, 0.6, 0.0, {}}, Verdict::Pass},     // under both
      {{0.6, 0.0, 0.1, 8.0, {}}, Verdict::Warn},     // 8.33 % > 8 %
      {{0.6, 0.0, 0.1, 9.0, {}}, Verdict::Pass},     // 8.33 % <= 9 %
      {{0.1, 8.0, 0.1, 50.0, {}}, Verdict::Fail},    // 8.33 % > 8 %
      {{0.1, 9.0, 0.01, 50.0, {}}, Verdict::Pass},   // within both allowances
      {{0.1, 9.0, 0.01, 50.0, 0.01}, Verdict::Fail},  // mean 0.0104 > 0.01
      {{0.1, 9.0, 0.01, 50.0, 0.011}, Verdict::Pass},
  };
  for (const ThresholdCase& tc : cases) {
    CompareOptions o = withThresholds(tc.thresholds);
    o.groups = {"beauty"};
    EXPECT_EQ(compareImages(a, b, o).verdict, tc.expected)
        << "fail " << tc.thresholds.fail << " " << tc.thresholds.failPercent << "%, warn " << tc.thresholds.warn
        << " " << tc.thresholds.warnPercent << "%";
  }
}

TEST(ImageDiff, ReasonsSayWhatFailed) {
  const Image a = blank("a.exr");
  Image b = blank("b.exr");
  set(b, 2, 1, "G", 0.5f);
  CompareOptions o = withThresholds({0.1, 0.0, 0.1, 0.0, 0.001});
  o.groups = {"beauty"};
  const Comparison c = compareImages(a, b, o);
  ASSERT_EQ(c.groups[0].reasons.size(), 2u);
  EXPECT_EQ(c.groups[0].reasons[0], "beauty: 1 pixels (8.33%) differ by more than 0.1 (allowed 0%)");
  EXPECT_EQ(c.groups[0].reasons[1], "beauty: mean error 0.0104167 exceeds 0.001");
}

TEST(ImageDiff, InfinitiesMatchAndNanFails) {
  Image a = blank("a.exr"), b = blank("b.exr");
  set(a, 0, 0, "Z", INFINITY);
  set(b, 0, 0, "Z", INFINITY);  // background depth on both sides: equal
  EXPECT_EQ(compareImages(a, b, withThresholds({})).verdict, Verdict::Pass);
  set(b, 1, 1, "R", NAN);
  const Comparison c = compareImages(a, b, withThresholds({1.0, 0.0, 1.0, 0.0, {}}));
  EXPECT_TRUE(std::isinf(group(c, "beauty").maxError));
  EXPECT_EQ(c.verdict, Verdict::Fail);
}

TEST(ImageDiff, MismatchesAreErrorsNamingTheFile) {
  const Image a = blank("a.exr");
  Image smaller = blank("b.exr");
  smaller.width = 2;
  smaller.height = 6;
  try {
    compareImages(a, smaller, withThresholds({}));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "b.exr: 2 x 6 pixels, but a.exr has 4 x 3");
  }
  Image noDepth = blank("b.exr");
  noDepth.channels = {"R", "G", "B", "A", "Y"};
  try {
    compareImages(a, noDepth, withThresholds({}));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "a.exr: no channel 'Y' (b.exr has it)");
  }
  CompareOptions onlyZ = withThresholds({});
  onlyZ.groups = {"Z"};
  try {
    compareImages(noDepth, a, onlyZ);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "b.exr: no channel group 'Z' (it has beauty, Y)");
  }
  onlyZ.groups = {"beauty"};  // the Z/Y difference does not matter when only the beauty is compared
  EXPECT_EQ(compareImages(a, noDepth, onlyZ).verdict, Verdict::Pass);
}

TEST(ImageDiff, FlipOfTheBeautyIsZeroForIdenticalImagesAndPositiveOtherwise) {
  Image a = blank("a.exr");
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) set(a, x, y, "G", 0.3f);
  Image b = a;
  CompareOptions o;
  const Comparison same = compareImages(a, b, o);
  ASSERT_TRUE(same.flip.has_value());
  EXPECT_EQ(same.flip->mean, 0.0);
  EXPECT_TRUE(same.flip->highDynamicRange);
  set(b, 1, 1, "R", 0.8f);
  const Comparison differing = compareImages(a, b, o);
  EXPECT_GT(differing.flip->mean, 0.0);
  EXPECT_EQ(differing.flip->maxX, 1);
  EXPECT_EQ(differing.flip->maxY, 1);
}

void writeImage(const fs::path& path, float value, int width = 4) {
  OIIO::ImageSpec spec(width, 3, 3, OIIO::TypeDesc::HALF);
  OIIO::ImageBuf buffer(spec);
  const float rgb[3] = {value, value, value};
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < width; ++x) buffer.setpixel(x, y, rgb, 3);
  ASSERT_TRUE(buffer.write(path.string())) << buffer.geterror();
}

TEST(ImagePairs, DirectoriesPairByNameAndListMissingFiles) {
  const fs::path dir = test::testDirectory("image_pairs", true);
  fs::create_directories(dir / "a");
  fs::create_directories(dir / "b");
  writeImage(dir / "a/one.exr", 0.1f);
  writeImage(dir / "b/one.exr", 0.1f);
  writeImage(dir / "a/two.exr", 0.1f);
  writeImage(dir / "b/three.exr", 0.1f);
  std::ofstream(dir / "a/notes.txt") << "not an image";
  const std::vector<ImagePair> pairs = pairImages((dir / "a").string(), (dir / "b").string());
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(pairs[0].label, "one.exr");
  EXPECT_TRUE(pairs[0].a && pairs[0].b);
  EXPECT_EQ(pairs[1].label, "three.exr");
  EXPECT_FALSE(pairs[1].a);
  EXPECT_EQ(pairs[2].label, "two.exr");
  EXPECT_FALSE(pairs[2].b);
}

TEST(ImagePairs, FramePatternsPairByNumber) {
  const fs::path dir = test::testDirectory("image_pairs", true);
  fs::create_directories(dir / "old");
  fs::create_directories(dir / "new");
  for (int f : {1, 2, 3}) writeImage(dir / "old" / ("shot.000" + std::to_string(f) + ".exr"), 0.2f);
  for (int f : {1, 3}) writeImage(dir / "new" / ("take2." + std::to_string(f) + ".exr"), 0.2f);
  writeImage(dir / "new/take2.x.exr", 0.2f);  // not a frame
  EXPECT_TRUE(isFramePattern("x/shot.####.exr"));
  EXPECT_TRUE(isFramePattern("x/shot.%04d.exr"));
  EXPECT_FALSE(isFramePattern("x/shot.0001.exr"));
  const std::vector<ImagePair> pairs =
      pairImages((dir / "old/shot.####.exr").string(), (dir / "new/take2.%d.exr").string());
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(pairs[1].label, "frame 2");
  EXPECT_TRUE(pairs[1].a.has_value());
  EXPECT_FALSE(pairs[1].b.has_value());
  EXPECT_EQ(*pairs[2].b, (dir / "new/take2.3.exr").string());
}

TEST(ImagePairs, KindsMustMatch) {
  const fs::path dir = test::testDirectory("image_pairs", true);
  writeImage(dir / "one.exr", 0.1f);
  try {
    pairImages((dir / "one.exr").string(), dir.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "one.exr").string() + " is a file but " + dir.string() +
                                         " is a directory: compare two files, two directories or two frame patterns");
  }
  try {
    pairImages((dir / "missing.exr").string(), (dir / "one.exr").string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "missing.exr").string() + ": no such file or directory");
  }
}

fs::path writeThresholds(const std::string& text) {
  const fs::path path = test::testDirectory("suite_thresholds", true) / "thresholds.json";
  std::ofstream(path) << text;
  return path;
}

TEST(SuiteThresholds, ShotEntriesOverrideTheDefault) {
  const fs::path path = writeThresholds(R"(// comments are allowed
    {"default": {"fail": 0.05, "failpercent": 0.5, "maxmean": 2e-3},
     "shots": {"furnace": {"fail": 0.01, "failpercent": 0.1}, "noisy": {"warn": 0.02, "aovs": ["beauty", "N"]}}})");
  const SuiteThresholds s = loadSuiteThresholds(path.string());
  EXPECT_DOUBLE_EQ(s.forShot("other").thresholds.fail, 0.05);
  EXPECT_DOUBLE_EQ(s.forShot("other").thresholds.warn, 0.005);  // fail / 10
  EXPECT_DOUBLE_EQ(s.forShot("other").thresholds.warnPercent, 0.5);
  EXPECT_EQ(s.forShot("other").aovs, std::vector<std::string>{"beauty"});
  const Thresholds& furnace = s.forShot("furnace").thresholds;
  EXPECT_DOUBLE_EQ(furnace.fail, 0.01);
  EXPECT_DOUBLE_EQ(furnace.failPercent, 0.1);
  EXPECT_DOUBLE_EQ(*furnace.maxMeanError, 2e-3);  // from the default
  EXPECT_DOUBLE_EQ(furnace.warn, 0.001);
  EXPECT_DOUBLE_EQ(s.forShot("noisy").thresholds.warn, 0.02);
  EXPECT_EQ(s.forShot("noisy").aovs, (std::vector<std::string>{"beauty", "N"}));
}

TEST(SuiteThresholds, BadValuesNameFileAndJsonPath) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"shots": {"a": {"fail": -1}}})", "/shots/a/fail: expected a number >= 0, found -1"},
      {R"({"default": {"fail": "0.1"}})", R"(/default/fail: expected a number >= 0, found "0.1")"},
      {R"({"default": {"fial": 0.1}})",
       "/default/fial: unknown key (expected fail, failpercent, warn, warnpercent, maxmean or aovs)"},
      {R"({"defaults": {}})", "/defaults: unknown key (expected default or shots)"},
      {R"({"default": {"aovs": []}})", "/default/aovs: expected a non-empty list of channel group names"},
  };
  for (const auto& [text, message] : cases) {
    const fs::path path = writeThresholds(text);
    try {
      loadSuiteThresholds(path.string());
      ADD_FAILURE() << "no error for " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), path.string() + ": " + message);
    }
  }
}

}  // namespace image_diff_test
}  // namespace lacrima::diff
