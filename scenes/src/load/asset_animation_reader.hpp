#pragma once
// The animation members of a shot asset: "rig", "joints", "controls", "performance" and
// "animation"
// (docs/shot-format.md, "Animating a face").
#include <filesystem>

#include "lacrima/scenes/shot_model.hpp"
#include "read/shot_checker.hpp"

namespace lacrima::shotfile {

struct AssetAnimationContext {
  std::filesystem::path baseDir;  // relative paths resolve against the shot file's directory
  double fps = 24.0;              // the shot's frame rate
  double frameStart = 1.0;        // the shot's first frame
};

// Reads the members of `o` (the asset object) that animate it into `asset`. Needs asset.gltf
// (nothing is checked against the asset when it failed to load).
void readAssetAnimation(ObjectReader& o, ShotAsset& asset, const AssetAnimationContext& context);

}  // namespace lacrima::shotfile
