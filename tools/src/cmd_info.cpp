// `lacrima info`: what a glTF asset or an EXR frame contains.
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "lacrima/geometry/error.hpp"
#include "lacrima/geometry/gltf_asset.hpp"

namespace lacrima::cli {

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

int describeImage(const std::string& path) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw InputError(fmt::format("{}: cannot read image: {}", path, OIIO::geterror()));
  const OIIO::ImageSpec& spec = input->spec();
  std::printf("%s\n  %d x %d, %d channels:", path.c_str(), spec.width, spec.height, spec.nchannels);
  for (int c = 0; c < spec.nchannels; ++c)
    std::printf(" %s(%s)", spec.channelnames[c].c_str(), spec.channelformat(c).c_str());
  std::printf("\n");
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
