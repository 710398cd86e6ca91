#pragma once
// The binding phase of loadShot (shot_loader.cpp), after the files are loaded (shot_files.hpp): the
// names and indices the shot description uses inside its assets (ShotUses, read/shot_uses.hpp)
// checked against the loaded files, each problem reported at the JSON pointer it was written at,
// and what follows from them derived:
//   - per asset (asset_binding.cpp): the part and material names of "materials" and "hide", the
//     blendshape weights (and their channels), the animation members ("rig", "joints", "controls",
//     "performance" with its track file, "animation"; asset_animation_reader.hpp), the material of
//     each primitive;
//   - the parts and surface anchors named by tears, details, eyes, flesh, SPH colliders and shapes;
//   - the camera, with the glTF camera it names.
// Nothing is checked against an asset that failed to load: its own error is already reported.
#include "lacrima/scenes/shot.hpp"
#include "read/shot_checker.hpp"
#include "read/shot_uses.hpp"

namespace lacrima::shotfile {

void bindShotUses(const ShotUses& uses, Shot& shot, Checker& c);

// asset_binding.cpp: what one asset's members use of its glTF file (the asset is loaded).
void bindAsset(const AssetUse& use, Shot& shot, Checker& c);

}  // namespace lacrima::shotfile
