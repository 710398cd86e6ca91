#pragma once
// Parsing of --frames values: "12", "1-48", "1-48x2" (every 2nd frame) and comma lists of those.
#include <optional>
#include <string>
#include <vector>

namespace lacrima::cli {

// Returns the frames in the order given, or std::nullopt with `error` set to what is wrong.
std::optional<std::vector<int>> parseFrameList(const std::string& text, std::string& error);

}  // namespace lacrima::cli
