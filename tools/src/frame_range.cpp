#include "frame_range.hpp"

#include <charconv>
#include <string>

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
  if (text.empty()) {
    error = "no frames given";
    return std::nullopt;
  }
  std::vector<int> frames;
  // Split on every comma, so that "1,", ",1" and "1,,2" are reported rather than read as "1" and "1,2".
  for (size_t begin = 0;;) {
    const size_t comma = text.find(',', begin);
    const std::string item = text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
    if (item.empty()) {
      error = "empty item in the list (a comma at the start or end, or two in a row)";
      return std::nullopt;
    }
    if (!parseItem(item, frames, error)) return std::nullopt;
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  return frames;
}

std::string formatFrameList(const std::vector<int>& frames) {
  if (frames.empty()) return "none";
  std::string text;
  for (size_t begin = 0; begin < frames.size();) {
    size_t end = begin + 1;  // one past the run of consecutive frames starting at `begin`
    while (end < frames.size() && frames[end] == frames[end - 1] + 1) ++end;
    if (!text.empty()) text += ',';
    text += std::to_string(frames[begin]);
    if (end - begin > 1) {
      text += '-';
      text += std::to_string(frames[end - 1]);
    }
    begin = end;
  }
  return text;
}

}  // namespace lacrima::cli
