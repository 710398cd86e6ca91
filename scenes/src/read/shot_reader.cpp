// ShotReader (shot_reader.hpp): the root object of a shot file, in the order its sections need each
// other, and what several sections read alike (files, "type", material references, asset parts,
// surface anchors, transforms, skin regions).
#include "read/shot_reader.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "read/animation_reader.hpp"
#include "shot_geometry.hpp"
#include "read/suggest.hpp"
#include "read/surface_anchor_reader.hpp"

namespace lacrima::shotfile {

namespace {

const std::vector<std::string> kRootKeys = {"version",   "frames", "output",      "colorConfig",
                                            "render",    "camera", "environment", "background",
                                            "materials", "lights", "assets",      "shapes",
                                            "tears",     "details", "eyes",   "flesh",
                                            "sph"};

constexpr int kSupportedVersion = 1;

}  // namespace

std::optional<size_t> readChoice(ObjectReader& o, const char* key, const std::vector<std::string>& names,
                                 const char* what) {
  const auto value = o.string(key);
  if (!value) return std::nullopt;
  const auto it = std::find(names.begin(), names.end(), *value);
  if (it != names.end()) return size_t(it - names.begin());
  const std::string suggestion = didYouMean(*value, names);
  o.error(key, suggestion.empty() ? fmt::format("unknown {} '{}' (expected one of {})", what, *value, quotedList(names))
                                  : fmt::format("unknown {} '{}'{}", what, *value, suggestion));
  return std::nullopt;
}

void appendUnique(std::vector<std::string>& list, const std::string& s) {
  if (!s.empty() && std::find(list.begin(), list.end(), s) == list.end()) list.push_back(s);
}

std::vector<std::string> primitiveNames(const GltfPrimitive& p) { return {p.part, p.name, p.material.name}; }

void warnTexturesWithoutUvs(Checker& c, Shot& shot, const std::string& pointer, uint32_t materialId,
                            const std::string& what) {
  if (materialId >= shot.materials.size() || !shot.materials[materialId].textures.any()) return;
  shot.warnings.push_back(c.warning(pointer, Anchor::Value,
                                    fmt::format("{} has no uvs: the textures of material '{}' are skipped there",
                                                what, shot.materials[materialId].name)));
}

// ---- ShotReader -------------------------------------------------------------------------------

void ShotReader::read(const Json& root) {
  ObjectReader o(c_, root, "", kRootKeys);
  if (!o.ok()) return;
  if (const Json* v = o.find("version")) {
    const auto version = readInteger(c_, *v, "/version", Range::any());
    if (version && *version != kSupportedVersion) {
      c_.error("/version", Anchor::Value,
               fmt::format("unsupported version {}: this lacrima reads shot files of version {}", *version,
                           kSupportedVersion));
      return;  // the rest would be checked against the wrong rules
    }
  } else {
    o.missing("version", "1, the version of the shot format");
  }

  const bool framesOk = readSection(o, "frames", "an object with 'start', 'end' and optionally 'fps'",
                                    [&](const Json& v) { return readFrames(v); });
  if (const Json* v = o.find("output"))
    readOutput(*v, framesOk);
  else
    o.missing("output", "a path pattern such as \"renders/shot.####.exr\"");
  if (const Json* v = o.find("colorConfig")) {
    if (const auto file = readString(c_, *v, "/colorConfig")) {
      uses_.colorConfig = fileUse("/colorConfig", *file);
      shot_.ocioConfig = uses_.colorConfig->resolved;
    }
  }
  readSection(o, "render", "an object with 'width', 'height' and 'spp'",
              [&](const Json& v) { return readRender(v); });
  if (const Json* v = o.find("materials")) readMaterials(*v);
  if (const Json* v = o.find("assets"))
    readArray(*v, "/assets", "assets", [&](const Json& e, const std::string& p) { readAsset(e, p); });
  readSection(o, "camera", "an object with 'position', 'lookAt' and 'fov', or with 'gltf'",
              [&](const Json& v) { return readCamera(v); });
  if (const Json* v = o.find("environment")) readEnvironment(*v);
  if (const Json* v = o.find("background")) {
    if (const auto color = readColor(c_, *v, "/background", Range::atLeast(0))) shot_.background = *color;
    if (o.has("environment"))
      c_.error("/background", Anchor::Key,
               "'background' and 'environment' cannot both be given: the uniform background is used only "
               "without an environment map");
  }
  if (const Json* v = o.find("lights"))
    readArray(*v, "/lights", "lights", [&](const Json& e, const std::string& p) { readLight(e, p); });
  if (const Json* v = o.find("shapes"))
    readArray(*v, "/shapes", "shapes", [&](const Json& e, const std::string& p) { readShape(e, p); });
  if (const Json* v = o.find("tears"))
    readArray(*v, "/tears", "tears", [&](const Json& e, const std::string& p) { readTear(e, p); });
  if (const Json* v = o.find("details"))
    readArray(*v, "/details", "details", [&](const Json& e, const std::string& p) { readDetail(e, p); });
  if (const Json* v = o.find("eyes"))
    readArray(*v, "/eyes", "eyes", [&](const Json& e, const std::string& p) { readEye(e, p); });
  if (const Json* v = o.find("flesh"))
    readArray(*v, "/flesh", "flesh volumes", [&](const Json& e, const std::string& p) { readFlesh(e, p); });
  if (const Json* v = o.find("sph"))
    readArray(*v, "/sph", "SPH liquids", [&](const Json& e, const std::string& p) { readSph(e, p); });
}

std::filesystem::path ShotReader::resolve(const std::string& value) const {
  const std::filesystem::path p(value);
  return (p.is_absolute() ? p : baseDir_ / p).lexically_normal();
}

FileUse ShotReader::fileUse(const std::string& pointer, const std::string& written) const {
  return FileUse{pointer, written, resolve(written)};
}

// Reads "type" of an object whose allowed keys depend on it. Reports a non-object value, a
// missing type and an unknown type.
std::optional<std::string> ShotReader::readType(const Json& v, const std::string& pointer,
                                                const std::vector<std::string>& types, const char* what) {
  if (!v.is_object()) {
    c_.error(pointer, Anchor::Value, "expected an object, found " + describeValue(v));
    return std::nullopt;
  }
  const auto it = v.find("type");
  if (it == v.end()) {
    c_.error(pointer, Anchor::Key, fmt::format("missing required key 'type' (one of {})", quotedList(types)));
    return std::nullopt;
  }
  const std::string typePointer = childPointer(pointer, "type");
  if (!it->is_string()) {
    c_.error(typePointer, Anchor::Value,
             fmt::format("expected one of {}, found {}", quotedList(types), describeValue(*it)));
    return std::nullopt;
  }
  const std::string type = it->get<std::string>();
  if (std::find(types.begin(), types.end(), type) == types.end()) {
    const std::string suggestion = didYouMean(type, types);
    c_.error(typePointer, Anchor::Value,
             suggestion.empty()
                 ? fmt::format("unknown {} type '{}' (expected one of {})", what, type, quotedList(types))
                 : fmt::format("unknown {} type '{}'{}", what, type, suggestion));
    return std::nullopt;
  }
  return type;
}

std::vector<std::string> ShotReader::materialNames() const {
  std::vector<std::string> names;
  for (const Material& m : shot_.materials) names.push_back(m.name);
  return names;
}

// A reference to a shot material by name (the value at `pointer`); -1 when undefined (reported).
int ShotReader::materialReference(const Json& v, const std::string& pointer) {
  const auto name = readString(c_, v, pointer);
  if (!name) return -1;
  const int id = shot_.findMaterial(*name);
  if (id < 0)
    c_.error(
        pointer, Anchor::Value,
        fmt::format("undefined material '{}'{}", *name,
                    suggestionOrList(*name, materialNames(), "defined materials", "the shot defines no materials")));
  return id;
}

// A required shot-material member; false when missing or undefined (reported).
bool ShotReader::readMaterialMember(ObjectReader& o, std::string& name, uint32_t& id) {
  const Json* m = o.find("material");
  if (!m) {
    o.missing("material", "the name of a material in 'materials'");
    return false;
  }
  const int found = materialReference(*m, o.at("material"));
  if (found < 0) return false;
  name = m->get<std::string>();
  id = uint32_t(found);
  return true;
}

// A required material member named `key`; false when missing or undefined (reported).
bool ShotReader::readNamedMaterial(ObjectReader& o, const std::string& key, uint32_t& id) {
  const Json* m = o.find(key);
  if (!m) {
    o.missing(key, "the name of a material in 'materials'");
    return false;
  }
  const int found = materialReference(*m, o.at(key));
  if (found < 0) return false;
  id = uint32_t(found);
  return true;
}

// The required "asset" and "part" members of o: the index of the asset, or nullopt (reported). The
// part is checked once the asset is loaded (PartUse).
std::optional<size_t> ShotReader::readAssetPart(ObjectReader& o, std::string& partOut) {
  const auto assetName = o.string("asset", true);
  const auto part = o.string("part", true);
  if (!assetName || !part) return std::nullopt;
  std::vector<std::string> assetNames;
  std::optional<size_t> index;
  for (size_t a = 0; a < shot_.assets.size(); ++a) {
    assetNames.push_back(shot_.assets[a].name);
    if (shot_.assets[a].name == *assetName) index = a;
  }
  if (!index) {
    o.error("asset", fmt::format("undefined asset '{}'{}", *assetName,
                                 suggestionOrList(*assetName, assetNames, "assets", "the shot has no assets")));
    return std::nullopt;
  }
  usePart(o, *index, *part);
  partOut = *part;
  return index;
}

// The value of o's "part" names a part of the asset: checked once the asset is loaded.
void ShotReader::usePart(ObjectReader& o, size_t asset, const std::string& part) {
  uses_.parts.push_back(PartUse{asset, part, o.at("part")});
}

// A required surface anchor member (read/surface_anchor_reader.hpp); a landmark, vertex or uv one is
// checked against the part once the asset is loaded.
void ShotReader::readAnchor(ObjectReader& o, const std::string& key, size_t asset, const std::string& part,
                            ShotSurfaceAnchor& anchor) {
  const Json* v = o.find(key);
  if (!v) {
    o.missing(key, "a point [x, y, z] near the skin, {\"landmark\": i}, {\"vertex\": i} or {\"uv\": [u, v]}");
    return;
  }
  const auto written = readSurfaceAnchor(c_, *v, o.at(key));
  if (!written) return;
  anchor = *written;
  if (anchor.kind != ShotSurfaceAnchor::Kind::Point)
    uses_.anchors.push_back(SurfaceAnchorUse{asset, part, o.at(key), v});
}

// A required [x, y, z] member that may be keyed.
std::optional<AnimatedVec3> ShotReader::readAnimatedMember(ObjectReader& o, const std::string& key) {
  const Json* v = o.find(key);
  if (!v) {
    o.missing(key, "[x, y, z], or keys {\"keys\": [[frame, [x, y, z]], ...]}");
    return std::nullopt;
  }
  return readAnimatedVec3(c_, *v, o.at(key));
}

std::optional<Mat3> ShotReader::readRotation(const Json& v, const std::string& pointer) {
  if (v.is_array()) {
    const auto degrees = readVec3(c_, v, pointer, Range::any(), "[x, y, z] degrees");
    if (!degrees) return std::nullopt;
    return eulerXyzDegrees(*degrees);
  }
  if (v.is_object()) {
    ObjectReader o(c_, v, pointer, {"axis", "angle"});
    const auto axis = o.vec3("axis", true);
    const auto angle = o.number("angle", Range::any(), true);
    if (axis && !(axis->norm() > 0.0f)) o.error("axis", "expected a non-zero axis, found [0, 0, 0]");
    if (!axis || !angle || !(axis->norm() > 0.0f)) return std::nullopt;
    return axisAngleDegrees(*axis, float(*angle));
  }
  c_.error(pointer, Anchor::Value,
           "expected [x, y, z] Euler angles in degrees or {\"axis\": [x, y, z], \"angle\": degrees}, found " +
               describeValue(v));
  return std::nullopt;
}

ShotTransform ShotReader::readTransform(const Json& v, const std::string& pointer) {
  ShotTransform t;
  ObjectReader o(c_, v, pointer, {"translate", "rotate", "scale"});
  if (auto x = o.vec3("translate")) t.translate = *x;
  if (const Json* r = o.find("rotate"))
    if (auto x = readRotation(*r, o.at("rotate"))) t.rotation = *x;
  if (const Json* s = o.find("scale")) {
    if (s->is_array()) {
      if (auto x = readVec3(c_, *s, o.at("scale"), Range::above(0))) t.scale = *x;
    } else if (s->is_number()) {
      if (auto x = readNumber(c_, *s, o.at("scale"), Range::above(0))) t.scale = Vec3::Constant(float(*x));
    } else {
      o.error("scale", "expected a number > 0 or [x, y, z] (each > 0), found " + describeValue(*s));
    }
  }
  return t;
}

// "regions": [{"center": anchor on the part, "radius": m > 0}, ...], at least one (the caller
// checks that the key is there when it must be).
void ShotReader::readSkinRegions(ObjectReader& o, size_t asset, const std::string& part,
                                 std::vector<ShotSkinRegion>& regions) {
  const Json* v = o.find("regions");
  if (!v) return;
  if (!v->is_array() || v->empty()) {
    o.error("regions", "expected a non-empty array of regions {\"center\", \"radius\"}, found " + describeValue(*v));
    return;
  }
  for (size_t i = 0; i < v->size(); ++i) {
    ObjectReader r(c_, (*v)[i], childPointer(o.at("regions"), i), {"center", "radius"});
    if (!r.ok()) continue;
    ShotSkinRegion region;
    readAnchor(r, "center", asset, part, region.center);
    if (auto x = r.number("radius", Range::above(0), true)) region.radius = *x;
    regions.push_back(region);
  }
}

}  // namespace lacrima::shotfile
