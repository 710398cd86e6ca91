// `lacrima diff` and `lacrima test-suite` through the real binary: the exit status CI relies on
// (0 pass, 1 warn, 2 fail or error), sequences with a missing frame, the exact error messages,
// the output files, and a test-suite run against a reference that has been tampered with.
#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/test_directory.hpp"
#include "tools/lacrima_cli_support.hpp"

namespace lacrima {
namespace diff_cli_test {

namespace fs = std::filesystem;
using test::commandLine;
using test::lacrima;
using test::lacrimaStderr;

fs::path freshDir() { return test::testDirectory("diff_cli", /*fresh=*/true); }

// An 8 x 6 RGBA half EXR of constant grey `value`, with pixel (3, 2) of channel G set to `changed`.
void writeExr(const fs::path& path, float value, float changed) {
  OIIO::ImageSpec spec(8, 6, 4, OIIO::TypeDesc::HALF);
  spec.channelnames = {"R", "G", "B", "A"};
  spec.alpha_channel = 3;
  OIIO::ImageBuf buffer(spec);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) {
      const float pixel[4] = {value, x == 3 && y == 2 ? changed : value, value, 1.0f};
      buffer.setpixel(x, y, pixel, 4);
    }
  fs::create_directories(path.parent_path());
  ASSERT_TRUE(buffer.write(path.string())) << buffer.geterror();
}

struct ExitCase {
  std::vector<std::string> options;
  int exitStatus;
};

TEST(DiffCli, ExitStatusFollowsTheThresholds) {
  const fs::path dir = freshDir();
  writeExr(dir / "a.exr", 0.25f, 0.25f);
  writeExr(dir / "b.exr", 0.25f, 0.75f);  // one pixel of 48 (2.08 %) off by 0.5 in G
  const ExitCase cases[] = {
      {{}, 2},                                                          // defaults: identical or fail
      {{"--fail", "0.6"}, 1},                                           // not failing, but over warn 1e-6
      {{"--fail", "0.6", "--warn", "0.6"}, 0},                          // under both
      {{"--fail", "0.1", "--failpercent", "2"}, 2},                     // 2.08 % > 2 %
      {{"--fail", "0.1", "--failpercent", "3", "--warnpercent", "3"}, 0},
      {{"--fail", "0.1", "--failpercent", "3", "--warnpercent", "3", "--max-mean", "0.001"}, 2},  // mean 0.0026
  };
  for (const ExitCase& c : cases) {
    std::vector<std::string> args = {"diff", (dir / "a.exr").string(), (dir / "b.exr").string()};
    args.insert(args.end(), c.options.begin(), c.options.end());
    const auto run = lacrima(args);
    EXPECT_EQ(run.exitStatus, c.exitStatus) << run.output;
  }
  const auto same = lacrima({"diff", (dir / "a.exr").string(), (dir / "a.exr").string()});
  EXPECT_EQ(same.exitStatus, 0) << same.output;
  EXPECT_NE(same.output.find("PASS"), std::string::npos);
}

TEST(DiffCli, TableShowsTheLargestDifferenceAndWritesImages) {
  const fs::path dir = freshDir();
  writeExr(dir / "a.exr", 0.25f, 0.25f);
  writeExr(dir / "b.exr", 0.25f, 0.75f);
  const auto run = lacrima({"diff", (dir / "a.exr").string(), (dir / "b.exr").string(), "--out",
                            (dir / "out/d.exr").string(), "--flip-out", (dir / "out/f.png").string()});
  EXPECT_EQ(run.exitStatus, 2);
  EXPECT_NE(run.output.find("(3, 2) G"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("FAIL: beauty: 1 pixels (2.08%) differ by more than 1e-06 (allowed 0%)"),
            std::string::npos)
      << run.output;
  OIIO::ImageBuf difference((dir / "out/d.exr").string());
  ASSERT_TRUE(difference.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << difference.geterror();
  EXPECT_EQ(difference.spec().channelnames, (std::vector<std::string>{"R", "G", "B", "A"}));
  EXPECT_FLOAT_EQ(difference.getchannel(3, 2, 0, 1), 0.5f);
  EXPECT_FLOAT_EQ(difference.getchannel(4, 2, 0, 1), 0.0f);
  EXPECT_TRUE(fs::exists(dir / "out/f.png"));
}

TEST(DiffCli, JsonReportForMachines) {
  const fs::path dir = freshDir();
  writeExr(dir / "a.exr", 0.25f, 0.25f);
  writeExr(dir / "b.exr", 0.25f, 0.75f);
  const auto run = test::runCommand(
      commandLine({"diff", (dir / "a.exr").string(), (dir / "b.exr").string(), "--json", "--fail", "0.6"}) +
      " 2>/dev/null");
  EXPECT_EQ(run.exitStatus, 1);
  EXPECT_EQ(run.output.front(), '{');
  EXPECT_NE(run.output.find(R"("exitStatus": 1)"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find(R"("maxChannel": "G")"), std::string::npos);
  EXPECT_NE(run.output.find(R"("verdict": "WARN")"), std::string::npos);
}

TEST(DiffCli, SequenceWithAMissingFrameFails) {
  const fs::path dir = freshDir();
  for (int f : {1, 2, 3}) writeExr(dir / "old" / ("shot.000" + std::to_string(f) + ".exr"), 0.5f, 0.5f);
  for (int f : {1, 3}) writeExr(dir / "new" / ("shot.000" + std::to_string(f) + ".exr"), 0.5f, 0.5f);
  const auto run = lacrima({"diff", (dir / "old/shot.####.exr").string(), (dir / "new/shot.####.exr").string()});
  EXPECT_EQ(run.exitStatus, 2) << run.output;
  EXPECT_NE(run.output.find("frame 2: FAIL: missing in B (" + (dir / "old/shot.0002.exr").string() + " has it)"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("3 pairs: 0 failed, 0 warned, 0 missing in A, 1 missing in B, 0 errors"),
            std::string::npos)
      << run.output;
  // The same frames as directories: paired by file name.
  writeExr(dir / "new/shot.0002.exr", 0.5f, 0.5f);
  const auto complete = lacrima({"diff", (dir / "old").string(), (dir / "new").string()});
  EXPECT_EQ(complete.exitStatus, 0) << complete.output;
}

TEST(DiffCli, ErrorsAreOneMessageNamingTheFile) {
  const fs::path dir = freshDir();
  writeExr(dir / "a.exr", 0.25f, 0.25f);
  std::ofstream(dir / "text.exr") << "not an image\n";
  OIIO::ImageBuf small(OIIO::ImageSpec(4, 4, 4, OIIO::TypeDesc::HALF));
  ASSERT_TRUE(small.write((dir / "small.exr").string()));
  const std::string a = (dir / "a.exr").string();

  auto missing = lacrimaStderr({"diff", a, (dir / "nope.exr").string()});
  EXPECT_EQ(missing.exitStatus, 2);
  EXPECT_EQ(missing.output, (dir / "nope.exr").string() + ": no such file or directory\n");

  auto size = lacrimaStderr({"diff", a, (dir / "small.exr").string()});
  EXPECT_EQ(size.exitStatus, 2);
  EXPECT_EQ(size.output, (dir / "small.exr").string() + ": 4 x 4 pixels, but " + a + " has 8 x 6\n");

  auto unreadable = lacrimaStderr({"diff", a, (dir / "text.exr").string()});
  EXPECT_EQ(unreadable.exitStatus, 2);
  EXPECT_EQ(unreadable.output.rfind((dir / "text.exr").string() + ": cannot read image: ", 0), 0u)
      << unreadable.output;
  EXPECT_EQ(std::count(unreadable.output.begin(), unreadable.output.end(), '\n'), 1) << unreadable.output;

  auto group = lacrimaStderr({"diff", a, a, "--aov", "N"});
  EXPECT_EQ(group.exitStatus, 2);
  EXPECT_EQ(group.output, a + ": no channel group 'N' (it has beauty)\n");

  auto option = lacrimaStderr({"diff", a, a, "--fail", "-1"});
  EXPECT_EQ(option.exitStatus, 2);
  EXPECT_NE(option.output.find("--fail: expected a number >= 0, found -1"), std::string::npos) << option.output;
}

TEST(TestSuiteCli, ComparesRendersWithReferencesAndThresholds) {
  // A one-shot suite: the 48 x 48 furnace regression shot, with a reference made by --update,
  // then a reference with one pixel tampered with.
  const fs::path dir = freshDir();
  fs::create_directories(dir / "shots");
  const fs::path furnace = fs::path(LACRIMA_SOURCE_DIR) / "tests/data/regression/water_sphere_furnace.json";
  std::ifstream in(furnace);
  std::string shot((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "shots/furnace.json") << shot;
  std::ofstream(dir / "shots/thresholds.json") << R"({"default": {"fail": 0.01, "failpercent": 0, "maxmean": 1}})";
  const std::string shots = (dir / "shots").string(), refs = (dir / "refs").string(), out = (dir / "out").string();

  const auto update = lacrima({"test-suite", shots, "--references", refs, "--update"});
  ASSERT_EQ(update.exitStatus, 0) << update.output;
  ASSERT_TRUE(fs::exists(dir / "refs/furnace.exr"));
  EXPECT_TRUE(fs::exists(dir / "refs/furnace.png"));  // the preview to review

  const auto pass = lacrima({"test-suite", shots, "--references", refs, "--out", out});
  EXPECT_EQ(pass.exitStatus, 0) << pass.output;
  EXPECT_NE(pass.output.find("furnace: PASS"), std::string::npos) << pass.output;

  OIIO::ImageBuf reference((dir / "refs/furnace.exr").string());
  ASSERT_TRUE(reference.read(0, 0, true, OIIO::TypeDesc::FLOAT));
  const float bright[4] = {5, 5, 5, 1};
  reference.setpixel(1, 1, bright, 4);
  ASSERT_TRUE(reference.write((dir / "refs/furnace.exr").string(), OIIO::TypeDesc::HALF));
  const auto fail = lacrima({"test-suite", shots, "--references", refs, "--out", out});
  EXPECT_EQ(fail.exitStatus, 2) << fail.output;
  EXPECT_NE(fail.output.find("furnace: FAIL"), std::string::npos) << fail.output;
  EXPECT_NE(fail.output.find("test-suite: 1 shots: 0 passed, 0 warned, 1 failed"), std::string::npos) << fail.output;
  EXPECT_TRUE(fs::exists(dir / "out/furnace.diff.exr"));
  EXPECT_TRUE(fs::exists(dir / "out/furnace.flip.png"));

  const auto unknown = lacrimaStderr({"test-suite", shots, "--shot", "nothing"});
  EXPECT_EQ(unknown.exitStatus, 2);
  EXPECT_EQ(unknown.output, "--shot nothing: no shot nothing.json in " + shots + "\n");
}

}  // namespace diff_cli_test
}  // namespace lacrima
