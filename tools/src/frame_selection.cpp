#include "frame_selection.hpp"

#include <fmt/format.h>

#include <cctype>
#include <filesystem>

#include "frame_range.hpp"
#include "lacrima/scenes/shot.hpp"

namespace lacrima::cli {

std::vector<int> selectShotFrames(const std::optional<std::string>& frames, const Shot& shot) {
  if (!frames) {
    std::vector<int> all;
    for (int f = shot.frameStart; f <= shot.frameEnd; ++f) all.push_back(f);
    return all;
  }
  const std::string shown = frames->empty() ? "''" : *frames;
  std::string error;
  auto parsed = parseFrameList(*frames, error);
  if (!parsed) throw InputError("--frames " + shown + ": " + error);
  for (int f : *parsed)
    if (f < shot.frameStart || f > shot.frameEnd)
      throw InputError(fmt::format("--frames {}: frame {} is outside the frame range {}-{} of {}", shown, f,
                                   shot.frameStart, shot.frameEnd, shot.path.string()));
  return *parsed;
}

void requireFrameField(const std::string& pattern, size_t frameCount, const std::string& verb) {
  // The same expansion the frames get: a frame field names different files for different frames.
  const bool hasFrameField = expandFramePattern(pattern, 1) != expandFramePattern(pattern, 2);
  if (frameCount > 1 && !hasFrameField)
    throw InputError(fmt::format("output '{}' has no #### frame field but {} frames are to be {}: every frame "
                                 "would overwrite the last",
                                 pattern, frameCount, verb));
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace lacrima::cli
