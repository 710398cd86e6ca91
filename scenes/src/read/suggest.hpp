#pragma once
// "Did you mean ...?" for unknown keys, blendshapes, parts and material names, and the lists of
// names a message offers instead.
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::shotfile {

// lacrima::closestName (base/name_suggestion.hpp: case-insensitive edit distance, case
// differences breaking ties) when it is within max(2, length/3) edits; "" when nothing is close
// enough to be a likely typo.
std::string closestName(std::string_view name, const std::vector<std::string>& candidates);

// "; did you mean 'x'?" or "" when there is no close candidate.
std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates);

// The items with `separator` between them: "a, b, c".
std::string join(const std::vector<std::string>& items, const char* separator);
// The items quoted, comma-separated: "'a', 'b', 'c'".
std::string quotedList(const std::vector<std::string>& items);

// "; did you mean 'x'?" or " (<listName>: a, b, c)" (at most 12 names, else "") or " (<emptyText>)"
// when there are no candidates.
std::string suggestionOrList(const std::string& name, const std::vector<std::string>& candidates,
                             const std::string& listName, const std::string& emptyText);

}  // namespace lacrima::shotfile
