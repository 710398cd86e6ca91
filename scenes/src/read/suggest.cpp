// Shot-file suggestions on top of the geometry library's edit distance and closest name, and lists of names.
#include "read/suggest.hpp"

#include <algorithm>
#include <cctype>

#include "lacrima/base/name_suggestion.hpp"

namespace lacrima::shotfile {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::string closestName(std::string_view name, const std::vector<std::string>& candidates) {
  const std::string closest = lacrima::closestName(std::string(name), candidates);
  if (closest.empty()) return "";
  // A suggestion far from what was written would mislead more than help.
  const size_t limit = std::max<size_t>(2, name.size() / 3);
  return levenshteinDistance(lower(name), lower(closest)) <= limit ? closest : "";
}

std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) {
  const std::string closest = closestName(name, candidates);
  return closest.empty() ? "" : "; did you mean '" + closest + "'?";
}

std::string join(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += separator;
    out += items[i];
  }
  return out;
}

std::string quotedList(const std::vector<std::string>& items) {
  std::vector<std::string> quoted;
  for (const std::string& s : items) quoted.push_back("'" + s + "'");
  return join(quoted, ", ");
}

std::string suggestionOrList(const std::string& name, const std::vector<std::string>& candidates,
                             const std::string& listName, const std::string& emptyText) {
  if (candidates.empty()) return " (" + emptyText + ")";
  const std::string suggestion = didYouMean(name, candidates);
  if (!suggestion.empty()) return suggestion;
  if (candidates.size() > 12) return "";
  return " (" + listName + ": " + quotedList(candidates) + ")";
}

}  // namespace lacrima::shotfile
