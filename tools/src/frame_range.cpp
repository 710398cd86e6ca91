#include "frame_range.hpp"

#include <charconv>
#include <sstream>

namespace lacrima::cli {

namespace {

bool parseInt(const std::string& text, int& value) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end;
}

// One item: "N", "A-B" or "A-BxS". Negative frame numbers are written "-5" only as a single item.
bool parseItem(const std::string& item, std::vector<int>& frames, std::string& error) {
  int single;
  if (parseInt(item, single)) {
    frames.push_back(single);
    return true;
  }
  std::string range = item;
  int step = 1;
  if (const size_t x = range.find('x'); x != std::string::npos) {
    if (!parseInt(range.substr(x + 1), step) || step < 1) {
      error = "step after 'x' in '" + item + "' must be a whole number >= 1";
      return false;
    }
    range = range.substr(0, x);
  }
  const size_t dash = range.find('-', 1);
  int first, last;
  if (dash == std::string::npos || !parseInt(range.substr(0, dash), first) || !parseInt(range.substr(dash + 1), last)) {
    error = "'" + item + "' is not a frame number or a range like 1-48 or 1-48x2";
    return false;
  }
  if (last < first) {
    error = "range '" + item + "' ends before it starts";
    return false;
  }
  for (int f = first; f <= last; f += step) frames.push_back(f);
  return true;
}

}  // namespace

std::optional<std::vector<int>> parseFrameList(const std::string& text, std::string& error) {
  std::vector<int> frames;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (!parseItem(item, frames, error)) return std::nullopt;
  }
  if (frames.empty()) {
    error = "no frames given";
    return std::nullopt;
  }
  return frames;
}

}  // namespace lacrima::cli
