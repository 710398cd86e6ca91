// Closest-name suggestions by edit distance.
#include "lacrima/base/name_suggestion.hpp"

#include <algorithm>
#include <cctype>
#include <numeric>

#include <fmt/format.h>

namespace lacrima {

namespace {

std::string lowercase(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

size_t levenshteinDistance(const std::string& a, const std::string& b) {
  // Wagner & Fischer 1974: d[i][j] = min(d[i-1][j] + 1, d[i][j-1] + 1, d[i-1][j-1] + (a_i != b_j)),
  // keeping only the previous row.
  std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), size_t(0));
  for (size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::string closestName(const std::string& name, const std::vector<std::string>& valid) {
  std::string best;
  // Case differences count less than any real edit: distance is (folded distance, exact distance).
  std::pair<size_t, size_t> bestDistance{SIZE_MAX, SIZE_MAX};
  const std::string folded = lowercase(name);
  for (const std::string& candidate : valid) {
    const std::pair<size_t, size_t> d{levenshteinDistance(folded, lowercase(candidate)),
                                      levenshteinDistance(name, candidate)};
    if (d < bestDistance) {
      bestDistance = d;
      best = candidate;
    }
  }
  return best;
}

std::string unknownNameMessage(const std::string& what, const std::string& name, const std::vector<std::string>& valid) {
  if (valid.empty()) return fmt::format("unknown {} '{}' (there are none)", what, name);
  return fmt::format("unknown {} '{}' (did you mean '{}'?)", what, name, closestName(name, valid));
}

}  // namespace lacrima
