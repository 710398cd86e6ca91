// Pairing of the images of `lacrima diff`; see image_pairs.hpp.
#include "diff/image_pairs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>

#include "lacrima/base/error.hpp"

namespace lacrima::diff {

namespace {

namespace fs = std::filesystem;

const std::regex kFrameField(R"(#+|%0?\d*d)");

bool isImageFile(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".exr" || ext == ".png" || ext == ".hdr" || ext == ".tif" || ext == ".tiff" || ext == ".jpg";
}

enum class Kind { File, Directory, Pattern };

Kind kindOf(const std::string& path) {
  if (isFramePattern(path)) return Kind::Pattern;
  std::error_code ec;
  if (fs::is_directory(path, ec)) return Kind::Directory;
  if (!fs::exists(path, ec)) throw InputError(fmt::format("{}: no such file or directory", path));
  return Kind::File;
}

const char* kindName(Kind k) { return k == Kind::File ? "a file" : k == Kind::Directory ? "a directory" : "a frame pattern"; }

std::map<std::string, std::string> imagesIn(const std::string& directory) {
  std::map<std::string, std::string> byName;
  for (const fs::directory_entry& e : fs::directory_iterator(directory))
    if (e.is_regular_file() && isImageFile(e.path())) byName[e.path().filename().string()] = e.path().string();
  return byName;
}

std::string regexEscaped(const std::string& text) {
  static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
  return std::regex_replace(text, special, R"(\$&)");
}

// Frame number -> file for the files matching the pattern's file name in its directory.
std::map<int, std::string> framesOf(const std::string& pattern) {
  const fs::path p(pattern);
  const fs::path directory = p.has_parent_path() ? p.parent_path() : fs::path(".");
  const std::string name = p.filename().string();
  std::smatch field;
  if (!std::regex_search(name, field, kFrameField))
    throw InputError(fmt::format("{}: the frame field must be in the file name", pattern));
  const std::regex matcher(regexEscaped(field.prefix().str()) + R"((-?\d+))" + regexEscaped(field.suffix().str()));
  std::map<int, std::string> frames;
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) throw InputError(fmt::format("{}: no such directory", directory.string()));
  for (const fs::directory_entry& e : fs::directory_iterator(directory)) {
    const std::string file = e.path().filename().string();
    std::smatch m;
    if (e.is_regular_file() && std::regex_match(file, m, matcher)) frames[std::stoi(m[1].str())] = e.path().string();
  }
  return frames;
}

template <typename Key>
std::vector<ImagePair> merged(const std::map<Key, std::string>& a, const std::map<Key, std::string>& b,
                              std::string (*label)(const Key&)) {
  std::map<Key, ImagePair> pairs;
  for (const auto& [key, path] : a) pairs[key].a = path;
  for (const auto& [key, path] : b) pairs[key].b = path;
  std::vector<ImagePair> out;
  for (auto& [key, pair] : pairs) {
    pair.label = label(key);
    out.push_back(pair);
  }
  return out;
}

std::string nameLabel(const std::string& name) { return name; }
std::string frameLabel(const int& frame) { return fmt::format("frame {}", frame); }

}  // namespace

bool isFramePattern(const std::string& path) {
  return std::regex_search(fs::path(path).filename().string(), kFrameField);
}

std::vector<ImagePair> pairImages(const std::string& a, const std::string& b) {
  const Kind kindA = kindOf(a), kindB = kindOf(b);
  if (kindA != kindB)
    throw InputError(fmt::format("{} is {} but {} is {}: compare two files, two directories or two frame patterns", a,
                                 kindName(kindA), b, kindName(kindB)));
  std::vector<ImagePair> pairs;
  if (kindA == Kind::File) pairs.push_back(ImagePair{a, a, b});
  else if (kindA == Kind::Directory) pairs = merged<std::string>(imagesIn(a), imagesIn(b), nameLabel);
  else pairs = merged<int>(framesOf(a), framesOf(b), frameLabel);
  if (pairs.empty()) throw InputError(fmt::format("no images in {} or {}", a, b));
  return pairs;
}

}  // namespace lacrima::diff
