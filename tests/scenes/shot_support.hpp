#pragma once
// Helpers shared by the shot-file tests.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <fstream>
#include <string>
#include <vector>

#include "lacrima/scenes/shot.hpp"
#include "support/test_directory.hpp"

namespace lacrima::test {

inline std::filesystem::path sourcePath(const std::string& relative) {
  return std::filesystem::path(LACRIMA_SOURCE_DIR) / relative;
}

// Writes a shot file under the test's own output directory and returns its path.
inline std::filesystem::path writeShot(const std::string& name, const std::string& text) {
  const std::filesystem::path dir = testDirectory("shots");
  const std::filesystem::path path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A minimal shot of one frame whose "render" object ends with renderExtra (e.g. `, "sampler":
// "sobol"`): for the tests of the render settings' keys.
inline std::string shotWithRender(const std::string& renderExtra) {
  return "{\n  \"version\": 1,\n  \"frames\": {\"start\": 1, \"end\": 1, \"fps\": 24},\n"
         "  \"output\": \"out.####.exr\",\n  \"render\": {\"width\": 8, \"height\": 8, \"spp\": 1" + renderExtra + "},\n"
         "  \"camera\": {\"position\": [0, 0, 3], \"lookAt\": [0, 0, 0], \"fov\": 30}\n}\n";
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

// The repository's ICT face asset.
inline const std::string kIctFace = LACRIMA_SOURCE_DIR "/scenes/assets/ict-face/ict_face.glb";

// A shot of the ICT face: frames 1..lastFrame at 24 fps, a 16x8 1-spp render, materials "skin"
// and "water", M_Face bound to skin. `extra` adds top-level members, `cameraExtra` members of
// the camera (after its fov), `asset` members of the face asset.
inline std::string ictFaceShot(const std::string& extra, const std::string& cameraExtra = "",
                               const std::string& asset = "", int lastFrame = 5) {
  return "{\n  \"version\": 1,\n  \"frames\": {\"start\": 1, \"end\": " + std::to_string(lastFrame) +
         ", \"fps\": 24},\n  \"output\": \"out.####.exr\",\n  \"render\": {\"width\": 16, \"height\": 8, \"spp\": 1},\n"
         "  \"camera\": {\"position\": [0, 0, 0.5], \"lookAt\": [0, 0, 0], \"fov\": 30" + cameraExtra + "},\n"
         "  \"materials\": {\"skin\": {\"type\": \"skin\"}, \"water\": {\"type\": \"water\"}},\n"
         "  \"assets\": [{\"name\": \"face\", \"file\": \"" + kIctFace + "\", \"materials\": {\"M_Face\": \"skin\"}" +
         (asset.empty() ? "" : ", " + asset) + "}]" + (extra.empty() ? "" : ",\n  " + extra) + "\n}\n";
}

// `text` with its first `from` replaced by `to` (a test failure when `from` is not in it).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the text";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

inline std::string firstLineOf(const std::string& s) { return s.substr(0, s.find('\n')); }

// A shot that must fail with exactly one problem; `pointerAndMessage` is its JSON pointer and
// the first line of its message ("/assets/0/joints/x: unknown joint channel ...").
inline void expectSingleError(const std::string& name, const std::string& text, const std::string& pointerAndMessage) {
  const auto path = writeShot(name, text);
  std::vector<Diagnostic> diagnostics;
  shotErrorOf(path, &diagnostics);
  ASSERT_EQ(diagnostics.size(), 1u) << shotErrorOf(path);
  EXPECT_EQ(diagnostics[0].jsonPath + ": " + firstLineOf(diagnostics[0].message), pointerAndMessage);
}

// Points $XDG_CACHE_HOME (where flesh volumes and flesh and SPH states are filed) at a folder of
// the test's own for its lifetime.
class ScopedCacheHome {
 public:
  explicit ScopedCacheHome(const std::filesystem::path& dir) {
    if (const char* old = std::getenv("XDG_CACHE_HOME")) old_ = old;
    setenv("XDG_CACHE_HOME", dir.c_str(), 1);
  }
  ~ScopedCacheHome() {
    if (old_) setenv("XDG_CACHE_HOME", old_->c_str(), 1);
    else unsetenv("XDG_CACHE_HOME");
  }
  ScopedCacheHome(const ScopedCacheHome&) = delete;
  ScopedCacheHome& operator=(const ScopedCacheHome&) = delete;

 private:
  std::optional<std::string> old_;
};

// The frame's mesh of that name (e.g. "face/ICTFace/M_Face"), or null.
inline const MeshInstance* findMesh(const Frame& frame, const std::string& name) {
  for (const MeshInstance& m : frame.meshes)
    if (m.mesh.name == name) return &m;
  return nullptr;
}

}  // namespace lacrima::test
