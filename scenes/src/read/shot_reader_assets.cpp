// ShotReader (shot_reader.hpp): the section "assets" (docs/shot-format.md): each asset's file,
// transform, material bindings, blendshape weights and hidden parts read; the names they use inside
// the glTF file, and the animation members, are recorded for after the file is loaded (AssetUse).
#include <fmt/format.h>

#include "read/animation_reader.hpp"
#include "read/shot_reader.hpp"

namespace lacrima::shotfile {

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
  AssetUse use{shot_.assets.size(), std::nullopt, {}, {}, o, o.has("materials") ? o.at("materials") : pointer};
  if (file) {
    use.file = fileUse(o.at("file"), *file);
    asset.file = use.file->resolved;
  }
  if (const Json* m = o.find("materials")) {
    if (!m->is_object()) {
      o.error("materials",
              "expected an object mapping part or material names to shot material names, found " + describeValue(*m));
    } else {
      for (const auto& item : m->items()) {
        const std::string p = childPointer(o.at("materials"), item.key());
        use.primitiveNames.push_back(PrimitiveNameUse{item.key(), p, Anchor::Key});
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
        use.blendshapes.push_back(BlendshapeUse{item.key(), p, weight});
        if (weight) asset.blendshapes.emplace_back(item.key(), weight->constant);
      }
    }
  }
  if (const Json* h = o.find("hide")) {
    readArray(*h, o.at("hide"), "part names", [&](const Json& e, const std::string& p) {
      if (auto part = readString(c_, e, p)) {
        use.primitiveNames.push_back(PrimitiveNameUse{*part, p, Anchor::Value});
        asset.hide.push_back(*part);
      }
    });
  }
  uses_.assets.push_back(std::move(use));
  shot_.assets.push_back(std::move(asset));
}

}  // namespace lacrima::shotfile
