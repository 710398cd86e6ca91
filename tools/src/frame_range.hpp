#pragma once
// Parsing of --frames values: "12", "1-48", "1-48x2" (every 2nd frame) and comma lists of those.
#include <optional>
#include <string>
#include <vector>

namespace lacrima::cli {

// Returns the frames in the order given, or std::nullopt with `error` set to what is wrong.
std::optional<std::vector<int>> parseFrameList(const std::string& text, std::string& error);

// The inverse, for messages: runs of consecutive frames as ranges, "1-3,5,7-8"; "none" when empty.
std::string formatFrameList(const std::vector<int>& frames);

}  // namespace lacrima::cli
