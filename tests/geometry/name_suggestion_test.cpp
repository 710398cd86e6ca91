// Edit distance and "did you mean" suggestions.
#include <gtest/gtest.h>

#include "lacrima/base/name_suggestion.hpp"

namespace lacrima {
namespace name_suggestion_test {

TEST(Levenshtein, KnownDistances) {
  EXPECT_EQ(levenshteinDistance("kitten", "sitting"), 3u);  // the textbook example
  EXPECT_EQ(levenshteinDistance("", "abc"), 3u);
  EXPECT_EQ(levenshteinDistance("abc", ""), 3u);
  EXPECT_EQ(levenshteinDistance("jawOpen", "jawOpen"), 0u);
  EXPECT_EQ(levenshteinDistance("jawOpen", "jawOpne"), 2u);  // a transposition is two edits
  EXPECT_EQ(levenshteinDistance("flaw", "lawn"), 2u);
  EXPECT_EQ(levenshteinDistance("ab", "ba"), levenshteinDistance("ba", "ab"));
}

TEST(ClosestName, PrefersCaseOnlyDifferencesThenFewestEdits) {
  const std::vector<std::string> names = {"eyeBlink_L", "eyeBlink_R", "jawOpen", "jawLeft"};
  EXPECT_EQ(closestName("jawopen", names), "jawOpen");
  EXPECT_EQ(closestName("eyeBlink_r", names), "eyeBlink_R");
  EXPECT_EQ(closestName("jawLef", names), "jawLeft");
  EXPECT_EQ(closestName("x", {}), "");
  EXPECT_EQ(unknownNameMessage("blendshape", "jawopen", names), "unknown blendshape 'jawopen' (did you mean 'jawOpen'?)");
}

}  // namespace name_suggestion_test
}  // namespace lacrima
