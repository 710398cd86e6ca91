#pragma once
// "Did you mean ...?" for unknown keys, blendshapes, parts and material names.
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

}  // namespace lacrima::shotfile
