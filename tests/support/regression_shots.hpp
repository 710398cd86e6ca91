#pragma once
// The image-regression shots (tests/data/regression/*.json, thresholds.json aside), by name, for the
// tests that go over all of them.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace lacrima::test {

inline const std::filesystem::path& regressionDir() {
  static const std::filesystem::path dir = std::filesystem::path(LACRIMA_SOURCE_DIR) / "tests/data/regression";
  return dir;
}

inline std::vector<std::string> regressionShots() {
  std::vector<std::string> names;
  for (const std::filesystem::directory_entry& e : std::filesystem::directory_iterator(regressionDir()))
    if (e.path().extension() == ".json" && e.path().filename() != "thresholds.json")
      names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace lacrima::test
