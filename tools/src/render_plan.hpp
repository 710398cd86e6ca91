#pragma once
// What `lacrima render` with some options would write: the settings of each frame (the shot's,
// with the command line's overrides), where each frame goes, and whether it is already on disk,
// complete. Shared by `render` (--resume) and `farm` (which submits only the missing frames and
// reports progress from the outputs).
#include <filesystem>
#include <string>

#include "commands.hpp"
#include "lacrima/renderer/frame.hpp"

namespace lacrima {
struct Shot;
}

namespace lacrima::cli {

// The overrides of `o` (--spp, --width, --region ...), applied once to a loaded shot's render
// settings (shot.render) before any of its frames is built or checked on disk: every frame then
// reads them there (renderSettingsAt). Throws InputError for a --region outside the frame.
void applyOverrides(const RenderOptions& o, RenderSettings& s);

// The output pattern (--out, else the shot's), checked: it has a frame field when frameCount > 1
// and names .exr files. Throws InputError otherwise.
std::string resolveOutputPattern(const RenderOptions& o, const Shot& shot, size_t frameCount);

// The PNG preview written next to an EXR (--preview).
std::filesystem::path previewPathFor(const std::filesystem::path& exrPath);

// Empty when frame `frameNumber` is on disk under `pattern`, complete and rendered with the
// settings of this run (the shot's, with the overrides of `o` applied by applyOverrides; and its
// preview is there when o.preview); else why it must be rendered ("missing" when there is no file).
std::string whyFrameIsNotComplete(const RenderOptions& o, const Shot& shot, const std::string& pattern,
                                  int frameNumber);

}  // namespace lacrima::cli
