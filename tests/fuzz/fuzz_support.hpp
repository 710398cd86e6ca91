#pragma once
// Shared by the libFuzzer targets: every input is written to a file in a private temporary
// folder (the loaders take paths, and shots find their assets next to themselves), holding
// copies of the small seed assets (tiny.glb, track.csv, track.json) that the seed shots name,
// placed so that the regression shots' paths to scenes/assets resolve too.
#include <stdlib.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace lacrima::fuzz {

// A private folder (tests run side by side under ctest -j and gtest shards), removed at exit:
// under the test output folder for the replay test, under the temporary folder for a fuzzer run.
// The inputs go three levels down, in <root>/tests/data/regression, with copies of the seed
// assets, and <root>/scenes links to the source tree's scenes/: the regression shots among the
// shot seeds name their assets as ../../../scenes/assets/..., so they load the ICT face wherever
// the temporary folder is (before, only when it happened to sit two levels below the source tree,
// as build-hardening/fuzz-tmp does on CI; elsewhere they only fuzzed the missing-file error).
struct WorkFolders {
  std::filesystem::path root, inputs;
};

inline const WorkFolders& workFolders();

inline WorkFolders makeWorkFolders() {
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
  const WorkFolders folders{templ, std::filesystem::path(templ) / "tests/data/regression"};
  std::atexit([] {
    std::error_code ignored;
    std::filesystem::remove_all(workFolders().root, ignored);  // removes the link, not the scenes
  });
  std::filesystem::create_directories(folders.inputs);
  std::filesystem::create_directory_symlink(LACRIMA_SOURCE_DIR "/scenes", folders.root / "scenes");
  for (const auto& entry : std::filesystem::directory_iterator(LACRIMA_SOURCE_DIR "/tests/fuzz/seed_assets"))
    std::filesystem::copy_file(entry.path(), folders.inputs / entry.path().filename());
  return folders;
}

// Made on first use and kept for the whole run (never destroyed: the atexit handler that removes
// it runs after static destructors registered later).
inline const WorkFolders& workFolders() {
  static const WorkFolders* folders = new WorkFolders(makeWorkFolders());
  return *folders;
}

// The folder the inputs are written to, next to the seed assets.
inline const std::filesystem::path& workDirectory() { return workFolders().inputs; }

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
