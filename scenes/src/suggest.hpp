#pragma once
// "Did you mean ...?" for unknown keys, blendshapes, parts and material names.
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::shotfile {

// Levenshtein edit distance (insertions, deletions, substitutions each cost 1).
size_t editDistance(std::string_view a, std::string_view b);

// The candidate closest to `name`: an exact match ignoring case first, otherwise the smallest
// edit distance (case-insensitive, ties to the earliest candidate) when it is at most
// max(2, length/3); "" when nothing is close enough.
std::string closestName(std::string_view name, const std::vector<std::string>& candidates);

// "; did you mean 'x'?" or "" when there is no close candidate.
std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace lacrima::shotfile
