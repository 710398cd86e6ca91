#include <gtest/gtest.h>

#include "lacrima/scenes/shot.hpp"

namespace lacrima {
namespace frame_pattern_test {

TEST(ExpandFramePattern, HashRunIsZeroPadded) {
  EXPECT_EQ(expandFramePattern("renders/tear_closeup.####.exr", 7), "renders/tear_closeup.0007.exr");
  EXPECT_EQ(expandFramePattern("a.#.exr", 3), "a.3.exr");
  EXPECT_EQ(expandFramePattern("a.##.exr", 0), "a.00.exr");
}

TEST(ExpandFramePattern, WiderNumbersAreNotTruncated) {
  EXPECT_EQ(expandFramePattern("a.####.exr", 12345), "a.12345.exr");
  EXPECT_EQ(expandFramePattern("a.#.exr", 48), "a.48.exr");
}

TEST(ExpandFramePattern, EveryRunIsReplaced) {
  EXPECT_EQ(expandFramePattern("f###/img.####.exr", 42), "f042/img.0042.exr");
}

TEST(ExpandFramePattern, NegativeFramesKeepTheirSign) { EXPECT_EQ(expandFramePattern("a.####.exr", -5), "a.-005.exr"); }

TEST(ExpandFramePattern, PrintfStyle) {
  EXPECT_EQ(expandFramePattern("a.%04d.exr", 7), "a.0007.exr");
  EXPECT_EQ(expandFramePattern("a.%d.exr", 7), "a.7.exr");
  EXPECT_EQ(expandFramePattern("a.%02d.exr", 123), "a.123.exr");
}

TEST(ExpandFramePattern, OtherPercentSequencesAreLiteral) {
  EXPECT_EQ(expandFramePattern("50%_grey.%s.exr", 7), "50%_grey.%s.exr");
  EXPECT_EQ(expandFramePattern("a%", 7), "a%");
}

TEST(ExpandFramePattern, NoFrameFieldLeavesThePatternAlone) {
  EXPECT_EQ(expandFramePattern("still.exr", 7), "still.exr");
  EXPECT_EQ(expandFramePattern("", 7), "");
}

}  // namespace frame_pattern_test
}  // namespace lacrima
