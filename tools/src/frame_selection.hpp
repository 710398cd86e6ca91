#pragma once
// Which frames of a shot a command works on (--frames) and where they go (--out), shared by
// `lacrima render` and `lacrima export` so both accept and refuse the same things, in the same words.
#include <optional>
#include <string>
#include <vector>

namespace lacrima {
struct Shot;
}

namespace lacrima::cli {

// The frames of --frames (the shot's whole range when absent), in the order given. Throws
// InputError "--frames TEXT: ..." for a malformed list or a frame outside the shot's range.
std::vector<int> selectShotFrames(const std::optional<std::string>& frames, const Shot& shot);

// Throws InputError when `pattern` has no frame field ('#' run, %d, %04d) but several frames are
// to be written: every frame would overwrite the last. `verb` says what happens to them ("rendered").
void requireFrameField(const std::string& pattern, size_t frameCount, const std::string& verb);

// The extension of the path, lower case, with its dot (".exr"); "" when none.
std::string lowerExtension(const std::string& path);

}  // namespace lacrima::cli
