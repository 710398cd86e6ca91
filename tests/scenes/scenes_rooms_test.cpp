// scenes/src is in rooms by loadShot's phases (README "What is where"): read -> load -> resolve ->
// frame. A room may use the rooms before it and not those after it, and what the rooms share (the
// headers at the top of scenes/src) uses none of them, so that a phase never reaches into a later
// one. The rooms share one library target and one include root, so the compiler cannot refuse an
// include that runs the wrong way: this test does.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace lacrima {
namespace scenes_rooms_test {

namespace fs = std::filesystem;

const std::vector<std::string> kRoomsInOrder = {"read", "load", "resolve", "frame"};

const fs::path kSources = fs::path(LACRIMA_SOURCE_DIR) / "scenes" / "src";

// The rooms a file includes headers of ("read" for #include "read/shot_checker.hpp"), with the line.
std::vector<std::pair<std::string, std::string>> roomIncludes(const fs::path& file) {
  static const std::regex include(R"(^\s*#\s*include\s*"([a-z_]+)/[^"]+")");
  std::vector<std::pair<std::string, std::string>> found;
  std::ifstream in(file);
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, m, include)) found.emplace_back(m[1].str(), line);
  return found;
}

int rank(const std::string& room) {
  const auto it = std::find(kRoomsInOrder.begin(), kRoomsInOrder.end(), room);
  return it == kRoomsInOrder.end() ? -1 : int(it - kRoomsInOrder.begin());
}

// The wrong-way includes of the files in `folder` (scenes/src itself when `room` is empty).
std::vector<std::string> wrongWayIncludes(const fs::path& folder, const std::string& room) {
  std::vector<std::string> wrong;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    const fs::path& file = entry.path();
    // At the top, a file that implements a shared header (asset_pose.cpp for asset_pose.hpp) is
    // shared too; the others there implement the public API over the rooms (shot_loader.cpp).
    const bool shared = room.empty() && (file.extension() == ".hpp" || fs::exists(fs::path(file).replace_extension(".hpp")));
    if (room.empty() && !shared) continue;
    for (const auto& [included, line] : roomIncludes(file))
      if (rank(included) >= 0 && (shared || rank(included) > rank(room)))
        wrong.push_back(fs::relative(file, kSources).string() + ": " + line);
  }
  return wrong;
}

TEST(ScenesRooms, EveryRoomIsInThePhaseOrder) {
  std::vector<std::string> unknown;
  for (const fs::directory_entry& entry : fs::directory_iterator(kSources))
    if (entry.is_directory() && rank(entry.path().filename().string()) < 0) unknown.push_back(entry.path().string());
  EXPECT_EQ(unknown, std::vector<std::string>{}) << "a new room of scenes/src needs its place in kRoomsInOrder";
}

TEST(ScenesRooms, ARoomUsesOnlyTheRoomsBeforeIt) {
  for (const std::string& room : kRoomsInOrder) {
    ASSERT_TRUE(fs::is_directory(kSources / room)) << room;
    EXPECT_EQ(wrongWayIncludes(kSources / room, room), std::vector<std::string>{}) << "room " << room;
  }
}

TEST(ScenesRooms, WhatTheRoomsShareUsesNoRoom) {
  EXPECT_EQ(wrongWayIncludes(kSources, ""), std::vector<std::string>{});
}

}  // namespace scenes_rooms_test
}  // namespace lacrima
