#pragma once
// Where lacrima files what it can rebuild (flesh volumes and states, bench references): the
// XDG base directory specification's cache folder.
#include <cstdlib>
#include <filesystem>
#include <string>

namespace lacrima {

// $XDG_CACHE_HOME/lacrima/<subfolder>, else ~/.cache/lacrima/<subfolder>; empty when neither
// variable is set.
inline std::filesystem::path userCacheDirectory(const std::string& subfolder) {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "lacrima" / subfolder;
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache/lacrima" / subfolder;
  return {};
}

}  // namespace lacrima
