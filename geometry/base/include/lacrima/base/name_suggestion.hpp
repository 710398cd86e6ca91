#pragma once
// "Did you mean ...?" for names typed by users: blendshapes, controls, CSV columns.
#include <string>
#include <vector>

namespace lacrima {

// Edit distance with unit-cost insertions, deletions and substitutions (Levenshtein 1966,
// Wagner & Fischer 1974 dynamic programme, two rows). Case-sensitive, on bytes.
size_t levenshteinDistance(const std::string& a, const std::string& b);

// The valid name with the smallest edit distance to name, comparing case-insensitively first so
// "jawopen" finds "jawOpen" (ties: the earlier name). "" when valid is empty.
std::string closestName(const std::string& name, const std::vector<std::string>& valid);

// "unknown <what> 'name' (did you mean 'closest'?)", or without the suggestion when there are no
// valid names.
std::string unknownNameMessage(const std::string& what, const std::string& name, const std::vector<std::string>& valid);

}  // namespace lacrima
