#pragma once
// What a shot description uses of the files it names, recorded by the reading phase (which opens no
// file) for the two phases after it (load/): the files to open, and the names and indices used inside
// them (parts, blendshapes, landmarks, cameras...), each with the JSON pointer of the value that uses
// it, so that a problem found once the file is open is reported where it was written.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lacrima/scenes/shot_model.hpp"
#include "read/shot_checker.hpp"

namespace lacrima::shotfile {

// A file named in the shot: the path as written, resolved against the shot file's directory.
struct FileUse {
  std::string pointer;  // of the value naming the file
  std::string written;
  std::filesystem::path resolved;
};

// A name of a part, primitive or material of an asset (a key of "materials", an entry of "hide").
struct PrimitiveNameUse {
  std::string name;
  std::string pointer;
  Anchor anchor = Anchor::Value;
};

// A blendshape weight: the name is checked against the asset's targets; an animated weight becomes
// an AssetChannel once its target index is known.
struct BlendshapeUse {
  std::string name;
  std::string pointer;  // of the member (reported at its key)
  std::optional<AnimatedFloat> weight;
};

// One asset of "assets": its glTF file and what its members use of it.
struct AssetUse {
  size_t asset = 0;  // index into Shot::assets
  std::optional<FileUse> file;
  std::vector<PrimitiveNameUse> primitiveNames;
  std::vector<BlendshapeUse> blendshapes;
  ObjectReader members;          // the asset object: its "rig", "joints", "controls", "performance", "animation"
  std::string materialsPointer;  // where a textured primitive without uvs is reported
};

// A part of an asset named by a tear, detail, eye, lashes, flesh, SPH collider or attached shape.
struct PartUse {
  size_t asset = 0;
  std::string part;
  std::string pointer;  // of the "part" value
};

// A landmark, vertex or uv anchor ({"landmark": i}, ...): checked against the part's mesh.
struct SurfaceAnchorUse {
  size_t asset = 0;
  std::string part;
  std::string pointer;
  const Json* value = nullptr;  // into the parsed shot file, which outlives the phases
};

// The camera, derived once its glTF camera (if any) is found.
struct CameraUse {
  std::optional<size_t> gltfAsset;  // Kind::Gltf: the asset holding the camera
  std::string gltfCameraPointer;    // of "/camera/gltf/camera"
};

struct ShotUses {
  std::optional<FileUse> colorConfig;
  std::optional<FileUse> environmentMap;
  std::vector<FileUse> textureImages;
  std::vector<AssetUse> assets;
  std::vector<PartUse> parts;
  std::vector<SurfaceAnchorUse> anchors;
  std::optional<CameraUse> camera;
};

}  // namespace lacrima::shotfile
