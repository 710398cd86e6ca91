#pragma once
// Helpers shared by the shot-file tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lacrima/scenes/shot.hpp"

namespace lacrima::test {

inline std::filesystem::path sourcePath(const std::string& relative) {
  return std::filesystem::path(LACRIMA_SOURCE_DIR) / relative;
}

// Writes a shot file under the test's own output directory (ctest runs tests as parallel
// processes; a shared directory would let them overwrite each other's files) and returns its path.
inline std::filesystem::path writeShot(const std::string& name, const std::string& text) {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string testName = info ? std::string(info->test_suite_name()) + "." + info->name() : "no_test";
  const std::filesystem::path dir = std::filesystem::path(LACRIMA_TEST_OUTPUT_DIR) / "shots" / testName;
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

inline std::string joinLines(const std::vector<std::string>& lines) {
  std::string out;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (i > 0) out += '\n';
    out += lines[i];
  }
  return out;
}

// Loads a shot that must fail; returns the ShotError's message ("" and a test failure otherwise).
inline std::string shotErrorOf(const std::filesystem::path& path, std::vector<Diagnostic>* diagnostics = nullptr) {
  try {
    loadShot(path);
  } catch (const ShotError& e) {
    if (diagnostics) *diagnostics = e.diagnostics();
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << path << ": expected a ShotError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << path << ": loaded without error";
  return "";
}

}  // namespace lacrima::test
