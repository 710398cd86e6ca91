#pragma once
// The loading phase of loadShot (shot_loader.cpp): every file the shot description names (ShotUses,
// read/shot_uses.hpp), opened once, after the whole description is read: the colour configuration
// (checked to exist), the glTF assets (a file named by several assets is loaded once and shared:
// they are immutable), the environment map and the texture images (their headers,
// so that a file that is no image is reported now and not halfway through a render). A file that
// cannot be used is reported at the JSON pointer of the value naming it; what uses its contents is
// then not checked (load/shot_binding.hpp skips an asset that did not load).
#include "lacrima/scenes/shot.hpp"
#include "read/shot_checker.hpp"
#include "read/shot_uses.hpp"

namespace lacrima::shotfile {

void loadShotFiles(const ShotUses& uses, Shot& shot, Checker& c, const GltfAssetLoader& loadAsset);

}  // namespace lacrima::shotfile
