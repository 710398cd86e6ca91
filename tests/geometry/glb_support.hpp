#pragma once
// Helpers for glTF tests: reading and writing GLB containers independently of the loader
// (nlohmann::json for the JSON chunk), and the committed face asset's path.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/test_directory.hpp"

namespace lacrima::test {

inline std::filesystem::path faceAssetPath() { return LACRIMA_SOURCE_DIR "/scenes/assets/ict-face/ict_face.glb"; }

// The running test's own output directory (see support/test_directory.hpp).
inline std::filesystem::path testOutputDir() { return testDirectory("geometry"); }

inline std::vector<unsigned char> readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("test: cannot read " + path.string());
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

inline void writeBytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  if (!out) throw std::runtime_error("test: cannot write " + path.string());
}

inline uint32_t u32At(const std::vector<unsigned char>& b, size_t offset) {
  uint32_t v;
  std::memcpy(&v, &b[offset], 4);
  return v;
}

// The two chunks of a GLB, parsed by hand.
struct GlbParts {
  nlohmann::json json;
  std::vector<unsigned char> bin;
};

inline GlbParts splitGlb(const std::vector<unsigned char>& bytes) {
  const uint32_t jsonLength = u32At(bytes, 12);
  GlbParts parts;
  parts.json = nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLength);
  const size_t binStart = 20 + size_t(jsonLength);
  if (binStart + 8 <= bytes.size()) {
    const uint32_t binLength = u32At(bytes, binStart);
    parts.bin.assign(bytes.begin() + long(binStart + 8), bytes.begin() + long(binStart + 8 + binLength));
  }
  return parts;
}

inline void appendU32(std::vector<unsigned char>& out, uint32_t v) {
  const auto* p = reinterpret_cast<const unsigned char*>(&v);
  out.insert(out.end(), p, p + 4);
}

// A GLB (version 2) from a JSON document and a BIN chunk, both padded to 4 bytes as required.
inline std::vector<unsigned char> makeGlb(const nlohmann::json& json, std::vector<unsigned char> bin) {
  std::string text = json.dump();
  while (text.size() % 4 != 0) text += ' ';
  while (bin.size() % 4 != 0) bin.push_back(0);
  std::vector<unsigned char> out;
  const uint32_t total = uint32_t(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size()));
  out.insert(out.end(), {'g', 'l', 'T', 'F'});
  appendU32(out, 2);
  appendU32(out, total);
  appendU32(out, uint32_t(text.size()));
  appendU32(out, 0x4E4F534Au);  // "JSON"
  out.insert(out.end(), text.begin(), text.end());
  if (!bin.empty()) {
    appendU32(out, uint32_t(bin.size()));
    appendU32(out, 0x004E4942u);  // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
  }
  return out;
}

// Appends raw values to a BIN chunk (4-byte aligned) and returns their byte offset.
template <class T>
size_t appendValues(std::vector<unsigned char>& bin, const std::vector<T>& values) {
  while (bin.size() % 4 != 0) bin.push_back(0);
  const size_t offset = bin.size();
  const auto* p = reinterpret_cast<const unsigned char*>(values.data());
  bin.insert(bin.end(), p, p + values.size() * sizeof(T));
  return offset;
}

}  // namespace lacrima::test
