// Output path patterns: "renders/tear.####.exr" -> "renders/tear.0007.exr".
#include "frame_pattern.hpp"

#include <fmt/format.h>

#include <cctype>

#include "lacrima/scenes/shot.hpp"

namespace lacrima {

namespace {

// A printf-style frame field at pattern[i] == '%': "%d" or "%0<digits>d". Returns its length
// (0 when there is none) and its width.
size_t printfField(const std::string& pattern, size_t i, int& width) {
  size_t j = i + 1;
  width = 0;
  if (j < pattern.size() && pattern[j] == '0') {
    ++j;
    const size_t digitsStart = j;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j;
    if (j == digitsStart || j - digitsStart > 2) return 0;
    width = std::stoi(pattern.substr(digitsStart, j - digitsStart));
  }
  if (j < pattern.size() && pattern[j] == 'd') return j + 1 - i;
  return 0;
}

}  // namespace

std::string expandFramePattern(const std::string& pattern, int frameNumber) {
  std::string out;
  for (size_t i = 0; i < pattern.size();) {
    if (pattern[i] == '#') {
      size_t run = 0;
      while (i + run < pattern.size() && pattern[i + run] == '#') ++run;
      out += fmt::format("{:0{}d}", frameNumber, run);  // wider numbers are not truncated
      i += run;
      continue;
    }
    int width = 0;
    if (pattern[i] == '%') {
      if (const size_t length = printfField(pattern, i, width)) {
        out += fmt::format("{:0{}d}", frameNumber, width);
        i += length;
        continue;
      }
    }
    out += pattern[i++];
  }
  return out;
}

namespace shotfile {

bool hasFrameField(const std::string& pattern) {
  for (size_t i = 0; i < pattern.size(); ++i) {
    int width = 0;
    if (pattern[i] == '#' || (pattern[i] == '%' && printfField(pattern, i, width) > 0)) return true;
  }
  return false;
}

}  // namespace shotfile
}  // namespace lacrima
