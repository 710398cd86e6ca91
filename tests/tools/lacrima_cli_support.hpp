#pragma once
// Helpers for the tests that run the real `lacrima` binary (cli, diff, export, sequence and farm
// tests): running it, a small shot with nothing to load, and comparing rendered frames byte for byte.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "support/run_command.hpp"

namespace lacrima::test {

// Built with += throughout: GCC 12 gives a false -Wrestrict for "literal" + std::string&&.
inline std::string commandLine(const std::vector<std::string>& args) {
  std::string command = shellQuote(LACRIMA_BINARY);
  for (const std::string& a : args) {
    command += ' ';
    command += shellQuote(a);
  }
  return command;
}

// Runs lacrima to completion; output is stdout and stderr interleaved.
inline CommandResult lacrima(const std::vector<std::string>& args) { return runCommand(commandLine(args)); }

// Only stdout, or only stderr: the other is redirected inside a subshell, because runCommand
// appends "2>&1" after the whole command.
inline CommandResult lacrimaStdout(const std::vector<std::string>& args) {
  std::string command = "(";
  command += commandLine(args);
  command += " 2>/dev/null)";
  return runCommand(command);
}
inline CommandResult lacrimaStderr(const std::vector<std::string>& args) {
  std::string command = "(";
  command += commandLine(args);
  command += " >/dev/null)";
  return runCommand(command);
}

// Every file below dir (recursively), relative to it.
inline std::set<std::string> filesIn(const std::filesystem::path& dir) {
  std::set<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
    if (!entry.is_directory()) files.insert(std::filesystem::relative(entry.path(), dir).string());
  return files;
}

// A shot of a water drop and a diffuse ball under a sphere light and a uniform sky (no textures,
// no meshes: nothing to load, no warnings). Frames 1-frameCount; the frame number changes the
// noise, so every frame's pixels differ.
// renderExtra: more keys of "render", e.g. R"(, "sampler": "independent")".
inline std::filesystem::path writeSphereShot(const std::filesystem::path& dir, int frameCount,
                                             const std::string& renderExtra = "") {
  const std::filesystem::path path = dir / "spheres.json";
  std::ofstream(path) << "{\n"
                      << "  \"version\": 1,\n"
                      << "  \"frames\": {\"start\": 1, \"end\": " << frameCount << ", \"fps\": 24},\n"
                      << "  \"output\": \"out/spheres.####.exr\",\n"
                      << "  \"render\": {\"width\": 32, \"height\": 18, \"spp\": 2, \"maxDepth\": 8, \"seed\": 5" << renderExtra
                      << "},\n"
                      << "  \"camera\": {\"position\": [0, 0, 3], \"lookAt\": [0, 0, 0], \"fov\": 30},\n"
                      << "  \"background\": [0.3, 0.35, 0.4],\n"
                      << "  \"materials\": {\"water\": {\"type\": \"water\", \"ior\": 1.337},\n"
                      << "                \"grey\": {\"type\": \"diffuse\", \"albedo\": [0.5, 0.5, 0.5]}},\n"
                      << "  \"lights\": [{\"type\": \"sphere\", \"center\": [1, 1.5, 2], \"radius\": 0.2, "
                         "\"power\": 40}],\n"
                      << "  \"shapes\": [{\"type\": \"sphere\", \"center\": [-0.3, 0, 0], \"radius\": 0.4, "
                         "\"material\": \"water\"},\n"
                      << "             {\"type\": \"sphere\", \"center\": [0.4, -0.1, -0.3], \"radius\": 0.35, "
                         "\"material\": \"grey\"}]\n"
                      << "}\n";
  return path;
}

inline std::string readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Zeroes the value of the header attribute `name` of type `type` in an EXR's bytes. An EXR
// attribute is "name\0type\0", a 4-byte little-endian size, then the value.
inline void zeroAttributeValue(std::string& bytes, const std::string& name, const std::string& type) {
  std::string key = name;
  key += '\0';
  key += type;
  key += '\0';
  const size_t at = bytes.find(key);
  if (at == std::string::npos || at + key.size() + 4 > bytes.size()) return;
  uint32_t size = 0;
  for (int i = 3; i >= 0; --i) size = size << 8 | uint8_t(bytes[at + key.size() + i]);
  const size_t value = at + key.size() + 4;
  std::memset(&bytes[value], 0, std::min<size_t>(size, bytes.size() - value));
}

// The file's bytes without the two values that record when and how long a frame was rendered:
// lacrima:renderSeconds, and capDate (the date and time OpenImageIO adds to every EXR it writes).
// They are all that differs between two renders of the same frame; everything else, the rest of
// the header and the compressed pixels, must then be bitwise equal.
inline std::string bytesWithoutRenderTime(const std::filesystem::path& path) {
  std::string bytes = readBytes(path);
  zeroAttributeValue(bytes, "lacrima:renderSeconds", "float");
  zeroAttributeValue(bytes, "capDate", "string");
  return bytes;
}

}  // namespace lacrima::test
