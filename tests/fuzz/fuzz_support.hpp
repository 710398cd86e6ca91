#pragma once
// Shared by the libFuzzer targets: every input is written to a file in a private temporary
// folder (the loaders take paths, and shots find their assets next to themselves), holding
// copies of the small seed assets (tiny.glb, track.csv, track.json) that the seed shots name.
#include <stdlib.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace lacrima::fuzz {

inline const std::filesystem::path& workDirectory();

// A fresh folder holding copies of the seed assets, private to this process (tests run side by
// side under ctest -j and gtest shards), removed at exit: under the test output folder for the
// replay test, under the temporary folder for a fuzzer run.
inline std::filesystem::path makeWorkDirectory() {
#ifdef LACRIMA_TEST_OUTPUT_DIR
  const std::filesystem::path parent = LACRIMA_TEST_OUTPUT_DIR "/fuzz";
#else
  const std::filesystem::path parent = std::filesystem::temp_directory_path();
#endif
  std::filesystem::create_directories(parent);
  std::string templ = (parent / "lacrima-fuzz-XXXXXX").string();
  if (!mkdtemp(templ.data())) {
    std::perror("lacrima fuzz: mkdtemp");
    std::abort();
  }
  const std::filesystem::path dir = templ;
  std::atexit([] {
    std::error_code ignored;
    std::filesystem::remove_all(workDirectory(), ignored);
  });
  for (const auto& entry : std::filesystem::directory_iterator(LACRIMA_SOURCE_DIR "/tests/fuzz/seed_assets"))
    std::filesystem::copy_file(entry.path(), dir / entry.path().filename());
  return dir;
}

// The folder, made on first use and kept for the whole run (never destroyed: the atexit handler
// that removes it runs after static destructors registered later).
inline const std::filesystem::path& workDirectory() {
  static const std::filesystem::path* dir = new std::filesystem::path(makeWorkDirectory());
  return *dir;
}

// Writes the input to `name` in the work folder and returns its path. `name` must not be one of
// the seed assets' names: the seed shots still need those.
inline std::filesystem::path writeInput(const uint8_t* data, size_t size, const std::string& name) {
  const std::filesystem::path path = workDirectory() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

// True when the input, after leading white space, starts with '{' (JSON rather than CSV / GLB).
inline bool looksLikeJson(const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i)
    if (data[i] != ' ' && data[i] != '\t' && data[i] != '\n' && data[i] != '\r') return data[i] == '{';
  return false;
}

}  // namespace lacrima::fuzz
