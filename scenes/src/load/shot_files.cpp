// The loading phase: the files of a shot description opened; see shot_files.hpp.
#include "load/shot_files.hpp"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <map>

#include "lacrima/renderer/environment.hpp"

namespace lacrima::shotfile {

namespace {

// Whether the file is there; reported, with the path it resolved to when that differs.
bool checkExists(Checker& c, const FileUse& file) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(file.resolved, ec)) return true;
  const std::string what = std::filesystem::exists(file.resolved, ec) ? "not a regular file" : "file not found";
  c.error(file.pointer, Anchor::Value,
          file.written == file.resolved.string()
              ? fmt::format("{}: '{}'", what, file.written)
              : fmt::format("{}: '{}' (resolved to '{}')", what, file.written, file.resolved.string()));
  return false;
}

// A glTF file as loaded, or why it could not be: assets of the same file share it.
struct LoadedGltf {
  std::shared_ptr<const GltfAsset> gltf;
  std::string error;
};

void loadGltfAssetFile(const AssetUse& use, Shot& shot, Checker& c, const GltfAssetLoader& loadAsset,
                       std::map<std::filesystem::path, LoadedGltf>& loaded) {
  if (!use.file || !checkExists(c, *use.file)) return;
  ShotAsset& asset = shot.assets[use.asset];
  auto [it, first] = loaded.try_emplace(asset.file);
  if (first) {
    try {
      it->second.gltf = loadAsset(asset.file);
    } catch (const std::exception& e) {
      it->second.error = e.what();
    }
  }
  if (!it->second.gltf) {
    c.error(use.file->pointer, Anchor::Value, fmt::format("cannot load the glTF asset: {}", it->second.error));
    return;
  }
  asset.gltf = it->second.gltf;
  for (const std::string& w : asset.gltf->warnings)
    shot.warnings.push_back(c.warning(use.file->pointer, Anchor::Value, asset.file.string() + ": " + w));
}

void loadEnvironmentMap(const FileUse& file, Shot& shot, Checker& c) {
  if (!checkExists(c, file)) return;
  ShotEnvironment& env = *shot.environment;  // read with the file name
  try {
    env.map = std::make_shared<const EnvironmentMap>(
        EnvironmentMap::load(env.file, env.intensity, degreesToRadians(env.rotationDegrees)));
    if (const size_t clamped = env.map->clampedTexelCount())
      shot.warnings.push_back(c.warning(file.pointer, Anchor::Value,
                                        fmt::format("{}: {} texel{} NaN, infinite or negative, set to 0",
                                                    env.file.string(), clamped, clamped == 1 ? " was" : "s were")));
  } catch (const std::exception& e) {
    c.error(file.pointer, Anchor::Value, fmt::format("cannot load the environment map: {}", e.what()));
  }
}

// Opens the image header with OIIO.
void checkImageReadable(Checker& c, const FileUse& file) {
  if (!checkExists(c, file) || OIIO::ImageInput::open(file.resolved.string())) return;
  std::string reason = OIIO::geterror();
  if (const size_t newline = reason.find('\n'); newline != std::string::npos) reason.resize(newline);
  c.error(file.pointer, Anchor::Value,
          fmt::format("not a readable image: '{}'{}: {}", file.written,
                      file.written == file.resolved.string() ? "" : " (resolved to '" + file.resolved.string() + "')",
                      reason));
}

}  // namespace

void loadShotFiles(const ShotUses& uses, Shot& shot, Checker& c, const GltfAssetLoader& loadAsset) {
  if (uses.colorConfig) checkExists(c, *uses.colorConfig);
  for (const FileUse& texture : uses.textureImages) checkImageReadable(c, texture);
  std::map<std::filesystem::path, LoadedGltf> loaded;
  for (const AssetUse& asset : uses.assets) loadGltfAssetFile(asset, shot, c, loadAsset, loaded);
  if (uses.environmentMap) loadEnvironmentMap(*uses.environmentMap, shot, c);
}

}  // namespace lacrima::shotfile
