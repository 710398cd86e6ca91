#pragma once
// Per-test output directories: ctest runs every test as its own process, in parallel, so tests
// must never share file names.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace lacrima::test {

// "Suite.Test" of the running test ('/' of parameterised names replaced), or "no_test".
inline std::string currentTestName() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  if (!info) return "no_test";
  std::string name = std::string(info->test_suite_name()) + "." + info->name();
  for (char& c : name)
    if (c == '/') c = '_';
  return name;
}

// LACRIMA_TEST_OUTPUT_DIR/<group>/<test>, created if missing; emptied first when `fresh`.
inline std::filesystem::path testDirectory(const std::string& group, bool fresh = false) {
  const std::filesystem::path dir = std::filesystem::path(LACRIMA_TEST_OUTPUT_DIR) / group / currentTestName();
  if (fresh) std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace lacrima::test
