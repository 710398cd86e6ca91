#pragma once
// Files written atomically: to "<path>.tmp-<pid>" next to the final file, then renamed over it
// (rename(2) is atomic within one filesystem), so an interrupted or failed write never leaves a
// half file under the final name. The same scheme as the renderer's EXR writer.
#include <filesystem>
#include <functional>
#include <ostream>

namespace lacrima::cli {

// Creates the parent directories, lets `write` fill the temporary file and renames it into place.
// Throws InputError "cannot write <what> '<path>': <reason>" when a directory cannot be created,
// the file cannot be opened or written, or the rename fails; the temporary file is removed then
// (and when `write` throws).
void writeFileAtomically(const std::filesystem::path& path, const char* what,
                         const std::function<void(std::ostream&)>& write);

}  // namespace lacrima::cli
