#include "suggest.hpp"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace lacrima::shotfile {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

size_t editDistance(std::string_view a, std::string_view b) {
  // One row of the dynamic programming table at a time.
  std::vector<size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), size_t(0));
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string closestName(std::string_view name, const std::vector<std::string>& candidates) {
  const std::string lowered = lower(name);
  for (const std::string& c : candidates)
    if (lower(c) == lowered) return c;
  const size_t limit = std::max<size_t>(2, name.size() / 3);
  size_t best = limit + 1;
  std::string bestName;
  for (const std::string& c : candidates) {
    const size_t d = editDistance(lowered, lower(c));
    if (d < best) {
      best = d;
      bestName = c;
    }
  }
  return bestName;
}

std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) {
  const std::string closest = closestName(name, candidates);
  return closest.empty() ? "" : "; did you mean '" + closest + "'?";
}

}  // namespace lacrima::shotfile
