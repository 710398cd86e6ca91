// loadShot: a shot file (docs/shot-format.md) in phases, each in its room of scenes/src:
//   1. parse (read/json_source.hpp): the JSON text (duplicate keys reported), with the --performance
//      takes played on their assets (the JSON rewritten: their own animation members give way to a
//      "performance");
//   2. read (read/shot_reader.hpp): every section read and checked into a Shot, opening no file; the
//      files it names and the names it uses inside them are recorded (read/shot_uses.hpp);
//   3. load (load/shot_files.hpp): those files opened once;
//   4. bind (load/shot_binding.hpp): the names used inside them checked, and what follows from them
//      derived (blendshape weights, primitive materials, the rig and animation, the camera);
//   5. resolve (resolve/shot_resolve.hpp): what the shot places on its assets' surfaces found on the
//      posed assets.
// Phases 2-4 report every problem at its JSON pointer and text position (diagnostics are sorted by
// position), and a shot with any of them stops before phase 5; phase 5's problems are reported together.
#include <fmt/format.h>

#include "lacrima/scenes/shot.hpp"
#include "load/shot_binding.hpp"
#include "load/shot_files.hpp"
#include "read/json_source.hpp"
#include "read/shot_checker.hpp"
#include "read/shot_reader.hpp"
#include "resolve/shot_resolve.hpp"
#include "read/suggest.hpp"
#include "read/text_file.hpp"

namespace lacrima {

namespace {

namespace fs = std::filesystem;
using shotfile::Anchor;
using shotfile::Checker;
using shotfile::Json;

std::shared_ptr<const GltfAsset> loadGltfAssetFile(const fs::path& file) {
  return std::make_shared<const GltfAsset>(loadGltfAsset(file));
}

// The asset's name as the shot reader gives it: "name", else the file's stem.
std::string writtenAssetName(const Json& asset) {
  if (const auto name = asset.find("name"); name != asset.end() && name->is_string()) return name->get<std::string>();
  if (const auto file = asset.find("file"); file != asset.end() && file->is_string())
    return fs::path(file->get<std::string>()).stem().string();
  return "";
}

// Plays each take on its asset: the asset's own animation members give way to a "performance".
void applyPerformanceOverrides(Json& root, const std::vector<PerformanceOverride>& performances, Checker& checker) {
  for (const PerformanceOverride& take : performances) {
    std::vector<std::string> names;
    Json* target = nullptr;
    if (root.is_object() && root.contains("assets") && root["assets"].is_array())
      for (Json& asset : root["assets"]) {
        if (!asset.is_object()) continue;
        names.push_back(writtenAssetName(asset));
        if (names.back() == take.asset && !target) target = &asset;
      }
    if (!target) {
      checker.error("/assets", Anchor::Key,
                    fmt::format("no asset named '{}' to play the performance {} on{}", take.asset, take.file.string(),
                                names.empty() ? "" : " (the shot's assets: " + shotfile::quotedList(names) + ")"));
      continue;
    }
    for (const char* member : {"blendshapes", "controls", "joints", "performance"}) target->erase(member);
    // A take's frames are the shot's unless told otherwise (a shot's own "performance" defaults to
    // 30 fps, a capture rig's rate).
    const Json* frames = root.contains("frames") ? &root["frames"] : nullptr;
    const bool shotFps = frames && frames->is_object() && frames->contains("fps") && (*frames)["fps"].is_number();
    Json performance = {{"file", fs::absolute(take.file).lexically_normal().string()},
                        {"fps", take.fps ? *take.fps : shotFps ? (*frames)["fps"].get<double>() : Shot{}.fps}};
    (*target)["performance"] = std::move(performance);
  }
}

void reportDuplicateKeys(const shotfile::JsonSource& source, Checker& checker) {
  for (const shotfile::DuplicateKey& d : source.duplicateKeys()) {
    const shotfile::TextPosition first = source.positionOf(d.firstKeyOffset);
    const std::string key = d.pointer.substr(d.pointer.rfind('/') + 1);
    checker.error(d.pointer, Anchor::Key,
                  fmt::format("duplicate key '{}' (first given at line {}, column {})", key, first.line, first.column));
  }
}

Shot loadShotWith(const fs::path& path, const GltfAssetLoader& loadAsset,
                  const std::vector<PerformanceOverride>& performances) {
  Shot shot;
  shot.path = path;
  shotfile::ParsedJsonFile parsed = shotfile::readJsonFile(path, "the shot file");
  Checker checker(path, parsed.source);
  reportDuplicateKeys(parsed.source, checker);
  applyPerformanceOverrides(parsed.json, performances, checker);
  shotfile::ShotUses uses;
  shotfile::ShotReader(checker, shot, uses).read(parsed.json);
  shotfile::loadShotFiles(uses, shot, checker, loadAsset);
  shotfile::bindShotUses(uses, shot, checker);
  shotfile::sortByPosition(shot.warnings);
  if (checker.errorCount() > 0) throw ShotError(checker.diagnostics());
  shotfile::resolveShot(shot, checker);
  if (checker.errorCount() > 0) throw ShotError(checker.diagnostics());
  return shot;
}

}  // namespace

Shot loadShot(const std::filesystem::path& path) { return loadShot(path, loadGltfAssetFile); }

Shot loadShot(const std::filesystem::path& path, const GltfAssetLoader& loadAsset) {
  return loadShotWith(path, loadAsset, {});
}

Shot loadShot(const std::filesystem::path& path, const std::vector<PerformanceOverride>& performances) {
  return loadShotWith(path, loadGltfAssetFile, performances);
}

}  // namespace lacrima
