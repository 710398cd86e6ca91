// ShotReader (shot_reader.hpp): the section "assets" (docs/shot-format.md): each glTF asset loaded
// (so that the part, material and blendshape names the shot uses are checked), its animation
// read, and its primitives given their materials.
#include <fmt/format.h>

#include <algorithm>

#include "read/animation_reader.hpp"
#include "read/asset_animation_reader.hpp"
#include "read/shot_reader.hpp"
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

}  // namespace

void ShotReader::readAsset(const Json& v, const std::string& pointer) {
  ObjectReader o(c_, v, pointer,
                 {"name", "file", "transform", "materials", "blendshapes", "hide", "rig", "joints", "controls",
                  "performance", "animation"});
  if (!o.ok()) return;
  ShotAsset asset;
  const auto file = o.string("file", true);
  const auto name = o.string("name");
  asset.name = name ? *name : file ? std::filesystem::path(*file).stem().string() : "";
  if (!asset.name.empty()) {
    for (size_t i = 0; i < shot_.assets.size(); ++i)
      if (shot_.assets[i].name == asset.name)
        c_.error(o.at(name ? "name" : "file"), Anchor::Value,
                 fmt::format("duplicate asset name '{}' (already used by /assets/{}){}", asset.name, i,
                             name ? "" : "; give the assets distinct 'name's"));
  }
  if (const Json* t = o.find("transform")) asset.transform = readTransform(*t, o.at("transform"));
  if (file) {
    asset.file = resolve(*file);
    if (checkExists(o.at("file"), *file, asset.file)) {
      try {
        asset.gltf = loadAsset_(asset.file);
        for (const std::string& w : asset.gltf->warnings)
          shot_.warnings.push_back(c_.warning(o.at("file"), Anchor::Value, asset.file.string() + ": " + w));
      } catch (const std::exception& e) {
        o.error("file", fmt::format("cannot load the glTF asset: {}", e.what()));
      }
    }
  }
  // Names the shot may use for the asset's primitives (only known when it loaded).
  std::vector<std::string> names;
  if (asset.gltf)
    for (const GltfPrimitive& p : asset.gltf->primitives)
      for (const std::string& n : primitiveNames(p)) appendUnique(names, n);
  auto checkPrimitiveName = [&](const std::string& key, const std::string& keyPointer, Anchor anchor) {
    if (!asset.gltf || std::find(names.begin(), names.end(), key) != names.end()) return;
    c_.error(keyPointer, anchor,
             fmt::format("asset '{}' has no part or material named '{}'{}", asset.name, key,
                         suggestionOrList(key, names, "its parts and materials", "it has no primitives")));
  };

  if (const Json* m = o.find("materials")) {
    if (!m->is_object()) {
      o.error("materials",
              "expected an object mapping part or material names to shot material names, found " + describeValue(*m));
    } else {
      for (const auto& item : m->items()) {
        const std::string p = childPointer(o.at("materials"), item.key());
        checkPrimitiveName(item.key(), p, Anchor::Key);
        if (materialReference(item.value(), p) >= 0)
          asset.materialBindings.emplace_back(item.key(), item.value().get<std::string>());
      }
    }
  }
  if (const Json* b = o.find("blendshapes")) {
    if (!b->is_object()) {
      o.error("blendshapes", "expected an object mapping blendshape names to weights, found " + describeValue(*b));
    } else {
      for (const auto& item : b->items()) {
        const std::string p = childPointer(o.at("blendshapes"), item.key());
        const auto weight = readAnimatedNumber(c_, item.value(), p, Range::closed(0, 1));
        const int target = asset.gltf ? asset.gltf->findTarget(item.key()) : -1;
        if (asset.gltf && target < 0) {
          if (asset.gltf->targetNames.empty())
            c_.error(p, Anchor::Key, fmt::format("asset '{}' has no blendshapes", asset.name));
          else
            c_.error(p, Anchor::Key,
                     fmt::format("unknown blendshape '{}'{}", item.key(),
                                 suggestionOrList(item.key(), asset.gltf->targetNames, "blendshapes", "")));
        }
        if (weight) asset.blendshapes.emplace_back(item.key(), weight->constant);
        if (weight && weight->animated() && target >= 0)
          asset.animatedBlendshapes.push_back(AssetChannel{item.key(), size_t(target), *weight});
      }
    }
  }
  if (const Json* h = o.find("hide")) {
    readArray(*h, o.at("hide"), "part names", [&](const Json& e, const std::string& p) {
      if (auto part = readString(c_, e, p)) {
        checkPrimitiveName(*part, p, Anchor::Value);
        asset.hide.push_back(*part);
      }
    });
  }
  readAssetAnimation(o, asset, {baseDir_, shot_.fps, double(shot_.frameStart)});
  if (asset.gltf) {
    assignPrimitiveMaterials(asset);
    warnTexturedPrimitivesWithoutUvs(asset, o.has("materials") ? o.at("materials") : pointer);
  }
  shot_.assets.push_back(std::move(asset));
}

void ShotReader::assignPrimitiveMaterials(ShotAsset& asset) {
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
    for (const std::string& n : names)  // part first, then primitive name, then material name
      if (!bound) bound = binding(n);
    if (bound) {
      asset.primitiveMaterials.push_back(std::max(0, shot_.findMaterial(*bound)));
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
    const int id = int(shot_.materials.size() + shot_.assetMaterials.size());
    shot_.assetMaterials.push_back(std::move(m));
    automatic.emplace_back(key, id);
    asset.primitiveMaterials.push_back(id);
  }
}

void ShotReader::warnTexturedPrimitivesWithoutUvs(const ShotAsset& asset, const std::string& pointer) {
  const std::vector<GltfPrimitive>& primitives = asset.gltf->primitives;
  for (size_t i = 0; i < primitives.size() && i < asset.primitiveMaterials.size(); ++i)
    if (primitives[i].mesh.uvs.empty() && asset.primitiveMaterials[i] >= 0)
      warnTexturesWithoutUvs(pointer, uint32_t(asset.primitiveMaterials[i]),
                             fmt::format("primitive '{}' of asset '{}'", primitives[i].name, asset.name));
}

}  // namespace lacrima::shotfile
