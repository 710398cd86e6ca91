#pragma once
// What `lacrima diff A B` compares: two files, two directories (images paired by file name) or
// two frame patterns such as shot.####.exr (images paired by frame number).
#include <optional>
#include <string>
#include <vector>

namespace lacrima::diff {

struct ImagePair {
  std::string label;             // the file name (directories), "frame 12" (patterns), or A's path
  std::optional<std::string> a;  // none: missing on that side
  std::optional<std::string> b;
};

// True for a path with a frame field: a run of '#' or printf's %d / %0Nd in its file name.
bool isFramePattern(const std::string& path);

// The pairs in file-name or frame order. Throws InputError when A and B are not the same kind
// (file, directory, pattern), when a file or directory does not exist, or when nothing matches.
std::vector<ImagePair> pairImages(const std::string& a, const std::string& b);

}  // namespace lacrima::diff
