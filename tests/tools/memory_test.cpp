// Memory over a sequence: `lacrima render --report-memory` prints the peak resident set after
// every frame. A leak per frame makes the peak keep growing long after the first frames, when
// the caches, the thread pool and the Embree scene have reached their size.
#include <gtest/gtest.h>

#include <cstring>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "memory_usage.hpp"
#include "support/test_directory.hpp"
#include "tools/lacrima_cli_support.hpp"

namespace lacrima {
namespace {

// The peak RSS (MiB) printed after `frame`, or none.
std::optional<double> peakAfterFrame(const std::string& output, int frame) {
  const std::regex line("frame " + std::to_string(frame) + R"(: memory: peak RSS ([0-9.]+) MiB, RSS [0-9.]+ MiB)");
  std::smatch match;
  if (!std::regex_search(output, match, line)) return std::nullopt;
  return std::stod(match[1].str());
}

TEST(MemoryUsage, PeakGrowsWhenMemoryIsTouched) {
  const double before = cli::currentMemoryUsage().peakMiB;
  std::vector<char> block(64 << 20);
  std::memset(block.data(), 1, block.size());  // resident only once written
  const cli::MemoryUsage after = cli::currentMemoryUsage();
  EXPECT_GT(after.peakMiB, before + 60);
  EXPECT_GE(after.peakMiB, after.residentMiB);
  EXPECT_GT(after.residentMiB, 60);
  EXPECT_NE(block[block.size() / 2], 0);
}

TEST(MemoryUsage, FormatNamesPeakAndResident) {
  EXPECT_EQ(cli::formatMemoryUsage({123.45, 120.0}), "peak RSS 123.5 MiB, RSS 120.0 MiB");
}

// 60 frames of a shapes-only shot: the peak after frame 60 stays within a few MiB of the peak
// after frame 10 (a leak of 100 kB per frame would add 5 MiB).
TEST(RenderMemory, PeakStaysFlatOverSixtyFrames) {
  const auto dir = test::testDirectory("memory", /*fresh=*/true);
  const auto shot = test::writeSphereShot(dir, 60);
  const auto result = test::lacrima({"render", shot.string(), "--width", "16", "--height", "9", "--spp", "1",
                                     "--quiet", "--report-memory"});
  ASSERT_EQ(result.exitStatus, 0) << result.output;
  const auto at10 = peakAfterFrame(result.output, 10), at60 = peakAfterFrame(result.output, 60);
  ASSERT_TRUE(at10 && at60) << result.output;
  EXPECT_LT(*at60 - *at10, 4.0) << "peak RSS after frame 10: " << *at10 << " MiB, after frame 60: " << *at60;
  EXPECT_NE(result.output.find("lacrima: memory: peak RSS"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace lacrima
