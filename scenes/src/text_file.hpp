#pragma once
// Reading a whole text file (a shot, a flood scenario) with a message for what went wrong.
#include <filesystem>
#include <optional>
#include <string>

namespace lacrima::shotfile {

// The file's bytes; nullopt with `error` set ("cannot read <what>: <reason>") when it is a
// directory, cannot be opened or fails while read.
std::optional<std::string> readTextFile(const std::filesystem::path& path, const char* what, std::string& error);

}  // namespace lacrima::shotfile
