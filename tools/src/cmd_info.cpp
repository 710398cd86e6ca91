// `lacrima info`: what a glTF asset or an EXR frame contains.
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "commands.hpp"
#include "frame_selection.hpp"
#include "lacrima/base/error.hpp"
#include "lacrima/io/gltf_asset.hpp"

namespace lacrima::cli {

namespace {

// The channels grouped by layer, in file order: the part of a name before its last '.' ("" for
// the beauty's R, G, B, A and bare channels such as Z), each with its channels' suffixes.
struct ChannelLayer {
  std::string name;
  std::vector<std::string> channels;
  std::string format;  // the channels' format, or "mixed"
};

std::vector<ChannelLayer> channelLayers(const OIIO::ImageSpec& spec) {
  std::vector<ChannelLayer> layers;
  for (int c = 0; c < spec.nchannels; ++c) {
    const std::string& full = spec.channelnames[c];
    const size_t dot = full.rfind('.');
    const bool bare = dot == std::string::npos;
    // A bare channel other than R, G, B, A is a layer of its own (Z, samples).
    const bool beauty = bare && (full == "R" || full == "G" || full == "B" || full == "A");
    const std::string layer = bare ? (beauty ? "" : full) : full.substr(0, dot);
    const std::string channel = bare ? (beauty ? full : "") : full.substr(dot + 1);
    const std::string format = spec.channelformat(c).c_str();
    auto it = std::find_if(layers.begin(), layers.end(), [&](const ChannelLayer& l) { return l.name == layer; });
    if (it == layers.end()) it = layers.insert(layers.end(), ChannelLayer{layer, {}, format});
    if (!channel.empty()) it->channels.push_back(channel);
    if (it->format != format) it->format = "mixed";
  }
  return layers;
}

// Each Cryptomatte type of the header: its name, key, hash, conversion and manifest.
void printCryptomattes(const OIIO::ImageSpec& spec) {
  std::map<std::string, std::map<std::string, std::string>> types;  // key -> field -> value
  for (const auto& attribute : spec.extra_attribs) {
    const std::string name = attribute.name().string();
    if (name.rfind("cryptomatte/", 0) != 0) continue;
    const size_t slash = name.find('/', 12);
    if (slash == std::string::npos) continue;
    types[name.substr(12, slash - 12)][name.substr(slash + 1)] = attribute.get_string(0);
  }
  for (auto& [key, fields] : types) {
    nlohmann::ordered_json manifest = nlohmann::ordered_json::object();
    if (fields.count("manifest")) manifest = nlohmann::ordered_json::parse(fields["manifest"], nullptr, false);
    std::printf("  Cryptomatte %s (key %s, %s, %s): %zu names in the manifest\n", fields["name"].c_str(), key.c_str(),
                fields["hash"].c_str(), fields["conversion"].c_str(), manifest.is_object() ? manifest.size() : 0);
    if (manifest.is_object())
      for (const auto& [name, id] : manifest.items())
        std::printf("    %-40s %s\n", name.c_str(), id.is_string() ? id.get<std::string>().c_str() : "?");
  }
}

int describeImage(const std::string& path) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw InputError(fmt::format("{}: cannot read image: {}", path, OIIO::geterror()));
  const OIIO::ImageSpec& spec = input->spec();
  const std::vector<ChannelLayer> layers = channelLayers(spec);
  std::printf("%s\n  %d x %d, %d channels in %zu layers:\n", path.c_str(), spec.width, spec.height, spec.nchannels,
              layers.size());
  if (spec.x != spec.full_x || spec.y != spec.full_y || spec.width != spec.full_width ||
      spec.height != spec.full_height)
    std::printf("  a region of the %d x %d frame: its pixels from (%d, %d)\n", spec.full_width, spec.full_height,
                spec.x - spec.full_x, spec.y - spec.full_y);
  int nameWidth = 20;  // the longest layer name's, so the channels line up
  for (const ChannelLayer& layer : layers) nameWidth = std::max(nameWidth, int(layer.name.size()));
  for (const ChannelLayer& layer : layers) {
    std::string channels;
    for (const std::string& c : layer.channels) channels += (channels.empty() ? "" : " ") + c;
    std::printf("    %-*s %s%s(%s)\n", nameWidth, layer.name.empty() ? "(beauty)" : layer.name.c_str(), channels.c_str(),
                channels.empty() ? "" : " ", layer.format.c_str());
  }
  printCryptomattes(spec);
  for (const auto& attribute : spec.extra_attribs) {
    const std::string name = attribute.name().string();
    if (name.rfind("lacrima:", 0) == 0 || name == "worldToCamera" || name == "worldToNDC" || name == "compression")
      std::printf("  %s = %s\n", name.c_str(), attribute.get_string(16).c_str());
  }
  input->close();
  return kExitOk;
}

}  // namespace

int runInfo(const std::string& path) {
  try {
    if (!std::filesystem::exists(path)) throw InputError(fmt::format("{}: no such file", path));
    const std::string ext = lowerExtension(path);
    if (ext == ".glb" || ext == ".gltf") {
      std::printf("%s", describeGltfAsset(loadGltfAsset(path)).c_str());
      return kExitOk;
    }
    if (ext == ".exr" || ext == ".hdr" || ext == ".png") return describeImage(path);
    throw InputError(fmt::format("{}: unknown file type '{}' (expected .glb, .gltf, .exr, .hdr or .png)", path, ext));
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace lacrima::cli
