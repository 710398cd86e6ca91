#pragma once
// Reading a whole text file (a shot, a flood scenario) with a message for what went wrong, and
// parsing it as JSON with positions.
#include <filesystem>
#include <optional>
#include <string>

#include "read/json_source.hpp"

namespace lacrima::shotfile {

// The file's bytes; nullopt with `error` set ("cannot read <what>: <reason>") when it is a
// directory, cannot be opened or fails while read.
std::optional<std::string> readTextFile(const std::filesystem::path& path, const char* what, std::string& error);

// A JSON file (comments allowed) parsed, with its text kept for the positions of later problems.
struct ParsedJsonFile {
  JsonSource source;
  Json json;
};
// Throws ShotError (lacrima/scenes/shot.hpp) naming the file when it cannot be read, and the line
// and column of a syntax error with an excerpt.
ParsedJsonFile readJsonFile(const std::filesystem::path& path, const char* what);

}  // namespace lacrima::shotfile
