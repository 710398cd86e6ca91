// The binding phase for one asset (shot_binding.hpp): the names its members use checked against its
// glTF file, its blendshape channels and animation read, its primitives given their materials.
#include <fmt/format.h>

#include <algorithm>

#include "load/asset_animation_reader.hpp"
#include "load/shot_binding.hpp"
#include "read/shot_reader.hpp"  // primitiveNames, appendUnique, warnTexturesWithoutUvs
#include "read/suggest.hpp"

namespace lacrima::shotfile {

namespace {

// Unbound glTF materials: transmissive or volumetric ones become smooth water-like dielectrics
// with the glTF ior, the others diffuse with the base colour.
MaterialParams mapGltfMaterial(const GltfMaterialInfo& m) {
  const Color base = m.baseColor.max(0.0f).min(1.0f);
  if (m.transmission > 0.0f || m.hasVolume) {
    SmoothDielectricParams p;
    p.ior = m.ior > 1.0f ? m.ior : 1.5f;
    p.tint = base;
    return p;
  }
  return DiffuseParams{base};
}

// The keys of "materials" and the entries of "hide" name a part, primitive or glTF material.
void checkPrimitiveNames(const AssetUse& use, const ShotAsset& asset, Checker& c) {
  std::vector<std::string> names;
  for (const GltfPrimitive& p : asset.gltf->primitives)
    for (const std::string& n : primitiveNames(p)) appendUnique(names, n);
  for (const PrimitiveNameUse& u : use.primitiveNames)
    if (std::find(names.begin(), names.end(), u.name) == names.end())
      c.error(u.pointer, u.anchor,
              fmt::format("asset '{}' has no part or material named '{}'{}", asset.name, u.name,
                          suggestionOrList(u.name, names, "its parts and materials", "it has no primitives")));
}

void bindBlendshapes(const AssetUse& use, ShotAsset& asset, Checker& c) {
  const GltfAsset& gltf = *asset.gltf;
  for (const BlendshapeUse& u : use.blendshapes) {
    const int target = gltf.findTarget(u.name);
    if (target < 0) {
      if (gltf.targetNames.empty())
        c.error(u.pointer, Anchor::Key, fmt::format("asset '{}' has no blendshapes", asset.name));
      else
        c.error(u.pointer, Anchor::Key,
                fmt::format("unknown blendshape '{}'{}", u.name,
                            suggestionOrList(u.name, gltf.targetNames, "blendshapes", "")));
    }
    if (u.weight && u.weight->animated() && target >= 0)
      asset.animatedBlendshapes.push_back(AssetChannel{u.name, size_t(target), *u.weight});
  }
}

// The still weights, and each primitive's material: hidden (-1), bound by the shot (its part name
// first, then its primitive name, then its material name), or the glTF material mapped once per
// glTF material name (Shot::assetMaterials).
void assignPrimitiveMaterials(ShotAsset& asset, Shot& shot) {
  const GltfAsset& gltf = *asset.gltf;
  asset.weights.assign(gltf.targetNames.size(), 0.0f);
  for (const auto& [name, weight] : asset.blendshapes)
    if (const int t = gltf.findTarget(name); t >= 0) asset.weights[size_t(t)] = weight;

  auto contains = [](const std::vector<std::string>& list, const std::string& s) {
    return !s.empty() && std::find(list.begin(), list.end(), s) != list.end();
  };
  auto binding = [&](const std::string& s) -> const std::string* {
    if (s.empty()) return nullptr;
    for (const auto& [key, material] : asset.materialBindings)
      if (key == s) return &material;
    return nullptr;
  };
  std::vector<std::pair<std::string, int>> automatic;  // glTF material key -> frame material id
  for (const GltfPrimitive& p : gltf.primitives) {
    const std::vector<std::string> names = primitiveNames(p);
    if (std::any_of(names.begin(), names.end(), [&](const std::string& n) { return contains(asset.hide, n); })) {
      asset.primitiveMaterials.push_back(-1);
      continue;
    }
    const std::string* bound = nullptr;
    for (const std::string& n : names)
      if (!bound) bound = binding(n);
    if (bound) {
      asset.primitiveMaterials.push_back(std::max(0, shot.findMaterial(*bound)));
      continue;
    }
    const std::string key = p.material.name.empty() ? p.name : p.material.name;
    const auto it = std::find_if(automatic.begin(), automatic.end(), [&](const auto& a) { return a.first == key; });
    if (it != automatic.end()) {
      asset.primitiveMaterials.push_back(it->second);
      continue;
    }
    Material m;
    m.name = asset.name + "/" + key;
    m.params = mapGltfMaterial(p.material);
    const int id = int(shot.materials.size() + shot.assetMaterials.size());
    shot.assetMaterials.push_back(std::move(m));
    automatic.emplace_back(key, id);
    asset.primitiveMaterials.push_back(id);
  }
}

void warnTexturedPrimitivesWithoutUvs(const ShotAsset& asset, Shot& shot, Checker& c, const std::string& pointer) {
  const std::vector<GltfPrimitive>& primitives = asset.gltf->primitives;
  for (size_t i = 0; i < primitives.size() && i < asset.primitiveMaterials.size(); ++i)
    if (primitives[i].mesh.uvs.empty() && asset.primitiveMaterials[i] >= 0)
      warnTexturesWithoutUvs(c, shot, pointer, uint32_t(asset.primitiveMaterials[i]),
                             fmt::format("primitive '{}' of asset '{}'", primitives[i].name, asset.name));
}

}  // namespace

void bindAsset(const AssetUse& use, Shot& shot, Checker& c) {
  ShotAsset& asset = shot.assets[use.asset];
  checkPrimitiveNames(use, asset, c);
  bindBlendshapes(use, asset, c);
  ObjectReader members = use.members;
  readAssetAnimation(members, asset, {shot.path.parent_path(), shot.fps, double(shot.frameStart)});
  assignPrimitiveMaterials(asset, shot);
  warnTexturedPrimitivesWithoutUvs(asset, shot, c, use.materialsPointer);
}

}  // namespace lacrima::shotfile
