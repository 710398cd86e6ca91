// ShotReader (shot_reader.hpp): the section "materials" (docs/shot-format.md). Their texture files
// are opened with the other files (load/shot_files.cpp), to check that they are images.
#include <fmt/format.h>

#include "read/shot_reader.hpp"
#include "read/suggest.hpp"

namespace lacrima::shotfile {

namespace {

const std::vector<std::string> kMaterialTypes = {"diffuse", "skin", "water", "rough_dielectric"};
const std::vector<std::string> kSubsurfaceMethods = {"randomWalk", "diffusion"};  // order of readSubsurfaceMethod's

}  // namespace

void ShotReader::readMaterials(const Json& v) {
  if (!v.is_object()) {
    c_.error("/materials", Anchor::Value,
             "expected an object mapping material names to materials, found " + describeValue(v));
    return;
  }
  for (const auto& item : v.items()) {
    const std::string pointer = childPointer("/materials", item.key());
    if (item.key().empty()) c_.error(pointer, Anchor::Key, "a material name must not be empty");
    // Registered even when invalid, so that references to it do not add confusing errors.
    Material m;
    m.name = item.key();
    readMaterial(item.value(), pointer, m);
    shot_.materials.push_back(std::move(m));
  }
}

void ShotReader::readMaterial(const Json& v, const std::string& pointer, Material& m) {
  const auto type = readType(v, pointer, kMaterialTypes, "material");
  if (!type) return;
  const Range unit = Range::closed(0, 1), ior = Range::openClosed(1, 3);
  const Range priority = Range::closed(0, kMaxDielectricPriority);  // nested dielectrics (docs/shot-format.md)
  if (*type == "diffuse") {
    ObjectReader o(c_, v, pointer, {"type", "albedo", "emission", "textures"});
    DiffuseParams p;
    readTextures(o, {"albedo", "normal"}, m.textures);
    if (m.textures.albedo) p.albedo = Color::Ones();  // with a map the constant is a factor, 1 unless given
    if (auto x = o.color("albedo", unit)) p.albedo = *x;
    m.params = p;
    if (auto x = o.color("emission", Range::atLeast(0))) m.emission = *x;
  } else if (*type == "skin") {
    ObjectReader o(c_, v, pointer,
                   {"type", "albedo", "roughness", "ior", "roughness2", "lobeMix", "poreScale", "poreDepth", "furrowScale",
                    "furrowDepth", "cavity", "subsurface", "emission", "textures"});
    SkinParams p;
    readTextures(o, {"albedo", "roughness", "normal", "meanFreePath"}, m.textures);
    if (m.textures.albedo) p.albedo = Color::Ones();  // with a map the constant is a factor, 1 unless given
    if (auto x = o.color("albedo", unit)) p.albedo = *x;
    if (auto x = o.number("roughness", unit)) p.roughness = float(*x);
    if (auto x = o.number("ior", ior)) p.ior = float(*x);
    if (auto x = o.number("roughness2", unit)) p.roughness2 = float(*x);
    if (auto x = o.number("lobeMix", unit)) p.lobeMix = float(*x);
    if (o.has("roughness2") && !o.has("lobeMix"))
      o.error("roughness2", "'roughness2' needs 'lobeMix' (the weight of the second lobe, in [0, 1])", Anchor::Key);
    if (auto x = o.number("poreScale", Range::above(0))) p.poreScale = float(*x);
    if (auto x = o.number("poreDepth", Range::atLeast(0))) p.poreDepth = float(*x);
    if (auto x = o.number("furrowScale", Range::above(0))) p.furrowScale = float(*x);
    if (auto x = o.number("furrowDepth", Range::atLeast(0))) p.furrowDepth = float(*x);
    if (auto x = o.number("cavity", unit)) p.cavity = float(*x);
    if (const Json* sss = o.find("subsurface")) {  // random-walk subsurface scattering (subsurface.hpp)
      ObjectReader so(c_, *sss, o.at("subsurface"), {"meanFreePath", "method"});
      SubsurfaceParams subsurface;
      if (auto x = so.color("meanFreePath", Range::above(0))) subsurface.meanFreePath = *x;
      readSubsurfaceMethod(so, subsurface);
      if (so.ok()) p.subsurface = subsurface;
    }
    if (m.textures.meanFreePath && !o.has("subsurface"))
      o.error("textures", "a 'meanFreePath' texture needs 'subsurface' (it scales the subsurface mean free path)");
    m.params = p;
    if (auto x = o.color("emission", Range::atLeast(0))) m.emission = *x;
  } else if (*type == "water") {
    ObjectReader o(c_, v, pointer, {"type", "ior", "tint", "priority", "emission"});
    SmoothDielectricParams p;
    if (auto x = o.number("ior", ior)) p.ior = float(*x);
    if (auto x = o.color("tint", unit)) p.tint = *x;
    if (auto x = o.integer("priority", priority)) p.priority = int(*x);
    m.params = p;
    if (auto x = o.color("emission", Range::atLeast(0))) m.emission = *x;
  } else {  // rough_dielectric
    ObjectReader o(c_, v, pointer, {"type", "ior", "roughness", "tint", "priority", "emission"});
    RoughDielectricParams p;
    if (auto x = o.number("ior", ior)) p.ior = float(*x);
    if (auto x = o.number("roughness", Range::openClosed(0, 1))) p.roughness = float(*x);
    if (auto x = o.color("tint", unit)) p.tint = *x;
    if (auto x = o.integer("priority", priority)) p.priority = int(*x);
    m.params = p;
    if (auto x = o.color("emission", Range::atLeast(0))) m.emission = *x;
  }
}

// "method": "randomWalk" | "diffusion" of a skin's "subsurface" (docs/shot-format.md, "Skin").
void ShotReader::readSubsurfaceMethod(ObjectReader& o, SubsurfaceParams& subsurface) {
  static constexpr SubsurfaceMethod methods[] = {SubsurfaceMethod::RandomWalk, SubsurfaceMethod::Diffusion};
  if (const auto i = readChoice(o, "method", kSubsurfaceMethods, "subsurface method")) subsurface.method = methods[*i];
}

// "textures": {"<role>": file or {"file": file[, "colorSpace": ...]}} with the roles `roles`
// (docs/shot-format.md). Each file must exist and open as an image.
void ShotReader::readTextures(ObjectReader& material, const std::vector<std::string>& roles, MaterialTextures& textures) {
  const Json* v = material.find("textures");
  if (!v) return;
  ObjectReader o(c_, *v, material.at("textures"), roles);
  if (!o.ok()) return;
  const std::pair<const char*, std::optional<TextureMap>*> slots[] = {{"albedo", &textures.albedo},
                                                                     {"roughness", &textures.roughness},
                                                                     {"normal", &textures.normal},
                                                                     {"meanFreePath", &textures.meanFreePath}};
  for (const auto& [role, slot] : slots) {
    const Json* map = o.find(role);
    if (!map) continue;
    if (std::string(role) == "albedo" && map->is_object() && map->contains("pattern"))
      textures.irisPattern = readAlbedoPattern(*map, o.at(role));
    else
      *slot = readTextureMap(*map, o.at(role), std::string(role) == "albedo");
  }
}

// {"pattern": "iris"[, "seed": n]}: a procedural albedo in place of a file (iris_pattern.hpp).
std::optional<IrisPatternParams> ShotReader::readAlbedoPattern(const Json& v, const std::string& pointer) {
  ObjectReader o(c_, v, pointer, {"pattern", "seed"});
  IrisPatternParams pattern;
  const std::vector<std::string> patterns = {"iris"};
  const auto kind = readChoice(o, "pattern", patterns, "albedo pattern");
  if (auto x = o.unsignedInteger("seed")) pattern.seed = *x;
  if (!kind || !o.ok()) return std::nullopt;
  return pattern;
}

// A texture file as a path, or {"file": path, "colorSpace": "auto" | "srgb" | "linear"} (the
// colour space only for albedo maps, whose values are colours; other maps are data).
std::optional<TextureMap> ShotReader::readTextureMap(const Json& v, const std::string& pointer, bool colour) {
  TextureMap map;
  std::optional<std::string> file;
  std::string filePointer = pointer;
  if (v.is_object()) {
    ObjectReader o(c_, v, pointer, colour ? std::vector<std::string>{"file", "colorSpace"} : std::vector<std::string>{"file"});
    file = o.string("file", true);
    filePointer = o.at("file");
    if (const auto space = o.string("colorSpace")) {
      const std::vector<std::string> spaces = {"auto", "srgb", "linear"};
      if (*space == "srgb") map.encoding = TextureEncoding::Srgb;
      else if (*space == "linear") map.encoding = TextureEncoding::Linear;
      else if (*space != "auto")
        o.error("colorSpace", fmt::format("unknown colour space '{}' (expected one of {})", *space, quotedList(spaces)));
    }
  } else if (v.is_string()) {
    file = v.get<std::string>();
  } else {
    c_.error(pointer, Anchor::Value,
             std::string("expected an image file path") + (colour ? " or {\"file\": path, \"colorSpace\": ...}" : "") +
                 ", found " + describeValue(v));
  }
  if (!file) return std::nullopt;
  uses_.textureImages.push_back(fileUse(filePointer, *file));
  map.file = uses_.textureImages.back().resolved;
  return map;
}

}  // namespace lacrima::shotfile
