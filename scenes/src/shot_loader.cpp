// loadShot: reads a shot file (docs/shot-format.md), checks all of it, collecting every problem
// with its JSON pointer and text position, and loads the files it names (glTF assets, the
// environment map) once, so that blendshape, part and camera names can be checked too.
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>

#include "frame_pattern.hpp"
#include "json_source.hpp"
#include "text_file.hpp"
#include "lacrima/scenes/shot.hpp"
#include "shot_checker.hpp"
#include "surface_anchor.hpp"
#include "shot_geometry.hpp"
#include "animation_reader.hpp"
#include "asset_animation_reader.hpp"
#include "asset_pose.hpp"
#include "detail_refinement.hpp"
#include "eye_resolve.hpp"
#include "flesh_frame.hpp"
#include "lacrima/sph/surface_tension.hpp"
#include "sph_liquid.hpp"
#include "suggest.hpp"
#include "liquid_tear_resolve.hpp"
#include "liquid_trail_refinement.hpp"
#include "shedding_tear_resolve.hpp"
#include "surface_attachment.hpp"

namespace lacrima {

namespace {

namespace fs = std::filesystem;
using namespace shotfile;

const std::vector<std::string> kRootKeys = {"version",   "frames", "output",      "colorConfig",
                                            "render",    "camera", "environment", "background",
                                            "materials", "lights", "assets",      "shapes",
                                            "tears",     "details", "eyes",   "flesh",
                                            "sph"};
const std::vector<std::string> kMaterialTypes = {"diffuse", "skin", "water", "rough_dielectric"};
const std::vector<std::string> kCausticsModes = {"mnee", "straight", "off"};  // order of readCaustics' modes
const std::vector<std::string> kSamplerKinds = {"sobol", "independent"};  // order of readSampler's kinds
const std::vector<std::string> kSubsurfaceMethods = {"randomWalk", "diffusion"};  // order of readSubsurfaceMethod's
const std::vector<std::string> kFilterTypes = {"blackman-harris", "gaussian", "mitchell", "box"};  // readFilter's order
// A filter wider than this blurs away the detail it should keep (and 16 px is already 8 pixels
// each way); a typo such as 15 for 1.5 is caught.
constexpr double kMaxFilterWidth = 16.0;
const std::vector<std::string> kLightTypes = {"rectangle", "sphere"};
const std::vector<std::string> kShapeTypes = {"sphere", "ellipsoid", "rectangle"};
const std::vector<std::string> kTearTypes = {"dripping", "shedding", "liquid"};
const std::vector<std::string> kDetailPatterns = {"forehead", "eyeCorner", "cheek", "frown", "dimple", "eyePouch"};
const std::vector<std::string> kSubdivisionSchemes = {"loop", "linear"};
const std::vector<std::string> kFleshMaterials = {"fixedCorotated", "stVenantKirchhoff"};  // readFlesh's order
const std::vector<std::string> kFleshIntegrators = {"backwardEuler", "midpoint"};         // readFlesh's order
// Each level quadruples the region's triangles: 4 levels turn one triangle into 256.
constexpr int kMaxSubdivisionLevels = 4;

constexpr int kSupportedVersion = 1;

std::string join(const std::vector<std::string>& items, const char* separator = ", ") {
  std::string out;
  for (size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += separator;
    out += items[i];
  }
  return out;
}

std::string quotedList(const std::vector<std::string>& items) {
  std::vector<std::string> quoted;
  for (const std::string& s : items) quoted.push_back("'" + s + "'");
  return join(quoted);
}

// The index in `names` of the string at `key`; nothing when the key is absent, or, with an error
// naming the key and the closest name (or all of them), when it is none of them:
// "unknown <what> 'x'; did you mean 'y'?".
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

// "; did you mean 'x'?" or " (<listName>: a, b, c)" or " (<emptyText>)".
std::string suggestionOrList(const std::string& name, const std::vector<std::string>& candidates,
                             const std::string& listName, const std::string& emptyText) {
  if (candidates.empty()) return " (" + emptyText + ")";
  const std::string suggestion = didYouMean(name, candidates);
  if (!suggestion.empty()) return suggestion;
  if (candidates.size() > 12) return "";
  return " (" + listName + ": " + quotedList(candidates) + ")";
}

void appendUnique(std::vector<std::string>& list, const std::string& s) {
  if (!s.empty() && std::find(list.begin(), list.end(), s) == list.end()) list.push_back(s);
}

// The names a shot can use for a primitive: its part, its primitive name, its material name.
std::vector<std::string> primitiveNames(const GltfPrimitive& p) { return {p.part, p.name, p.material.name}; }

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

class ShotReader {
 public:
  ShotReader(Checker& c, Shot& shot, const GltfAssetLoader& loadAsset)
      : c_(c), shot_(shot), baseDir_(shot.path.parent_path()), loadAsset_(loadAsset) {}

  void read(const Json& root) {
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
        shot_.ocioConfig = resolve(*file);
        checkExists("/colorConfig", *file, shot_.ocioConfig);
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

 private:
  Checker& c_;
  Shot& shot_;
  fs::path baseDir_;
  const GltfAssetLoader& loadAsset_;

  // ---- helpers -----------------------------------------------------------------------------

  // Reads a required section; returns what the reader returns (false when it is missing).
  template <typename F>
  bool readSection(ObjectReader& o, const std::string& key, const std::string& expectation, F&& reader) {
    const Json* v = o.find(key);
    if (!v) {
      o.missing(key, expectation);
      return false;
    }
    return reader(*v);
  }

  template <typename F>
  void readArray(const Json& v, const std::string& pointer, const char* what, F&& reader) {
    if (!v.is_array()) {
      c_.error(pointer, Anchor::Value, fmt::format("expected an array of {}, found {}", what, describeValue(v)));
      return;
    }
    for (size_t i = 0; i < v.size(); ++i) reader(v[i], childPointer(pointer, i));
  }

  fs::path resolve(const std::string& value) const {
    const fs::path p(value);
    return (p.is_absolute() ? p : baseDir_ / p).lexically_normal();
  }

  bool checkExists(const std::string& pointer, const std::string& written, const fs::path& resolved) {
    std::error_code ec;
    if (fs::is_regular_file(resolved, ec)) return true;
    const std::string what = fs::exists(resolved, ec) ? "not a regular file" : "file not found";
    c_.error(pointer, Anchor::Value,
             written == resolved.string()
                 ? fmt::format("{}: '{}'", what, written)
                 : fmt::format("{}: '{}' (resolved to '{}')", what, written, resolved.string()));
    return false;
  }

  // Reads "type" of an object whose allowed keys depend on it. Reports a non-object value, a
  // missing type and an unknown type.
  std::optional<std::string> readType(const Json& v, const std::string& pointer, const std::vector<std::string>& types,
                                      const char* what) {
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

  std::vector<std::string> materialNames() const {
    std::vector<std::string> names;
    for (const Material& m : shot_.materials) names.push_back(m.name);
    return names;
  }

  // A reference to a shot material by name (the value at `pointer`); -1 when undefined (reported).
  int materialReference(const Json& v, const std::string& pointer) {
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

  // ---- frames, output, render --------------------------------------------------------------

  bool readFrames(const Json& v) {
    ObjectReader o(c_, v, "/frames", {"start", "end", "fps"});
    const auto start = o.integer("start", Range::any(), true);
    const auto end = o.integer("end", start ? Range::atLeast(double(*start)) : Range::any(), true);
    const auto fps = o.number("fps", Range::above(0));
    if (start) shot_.frameStart = int(*start);
    if (end) shot_.frameEnd = int(*end);
    if (fps) shot_.fps = *fps;
    return start && end;
  }

  void readOutput(const Json& v, bool framesOk) {
    const auto pattern = readString(c_, v, "/output");
    if (!pattern) return;
    shot_.outputPattern = resolve(*pattern).string();
    if (framesOk && shot_.frameStart != shot_.frameEnd && !hasFrameField(*pattern))
      c_.error("/output", Anchor::Value,
               fmt::format("'{}' has no frame number field ('####' or '%04d') but the shot has frames {}-{}: every "
                           "frame would overwrite the last",
                           *pattern, shot_.frameStart, shot_.frameEnd));
  }

  bool readRender(const Json& v) {
    const size_t before = c_.errorCount();
    ObjectReader o(c_, v, "/render", {"width", "height", "spp", "maxDepth", "seed", "threads", "floatOutput",
                                           "transparentShadows", "caustics", "sampler", "filter", "bounces",
                                           "adaptive", "denoise", "aovs"});
    RenderSettings& s = shot_.render;
    if (auto x = o.integer("width", Range::closed(1, 16384), true)) s.width = int(*x);
    if (auto x = o.integer("height", Range::closed(1, 16384), true)) s.height = int(*x);
    if (auto x = o.integer("spp", Range::atLeast(1), true)) s.samplesPerPixel = int(*x);
    if (auto x = o.integer("maxDepth", Range::closed(1, 1024))) s.maxDepth = int(*x);
    if (auto x = o.unsignedInteger("seed")) s.seed = *x;
    if (auto x = o.integer("threads", Range::atLeast(0))) s.threads = int(*x);
    if (auto x = o.boolean("floatOutput")) s.floatOutput = *x;
    // Retired: it only switched the caustics off, which "caustics": "off" says. Named, so an older
    // shot learns what replaces it rather than that the key is unknown.
    if (o.has("transparentShadows"))
      o.error("transparentShadows", "is no longer read: give \"caustics\" instead (\"off\" for false; true was the "
                                    "default, \"mnee\")",
              Anchor::Key);
    if (auto x = o.boolean("denoise")) s.denoise = *x;
    readCaustics(o, s);
    readSampler(o, s);
    readFilter(o, s);
    readBounces(o, s);
    readAdaptive(o, s);
    readAovs(o, s);
    return c_.errorCount() == before;
  }

  // "aovs": ["CryptoObject", "CryptoMaterial", "lightGroups", "lightPaths", "diffuse_direct", ...]: further layers of the EXR
  // (docs/compositing.md).
  void readAovs(ObjectReader& render, RenderSettings& s) {
    const Json* v = render.find("aovs");
    if (!v) return;
    if (!v->is_array()) {
      render.error("aovs", "expected a list of layer names such as [\"CryptoObject\", \"CryptoMaterial\"], found " +
                               describeValue(*v));
      return;
    }
    for (size_t i = 0; i < v->size(); ++i) {
      const std::string pointer = childPointer(render.at("aovs"), std::to_string(i));
      const auto name = readString(c_, (*v)[i], pointer);
      if (!name || enableAov(s, *name)) continue;
      const std::string suggestion = didYouMean(*name, aovNames());
      c_.error(pointer, Anchor::Value,
               suggestion.empty() ? fmt::format("unknown AOV '{}' (expected one of {})", *name, quotedList(aovNames()))
                                  : fmt::format("unknown AOV '{}'{}", *name, suggestion));
    }
  }

  // "adaptive": true | false | {"threshold": t > 0, "minSpp": n in [1, spp]} (docs/shot-format.md,
  // "Adaptive sampling"); "spp" is then each pixel's maximum.
  void readAdaptive(ObjectReader& render, RenderSettings& s) {
    const Json* v = render.find("adaptive");
    if (!v) return;
    if (v->is_boolean()) {
      s.adaptive.enabled = v->get<bool>();
    } else {
      ObjectReader o(c_, *v, render.at("adaptive"), {"threshold", "minSpp"});
      s.adaptive.enabled = true;
      if (auto x = o.number("threshold", Range::openClosed(0, 1))) s.adaptive.threshold = float(*x);
      if (auto x = o.integer("minSpp", Range::atLeast(1))) {
        if (*x > s.samplesPerPixel)
          o.error("minSpp", fmt::format("minSpp {} is more than spp {}, each pixel's maximum under adaptive sampling",
                                        *x, s.samplesPerPixel));
        else
          s.adaptive.minSamples = int(*x);
      }
    }
    s.adaptive.minSamples = std::min(s.adaptive.minSamples, s.samplesPerPixel);  // the default 16 under a small spp
  }

  // "bounces": {"diffuse": n, "glossy": n, "transmission": n}, each 0-1024; a kind left out has no
  // limit (docs/shot-format.md, "Bounce limits").
  void readBounces(ObjectReader& render, RenderSettings& s) {
    const Json* v = render.find("bounces");
    if (!v) return;
    ObjectReader o(c_, *v, render.at("bounces"), {"diffuse", "glossy", "transmission"});
    const auto range = Range::closed(0, BounceLimits::kUnlimited);
    if (auto x = o.integer("diffuse", range)) s.bounces.diffuse = int(*x);
    if (auto x = o.integer("glossy", range)) s.bounces.glossy = int(*x);
    if (auto x = o.integer("transmission", range)) s.bounces.transmission = int(*x);
  }

  // "method": "randomWalk" | "diffusion" of a skin's "subsurface" (docs/shot-format.md, "Skin").
  void readSubsurfaceMethod(ObjectReader& o, SubsurfaceParams& subsurface) {
    static constexpr SubsurfaceMethod methods[] = {SubsurfaceMethod::RandomWalk, SubsurfaceMethod::Diffusion};
    if (const auto i = readChoice(o, "method", kSubsurfaceMethods, "subsurface method")) subsurface.method = methods[*i];
  }

  // "sampler": "sobol" | "independent" (docs/shot-format.md, "Sampling").
  void readSampler(ObjectReader& o, RenderSettings& s) {
    static constexpr SamplerKind kinds[] = {SamplerKind::Sobol, SamplerKind::Independent};
    if (const auto i = readChoice(o, "sampler", kSamplerKinds, "sampler")) s.sampler = kinds[*i];
  }

  // "filter": {"type": "blackman-harris" | "gaussian" | "mitchell" | "box", "width": full width in
  // pixels} (docs/shot-format.md, "Pixel filter"). The width defaults per type.
  void readFilter(ObjectReader& render, RenderSettings& s) {
    const Json* v = render.find("filter");
    if (!v) return;
    const auto type = readType(*v, render.at("filter"), kFilterTypes, "filter");
    if (!type) return;
    ObjectReader o(c_, *v, render.at("filter"), {"type", "width"});
    static constexpr FilterType types[] = {FilterType::BlackmanHarris, FilterType::Gaussian, FilterType::Mitchell,
                                           FilterType::Box};
    PixelFilter filter;
    filter.type = types[std::find(kFilterTypes.begin(), kFilterTypes.end(), *type) - kFilterTypes.begin()];
    filter.width = defaultFilterWidth(filter.type);
    if (auto x = o.number("width", Range::openClosed(0, kMaxFilterWidth))) filter.width = float(*x);
    s.filter = filter;
  }

  // "caustics": "mnee" | "straight" | "off" (docs/shot-format.md, "Caustics").
  void readCaustics(ObjectReader& o, RenderSettings& s) {
    static constexpr Caustics modes[] = {Caustics::Mnee, Caustics::Straight, Caustics::Off};
    const auto i = readChoice(o, "caustics", kCausticsModes, "caustics mode");
    if (i) s.caustics = modes[*i];
  }

  // ---- materials ---------------------------------------------------------------------------

  void readMaterials(const Json& v) {
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

  void readMaterial(const Json& v, const std::string& pointer, Material& m) {
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

  // "textures": {"<role>": file or {"file": file[, "colorSpace": ...]}} with the roles `roles`
  // (docs/shot-format.md). Each file must exist and open as an image.
  void readTextures(ObjectReader& material, const std::vector<std::string>& roles, MaterialTextures& textures) {
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
  std::optional<IrisPatternParams> readAlbedoPattern(const Json& v, const std::string& pointer) {
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
  std::optional<TextureMap> readTextureMap(const Json& v, const std::string& pointer, bool colour) {
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
    map.file = resolve(*file);
    if (!checkExists(filePointer, *file, map.file) || !checkImageReadable(filePointer, *file, map.file)) return std::nullopt;
    return map;
  }

  // Opens the image header with OIIO: a file that exists but is no image is reported here, not
  // halfway through a render.
  bool checkImageReadable(const std::string& pointer, const std::string& written, const fs::path& resolved) {
    if (OIIO::ImageInput::open(resolved.string())) return true;
    std::string reason = OIIO::geterror();
    if (const size_t newline = reason.find('\n'); newline != std::string::npos) reason.resize(newline);
    c_.error(pointer, Anchor::Value, fmt::format("not a readable image: '{}'{}: {}", written,
                                                 written == resolved.string() ? "" : " (resolved to '" + resolved.string() + "')",
                                                 reason));
    return false;
  }

  // ---- transforms --------------------------------------------------------------------------

  std::optional<Mat3> readRotation(const Json& v, const std::string& pointer) {
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

  ShotTransform readTransform(const Json& v, const std::string& pointer) {
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

  // A required [x, y, z] member that may be keyed.
  std::optional<AnimatedVec3> readAnimatedMember(ObjectReader& o, const std::string& key) {
    const Json* v = o.find(key);
    if (!v) {
      o.missing(key, "[x, y, z], or keys {\"keys\": [[frame, [x, y, z]], ...]}");
      return std::nullopt;
    }
    return readAnimatedVec3(c_, *v, o.at(key));
  }

  // {"open": frames, "close": frames} relative to each frame.
  void readShutter(const Json& v, const std::string& pointer) {
    ObjectReader o(c_, v, pointer, {"open", "close"});
    const auto open = o.number("open", Range::closed(-1, 1), true);
    const auto close = o.number("close", Range::closed(-1, 1), true);
    if (!open || !close) return;
    if (*close < *open) {
      o.error("close", fmt::format("the shutter must close after it opens: close {} < open {}", *close, *open));
      return;
    }
    shot_.shutter = std::make_pair(*open, *close);
  }

  // The required "asset" and "part" members of o: the index of the asset, or nullopt (reported).
  std::optional<size_t> readAssetPart(ObjectReader& o, std::string& partOut) {
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
    const ShotAsset& asset = shot_.assets[*index];
    if (!asset.gltf) return std::nullopt;  // its loading error is reported
    std::vector<std::string> parts;
    for (const GltfPrimitive& p : asset.gltf->primitives) appendUnique(parts, p.part);
    if (std::find(parts.begin(), parts.end(), *part) == parts.end()) {
      o.error("part", fmt::format("asset '{}' has no part '{}'{}", *assetName, *part,
                                  suggestionOrList(*part, parts, "its parts", "it has no primitives")));
      return std::nullopt;
    }
    partOut = *part;
    return index;
  }

  // {"asset": name, "part": part name}: the shape follows that part's surface.
  void readAttachment(const Json& v, const std::string& pointer, ShotShape& shape) {
    ObjectReader o(c_, v, pointer, {"asset", "part"});
    std::string part;
    if (const auto index = readAssetPart(o, part)) {
      shape.attachAsset = shot_.assets[*index].name;
      shape.attachPart = part;
    }
  }

  // ---- assets ------------------------------------------------------------------------------

  void readAsset(const Json& v, const std::string& pointer) {
    ObjectReader o(c_, v, pointer,
                   {"name", "file", "transform", "materials", "blendshapes", "hide", "rig", "joints", "controls",
                    "performance", "animation"});
    if (!o.ok()) return;
    ShotAsset asset;
    const auto file = o.string("file", true);
    const auto name = o.string("name");
    asset.name = name ? *name : file ? fs::path(*file).stem().string() : "";
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

  void assignPrimitiveMaterials(ShotAsset& asset) {
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

  // A textured material on a mesh without uvs shades with its constants there: said once per mesh.
  void warnTexturesWithoutUvs(const std::string& pointer, uint32_t materialId, const std::string& what) {
    if (materialId >= shot_.materials.size() || !shot_.materials[materialId].textures.any()) return;
    shot_.warnings.push_back(c_.warning(pointer, Anchor::Value,
                                        fmt::format("{} has no uvs: the textures of material '{}' are skipped there",
                                                    what, shot_.materials[materialId].name)));
  }

  void warnTexturedPrimitivesWithoutUvs(const ShotAsset& asset, const std::string& pointer) {
    const std::vector<GltfPrimitive>& primitives = asset.gltf->primitives;
    for (size_t i = 0; i < primitives.size() && i < asset.primitiveMaterials.size(); ++i)
      if (primitives[i].mesh.uvs.empty() && asset.primitiveMaterials[i] >= 0)
        warnTexturesWithoutUvs(pointer, uint32_t(asset.primitiveMaterials[i]),
                               fmt::format("primitive '{}' of asset '{}'", primitives[i].name, asset.name));
  }

  // ---- camera ------------------------------------------------------------------------------

  bool readCamera(const Json& v) {
    // Counted before the reader: an unknown key it reports ("FOV", did you mean 'fov'?) stands in
    // for the missing 'fov', which is then not reported again (found by tools/hardening.sh: the
    // camera was derived without a field of view and crashed).
    const size_t before = c_.errorCount();
    ObjectReader o(
        c_, v, "/camera",
        {"position", "lookAt", "up", "gltf", "fov", "focalLength", "sensorHeight", "fStop", "focusDistance",
         "focus", "shutter"});
    if (!o.ok()) return false;
    ShotCamera& cam = shot_.camera;
    const GltfCamera* gltfCamera = nullptr;
    const ShotAsset* gltfAsset = nullptr;

    if (const Json* g = o.find("gltf")) {
      cam.kind = ShotCamera::Kind::Gltf;
      for (const char* key : {"position", "lookAt", "up"})
        if (o.has(key))
          o.error(key,
                  fmt::format("'{}' cannot be combined with 'gltf': the glTF camera gives the position and "
                              "orientation",
                              key),
                  Anchor::Key);
      ObjectReader go(c_, *g, o.at("gltf"), {"asset", "camera"});
      const auto assetName = go.string("asset", true);
      const auto cameraName = go.string("camera", true);
      if (assetName) {
        cam.gltfAsset = *assetName;
        std::vector<std::string> assetNames;
        for (const ShotAsset& a : shot_.assets) {
          assetNames.push_back(a.name);
          if (a.name == *assetName) gltfAsset = &a;
        }
        if (!gltfAsset)
          go.error("asset", fmt::format("undefined asset '{}'{}", *assetName,
                                        suggestionOrList(*assetName, assetNames, "assets", "the shot has no assets")));
      }
      if (cameraName) cam.gltfCamera = *cameraName;
      if (cameraName && gltfAsset && gltfAsset->gltf) {
        std::vector<std::string> cameraNames;
        for (const GltfCamera& gc : gltfAsset->gltf->cameras) {
          cameraNames.push_back(gc.name);
          if (gc.name == *cameraName && !gltfCamera) gltfCamera = &gc;
        }
        if (!gltfCamera)
          go.error("camera",
                   fmt::format("asset '{}' has no camera '{}'{}", gltfAsset->name, *cameraName,
                               suggestionOrList(*cameraName, cameraNames, "its cameras", "it has no cameras")));
      }
    } else {
      cam.kind = ShotCamera::Kind::LookAt;
      // Position and look-at point may be keyed; the checks below apply to their first keys.
      const auto animatedPosition = readAnimatedMember(o, "position");
      const auto animatedLookAt = readAnimatedMember(o, "lookAt");
      const auto position = animatedPosition ? std::optional<Vec3>(animatedPosition->constant) : std::nullopt;
      const auto lookAt = animatedLookAt ? std::optional<Vec3>(animatedLookAt->constant) : std::nullopt;
      const auto up = o.vec3("up");
      if (animatedPosition) cam.animatedPosition = *animatedPosition;
      if (animatedLookAt) cam.animatedLookAt = *animatedLookAt;
      if (position) cam.position = *position;
      if (lookAt) cam.lookAt = *lookAt;
      if (up) cam.up = *up;
      if (position && lookAt) {
        const Vec3 view = *lookAt - *position;
        if (!(view.norm() > 0.0f))
          o.error("lookAt", "'lookAt' must differ from 'position'");
        else if (up && parallel(view, *up))
          o.error("up", "'up' must not be parallel to the view direction (lookAt - position)");
        else if (!o.has("up") && parallel(view, cam.up))
          o.error("lookAt", "the view direction is parallel to the default 'up' [0, 1, 0]; give 'up'");
      }
    }

    const auto fov = o.number("fov", Range::open(0, 180));
    const auto focalLength = o.number("focalLength", Range::above(0));
    const auto sensorHeight = o.number("sensorHeight", Range::above(0));
    const auto fStop = o.number("fStop", Range::above(0));
    const auto focusDistance = o.number("focusDistance", Range::above(0));
    if (o.has("fov") && o.has("focalLength"))
      o.error("focalLength", "give either 'fov' or 'focalLength', not both", Anchor::Key);
    else if (!o.has("fov") && !o.has("focalLength") && cam.kind == ShotCamera::Kind::LookAt)
      o.missing("fov", "vertical field of view in degrees; or 'focalLength' in mm");
    const auto focus = readChoice(o, "focus", {"lookAt", "surface"}, "focus");
    const bool focusOnSurface = focus && *focus == 1;
    if (o.has("focus") && o.has("focusDistance"))
      o.error("focus", "give either 'focusDistance' or 'focus', not both", Anchor::Key);
    else if (fStop && !o.has("focusDistance") && !focusOnSurface && cam.kind == ShotCamera::Kind::Gltf)
      o.missing("focusDistance",
                "metres; with 'fStop', a glTF camera has no look-at point to focus on: give it, or "
                "\"focus\": \"surface\"");
    if (fov) cam.fovDegrees = float(*fov);
    if (focalLength) cam.focalLengthMm = float(*focalLength);
    if (sensorHeight) cam.sensorHeightMm = float(*sensorHeight);
    if (fStop) cam.fStop = float(*fStop);
    if (focusDistance) cam.focusDistance = float(*focusDistance);
    cam.focusOnSurface = focusOnSurface;
    if (focusOnSurface && !fStop)
      shot_.warnings.push_back(c_.warning(o.at("focus"), Anchor::Value,
                                          "'focus' has no effect without 'fStop': a pinhole camera has everything "
                                          "in focus"));
    if (const Json* s = o.find("shutter")) readShutter(*s, o.at("shutter"));

    if (c_.errorCount() != before) return false;
    // An asset that failed to load has no cameras; its own error is already reported.
    if (cam.kind == ShotCamera::Kind::Gltf && (!gltfAsset || !gltfCamera)) return false;
    deriveCamera(cam, gltfAsset, gltfCamera);
    return true;
  }

  static void deriveCamera(ShotCamera& cam, const ShotAsset* asset, const GltfCamera* gltfCamera) {
    Camera& out = cam.camera;
    float viewDistance = 1.0f;
    if (cam.kind == ShotCamera::Kind::LookAt) {
      out.cameraToWorld = *lookAtCameraToWorld(cam.position, cam.lookAt, cam.up);
      viewDistance = (cam.lookAt - cam.position).norm();
    } else {
      // The asset's transform applies; its scale does not scale the camera.
      const Affine3 full = asset->transform.matrix() * gltfCamera->cameraToAsset;
      out.cameraToWorld = Affine3::Identity();
      out.cameraToWorld.linear() = full.rotation();
      out.cameraToWorld.translation() = full.translation();
    }
    if (cam.fovDegrees)
      out.verticalFovRadians = degreesToRadians(*cam.fovDegrees);
    else if (cam.focalLengthMm)
      out.verticalFovRadians = 2.0f * std::atan(cam.sensorHeightMm / (2.0f * *cam.focalLengthMm));
    else
      out.verticalFovRadians = gltfCamera->yfovRadians;
    out.focusDistance = cam.focusDistance.value_or(viewDistance);
    out.focusOnSurface = cam.focusOnSurface;
    out.lensRadius = 0.0f;
    if (cam.fStop) {
      const float focalLengthMm =
          cam.focalLengthMm.value_or(cam.sensorHeightMm / (2.0f * std::tan(0.5f * out.verticalFovRadians)));
      out.lensRadius = focalLengthMm * 1e-3f / (2.0f * *cam.fStop);
    }
  }

  // ---- environment -------------------------------------------------------------------------

  void readEnvironment(const Json& v) {
    ObjectReader o(c_, v, "/environment", {"file", "intensity", "rotation"});
    if (!o.ok()) return;
    ShotEnvironment env;
    const auto file = o.string("file", true);
    if (auto x = o.number("intensity", Range::atLeast(0))) env.intensity = float(*x);
    if (auto x = o.number("rotation", Range::any())) env.rotationDegrees = float(*x);
    if (file) {
      env.file = resolve(*file);
      if (checkExists(o.at("file"), *file, env.file)) {
        try {
          env.map = std::make_shared<const EnvironmentMap>(
              EnvironmentMap::load(env.file, env.intensity, degreesToRadians(env.rotationDegrees)));
          if (const size_t clamped = env.map->clampedTexelCount())
            shot_.warnings.push_back(c_.warning(
                o.at("file"), Anchor::Value,
                fmt::format("{}: {} texel{} NaN, infinite or negative, set to 0", env.file.string(), clamped,
                            clamped == 1 ? " was" : "s were")));
        } catch (const std::exception& e) {
          o.error("file", fmt::format("cannot load the environment map: {}", e.what()));
        }
      }
    }
    shot_.environment = std::move(env);
  }

  // ---- lights and shapes -------------------------------------------------------------------

  // Rectangle geometry: edges 'u' and 'v', or 'size' with 'normal' or 'lookAt' (and 'up').
  std::optional<RectangleEdges> readRectangle(ObjectReader& o, const Vec3* center) {
    const bool byEdges = o.has("u") || o.has("v");
    if (byEdges) {
      bool mixed = false;
      for (const char* key : {"size", "normal", "lookAt", "up"})
        if (o.has(key)) {
          o.error(key, fmt::format("'{}' cannot be combined with the edges 'u' and 'v'", key), Anchor::Key);
          mixed = true;
        }
      const auto u = o.vec3("u", true);
      const auto v = o.vec3("v", true);
      if (!u || !v || mixed) return std::nullopt;
      if (parallel(*u, *v)) {
        o.error("v", "the edges 'u' and 'v' are parallel or zero: the rectangle has no area");
        return std::nullopt;
      }
      return RectangleEdges{*u, *v};
    }
    std::optional<Vec2> size;
    if (const Json* s = o.find("size"))
      size = readVec2(o.checker(), *s, o.at("size"), Range::above(0), "[width, height]");
    else
      o.missing("size", "[width, height] with 'normal' or 'lookAt'; or the edge vectors 'u' and 'v'");
    const auto normal = o.vec3("normal");
    const auto lookAt = o.vec3("lookAt");
    const auto up = o.vec3("up");
    std::optional<Vec3> facing;
    if (o.has("normal") && o.has("lookAt")) {
      o.error("lookAt", "give either 'normal' or 'lookAt', not both", Anchor::Key);
      return std::nullopt;
    }
    if (!o.has("normal") && !o.has("lookAt")) {
      o.missing("normal", "the direction the rectangle faces; or 'lookAt', a point it faces");
      return std::nullopt;
    }
    if (normal) {
      if (!(normal->norm() > 0.0f))
        o.error("normal", "expected a non-zero direction, found [0, 0, 0]");
      else
        facing = normal->normalized();
    }
    if (lookAt && center) {
      if (!((*lookAt - *center).norm() > 0.0f))
        o.error("lookAt", "'lookAt' must differ from 'center'");
      else
        facing = (*lookAt - *center).normalized();
    }
    if (up && facing && parallel(*up, *facing)) {
      o.error("up", "'up' must not be parallel to the direction the rectangle faces");
      return std::nullopt;
    }
    if (!size || !facing || (o.has("up") && !up)) return std::nullopt;
    return rectangleFacing(*facing, up.value_or(Vec3(0, 1, 0)), *size);
  }

  void readLight(const Json& v, const std::string& pointer) {
    const auto type = readType(v, pointer, kLightTypes, "light");
    if (!type) return;
    const bool rectangle = *type == "rectangle";
    ObjectReader o(c_, v, pointer,
                   rectangle ? std::vector<std::string>{"type", "center", "u", "v", "size", "normal", "lookAt", "up",
                                                        "radiance", "power", "twoSided", "intensity", "lightGroup"}
                             : std::vector<std::string>{"type", "center", "radius", "radiance", "power", "intensity",
                                                        "lightGroup"});
    const size_t before = c_.errorCount();
    AreaLight light;
    light.shape = rectangle ? AreaLight::Shape::Rectangle : AreaLight::Shape::Sphere;
    if (auto group = o.string("lightGroup")) {
      if (group->empty()) o.error("lightGroup", "expected a light group's name, found \"\"");
      light.group = *group;
    }
    // A keyed center moves the light; its orientation is the one at the first key.
    const auto animatedCenter = readAnimatedMember(o, "center");
    const auto center = animatedCenter ? std::optional<Vec3>(animatedCenter->constant) : std::nullopt;
    if (center) light.center = *center;
    float area = 0.0f;
    if (rectangle) {
      if (const auto edges = readRectangle(o, center ? &*center : nullptr)) {
        light.edgeU = edges->edgeU;
        light.edgeV = edges->edgeV;
        area = light.edgeU.cross(light.edgeV).norm();
      }
      if (auto x = o.boolean("twoSided")) light.twoSided = *x;
    } else {
      if (auto x = o.number("radius", Range::above(0), true)) light.radius = float(*x);
      area = 4.0f * kPi * light.radius * light.radius;
    }

    const Range nonNegative = Range::atLeast(0);
    if (o.has("radiance") && o.has("power")) {
      o.error("power", "give either 'radiance' or 'power', not both", Anchor::Key);
    } else if (const Json* r = o.find("radiance")) {
      if (auto x = readColor(c_, *r, o.at("radiance"), nonNegative)) light.radiance = *x;
    } else if (const Json* p = o.find("power")) {
      std::optional<Color> watts;
      if (p->is_number()) {
        if (auto x = readNumber(c_, *p, o.at("power"), nonNegative)) watts = Color::Constant(float(*x));
      } else if (p->is_array()) {
        watts = readColor(c_, *p, o.at("power"), nonNegative);
      } else {
        o.error("power", "expected watts: a number >= 0 or [r, g, b] (each >= 0), found " + describeValue(*p));
      }
      // Lambertian emitter: power = radiance * pi * area per emitting side.
      if (watts && area > 0.0f) light.radiance = *watts / (kPi * area * (light.twoSided ? 2.0f : 1.0f));
    } else if (o.ok()) {
      o.missing("radiance", "[r, g, b] in W/(m^2 sr); or 'power' in watts");
    }
    // A multiplier of the radiance, keyed to dim or flicker a light over the shot.
    AnimatedFloat intensity{1.0f, nullptr};
    if (const Json* i = o.find("intensity"))
      if (auto x = readAnimatedNumber(c_, *i, o.at("intensity"), Range::atLeast(0))) intensity = *x;
    // animatedCenter is checked too: a missing center is not always an error yet here (with a
    // misspelt key such as "centcr" the object's unknown-key error comes later, from o).
    if (c_.errorCount() == before && animatedCenter) shot_.lights.push_back({light, animatedCenter->curve, intensity});
  }

  void readShape(const Json& v, const std::string& pointer) {
    const auto type = readType(v, pointer, kShapeTypes, "shape");
    if (!type) return;
    ShotShape shape;
    std::vector<std::string> keys;
    if (*type == "sphere") {
      shape.type = ShotShape::Type::Sphere;
      keys = {"type", "center", "radius", "material", "attach"};
    } else if (*type == "ellipsoid") {
      shape.type = ShotShape::Type::Ellipsoid;
      keys = {"type", "center", "radii", "rotate", "material", "attach"};
    } else {
      shape.type = ShotShape::Type::Rectangle;
      keys = {"type", "center", "u", "v", "size", "normal", "lookAt", "up", "material", "attach"};
    }
    ObjectReader o(c_, v, pointer, keys);
    const size_t before = c_.errorCount();
    const auto animatedCenter = readAnimatedMember(o, "center");
    const auto center = animatedCenter ? std::optional<Vec3>(animatedCenter->constant) : std::nullopt;
    if (center) shape.center = *center;
    if (animatedCenter) shape.centerCurve = animatedCenter->curve;
    if (const Json* a = o.find("attach")) readAttachment(*a, o.at("attach"), shape);
    if (shape.type == ShotShape::Type::Sphere) {
      if (auto x = o.number("radius", Range::above(0), true)) shape.radius = float(*x);
    } else if (shape.type == ShotShape::Type::Ellipsoid) {
      if (auto x = o.vec3("radii", true, Range::above(0))) shape.radii = *x;
      if (const Json* r = o.find("rotate"))
        if (auto x = readRotation(*r, o.at("rotate"))) shape.rotation = *x;
    } else {
      if (const auto edges = readRectangle(o, center ? &*center : nullptr)) {
        shape.edgeU = edges->edgeU;
        shape.edgeV = edges->edgeV;
      }
    }
    if (const Json* m = o.find("material")) {
      const int id = materialReference(*m, o.at("material"));
      if (id >= 0) {
        shape.material = m->get<std::string>();
        shape.materialId = uint32_t(id);
        if (shape.type != ShotShape::Type::Rectangle)  // spheres and ellipsoids have no uvs
          warnTexturesWithoutUvs(o.at("material"), shape.materialId,
                                 shape.type == ShotShape::Type::Sphere ? "this sphere" : "this ellipsoid");
      }
    } else {
      o.missing("material", "the name of a material in 'materials'");
    }
    if (c_.errorCount() == before) shot_.shapes.push_back(shape);
  }

  // ---- tears and details -------------------------------------------------------------------

  // A required surface anchor member (see surface_anchor.hpp).
  void readAnchor(ObjectReader& o, const std::string& key, size_t asset, const std::string& part,
                  ShotSurfaceAnchor& anchor) {
    const Json* v = o.find(key);
    if (!v) {
      o.missing(key, "a point [x, y, z] near the skin, {\"landmark\": i}, {\"vertex\": i} or {\"uv\": [u, v]}");
      return;
    }
    if (auto x = readSurfaceAnchor(c_, *v, o.at(key), shot_.assets[asset], part)) anchor = *x;
  }

  // A required shot-material member; false when missing or undefined (reported).
  bool readMaterialMember(ObjectReader& o, std::string& name, uint32_t& id) {
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

  void readTear(const Json& v, const std::string& pointer) {
    const auto type = readType(v, pointer, kTearTypes, "tear");
    if (!type) return;
    if (*type == "shedding") {
      readSheddingTear(v, pointer);
      return;
    }
    if (*type == "liquid") {
      readLiquidTear(v, pointer);
      return;
    }
    ObjectReader o(c_, v, pointer,
                   {"type", "asset", "part", "start", "startFrame", "alpha", "beta", "lambda", "headAngle", "minTime",
                    "gravity", "material", "rings", "segments"});
    if (!o.ok()) return;
    const size_t before = c_.errorCount();
    ShotTear tear;
    const auto asset = readAssetPart(o, tear.part);
    if (asset) tear.asset = *asset;
    if (asset) readAnchor(o, "start", *asset, tear.part, tear.start);
    if (auto x = o.number("startFrame", Range::any(), true)) tear.startFrame = *x;
    if (auto x = o.number("alpha", Range::above(0), true)) tear.params.alpha = float(*x);
    if (auto x = o.number("beta", Range::above(0), true)) tear.params.beta = float(*x);
    if (auto x = o.number("lambda", Range::any(), true)) tear.params.lambda = float(*x);
    if (auto x = o.number("headAngle", Range::openClosed(0, 1.5))) tear.params.headAngle = float(*x);
    if (auto x = o.number("minTime", Range::above(0))) tear.params.minTime = float(*x);
    if (auto x = o.vec3("gravity")) {
      if (*x == Vec3::Zero())
        o.error("gravity", "the gravity direction must not be zero");
      else
        tear.gravity = *x;
    }
    if (auto x = o.integer("rings", Range::closed(2, 1024))) tear.rings = int(*x);
    if (auto x = o.integer("segments", Range::closed(3, 1024))) tear.segments = int(*x);
    readMaterialMember(o, tear.material, tear.materialId);
    if (c_.errorCount() == before && asset) shot_.tears.push_back(tear);
  }

  // "path": [[x, y, z], ...], at least two points.
  void readTearPath(ObjectReader& o, std::vector<Vec3>& path) {
    const Json* v = o.find("path");
    if (!v) {
      o.missing("path", "[[x, y, z], ...], two or more points near the skin that the tear runs through");
      return;
    }
    if (!v->is_array() || v->size() < 2) {
      o.error("path", "expected an array of two or more points [[x, y, z], ...], found " + describeValue(*v));
      return;
    }
    for (size_t i = 0; i < v->size(); ++i)
      if (auto p = readVec3(c_, (*v)[i], childPointer(o.at("path"), i))) path.push_back(*p);
  }

  // Lin & Cheng 2013 section 4.2: a strip of water shed along a path over the skin (ShotSheddingTear).
  void readSheddingTear(const Json& v, const std::string& pointer) {
    ObjectReader o(c_, v, pointer,
                   {"type", "asset", "part", "path", "startFrame", "material", "width", "thickness", "start", "speed",
                    "headLength", "headBulge", "tipFraction", "tailLength", "skinRoughness", "noiseAmplitude", "smoothingEpsilon",
                    "smoothingDegree", "sampleSpacing", "acrossSamples", "baseOffset", "seed"});
    if (!o.ok()) return;
    const size_t before = c_.errorCount();
    ShotSheddingTear tear;
    tear.pointer = pointer;
    const auto asset = readAssetPart(o, tear.part);
    if (asset) tear.asset = *asset;
    readTearPath(o, tear.path);
    if (auto x = o.number("startFrame", Range::any(), true)) tear.startFrame = *x;
    SheddingTearParams& p = tear.params;
    auto number = [&](const char* key, Range range, float& out) {
      if (auto x = o.number(key, range)) out = float(*x);
    };
    number("width", Range::above(0), p.width);
    number("thickness", Range::above(0), p.thickness);
    number("start", Range::atLeast(0), p.start);
    number("speed", Range::atLeast(0), p.speed);
    number("headLength", Range::atLeast(0), p.headLength);
    number("headBulge", Range::atLeast(0), p.headBulge);
    number("tipFraction", Range::openClosed(0, 1), p.tipFraction);
    number("tailLength", Range::atLeast(0), p.tailLength);
    number("skinRoughness", Range::closed(0, 1), p.noiseDensity);
    number("noiseAmplitude", Range::atLeast(0), p.noiseAmplitude);
    number("smoothingEpsilon", Range::above(0), p.smoothingEpsilon);
    number("sampleSpacing", Range::above(0), p.sampleSpacing);
    number("baseOffset", Range::above(0), p.baseOffset);
    if (auto x = o.integer("smoothingDegree", Range::closed(0, 4))) p.smoothingDegree = int(*x);
    if (auto x = o.integer("acrossSamples", Range::closed(3, 101))) p.acrossSamples = int(*x);
    if (auto x = o.unsignedInteger("seed")) p.seed = *x;
    readMaterialMember(o, tear.material, tear.materialId);
    if (c_.errorCount() == before && asset) shot_.sheddingTears.push_back(tear);
  }

  // A liquid tear: tear fluid welling at a skin point and running down its flow path (ShotLiquidTear).
  // Volumes in microlitres, angles in degrees, welling times in frames, the rest in SI units.
  void readLiquidTear(const Json& v, const std::string& pointer) {
    ObjectReader o(c_, v, pointer,
                   {"type", "asset", "part", "source", "material", "gravity", "maxLength", "rate", "wellStart",
                    "wellEnd", "overflowVolume", "spillVolume", "contactAngles", "filmThickness", "dryingTime",
                    "hangingContactRadius", "overhangAngle", "viscosity", "trailRefinement", "contactAngleRegions",
                    "pinning", "skinTemperature", "airTemperature", "humidity", "rivulet"});
    if (!o.ok()) return;
    const size_t before = c_.errorCount();
    ShotLiquidTear tear;
    tear.pointer = pointer;
    const auto asset = readAssetPart(o, tear.part);
    if (asset) tear.asset = *asset;
    if (asset) readAnchor(o, "source", *asset, tear.part, tear.source);
    if (auto x = o.vec3("gravity")) {
      if (*x == Vec3::Zero())
        o.error("gravity", "the gravity direction must not be zero");
      else
        tear.gravity = *x;
    }
    LiquidTearParams& p = tear.params;
    WellingSource& source = p.source;
    if (auto x = o.number("maxLength", Range::above(0))) tear.maxLength = float(*x);
    readWellingTimes(o, tear);
    readWellingRate(o, tear);
    if (auto x = o.number("overflowVolume", Range::above(0))) source.overflowVolume = *x * kMicrolitre;
    if (auto x = o.number("spillVolume", Range::above(0))) {
      if (*x * kMicrolitre > source.overflowVolume)
        o.error("spillVolume", fmt::format("the spill volume ({} uL) must not exceed the overflow volume ({} uL)", *x,
                                           source.overflowVolume / kMicrolitre));
      else
        source.spillVolume = *x * kMicrolitre;
    }
    readContactAngles(o, p.contactAngles);
    if (asset) readContactAngleRegions(o, *asset, tear);
    if (auto x = o.number("filmThickness", Range::above(0))) p.filmThickness = *x;
    if (auto x = o.number("dryingTime", Range::above(0))) p.filmDryingTime = *x;
    // The film's evaporation (film_evaporation.hpp): degrees C and relative humidity.
    if (auto x = o.number("skinTemperature", Range::closed(-20, 50))) p.air.skinTemperature = *x;
    if (auto x = o.number("airTemperature", Range::closed(-20, 50))) p.air.airTemperature = *x;
    if (auto x = o.number("humidity", Range::closed(0, 1))) p.air.relativeHumidity = *x;
    if (auto x = o.number("hangingContactRadius", Range::atLeast(0))) p.hangingContactRadius = *x;
    // A drip site: the skin's normal within this angle of gravity (degrees; LiquidTearParams::overhangCosine).
    if (auto x = o.number("overhangAngle", Range::open(0, 180))) p.overhangCosine = std::cos(*x * std::numbers::pi / 180.0);
    if (auto x = o.number("viscosity", Range::above(0))) p.viscosity = *x;
    if (auto x = o.integer("trailRefinement", Range::closed(0, 3))) tear.trailRefinementLevels = int(*x);
    readPinning(o, tear);
    readRivulet(o, tear.params);
    readMaterialMember(o, tear.material, tear.materialId);
    if (c_.errorCount() == before && asset) shot_.liquidTears.push_back(tear);
  }

  // "wellStart" / "wellEnd": frames (default: from the shot's first frame, for ever). The
  // simulation starts (t = 0) at the earlier of wellStart and the shot's first frame; the welling
  // times are stored in seconds since then.
  void readWellingTimes(ObjectReader& o, ShotLiquidTear& tear) {
    const auto start = o.number("wellStart", Range::any());
    const auto end = o.number("wellEnd", Range::any());
    const double first = double(shot_.frameStart);
    tear.simulationStartFrame = start ? std::min(*start, first) : first;
    WellingSource& source = tear.params.source;
    source.start = ((start ? *start : first) - tear.simulationStartFrame) / shot_.fps;
    if (end) source.end = (*end - tear.simulationStartFrame) / shot_.fps;
    if (end && *end < (start ? *start : first))
      o.error("wellEnd", fmt::format("welling must end at or after it starts: wellEnd {} < {} {}", *end,
                                     start ? "wellStart" : "the shot's first frame", start ? *start : first));
  }

  // "rate": uL/s >= 0, or keys {"keys": [[frame, uL/s], ...], "interpolation": ...} for crying that
  // swells and eases. The simulation integrates the rate exactly over straight pieces: "linear"
  // keys are handed to it as they are, other interpolations as a polyline of kRateKeysPerFrame
  // points a frame between the first and the last key.
  void readWellingRate(ObjectReader& o, ShotLiquidTear& tear) {
    const Json* v = o.find("rate");
    if (!v) return;
    const auto rate = readAnimatedNumber(c_, *v, o.at("rate"), Range::atLeast(0));
    if (!rate) return;
    WellingSource& source = tear.params.source;
    source.rate = double(rate->constant) * kMicrolitre;
    if (!rate->animated()) return;
    constexpr int kRateKeysPerFrame = 8;
    const std::vector<ScalarKey>& keys = rate->curve->keys();
    auto seconds = [&](double frame) { return (frame - tear.simulationStartFrame) / shot_.fps; };
    if (rate->curve->interpolation() == Interpolation::Linear || keys.size() == 1) {
      for (const ScalarKey& key : keys) source.rateKeys.emplace_back(seconds(key.time), double(key.value) * kMicrolitre);
      return;
    }
    const double first = keys.front().time, last = keys.back().time;
    const int pieces = std::max(1, int(std::ceil((last - first) * kRateKeysPerFrame)));
    for (int i = 0; i <= pieces; ++i) {
      const double frame = first + (last - first) * double(i) / double(pieces);
      source.rateKeys.emplace_back(seconds(frame), double(rate->at(frame)) * kMicrolitre);
    }
  }

  // "pinning": {"factor": >= 1, "patchSize": m > 0 (default 4 mm)}: skin that holds the contact
  // line up to `factor` times harder in some patches and as much softer in others.
  void readPinning(ObjectReader& o, ShotLiquidTear& tear) {
    const Json* v = o.find("pinning");
    if (!v) return;
    ObjectReader r(c_, *v, o.at("pinning"), {"factor", "patchSize"});
    if (!r.ok()) return;
    if (auto x = r.number("factor", Range::atLeast(1), true)) tear.pinningFactor = *x;
    if (auto x = r.number("patchSize", Range::above(0))) tear.pinningPatchSize = *x;
  }

  // "rivulet": {"formFlowRate": uL/s > 0, "breakFlowRate": uL/s in (0, formFlowRate] (default half
  // of it)}: welling at formFlowRate or faster runs down as a rivulet (LiquidTearParams::rivulet).
  void readRivulet(ObjectReader& o, LiquidTearParams& p) {
    const Json* v = o.find("rivulet");
    if (!v) return;
    ObjectReader r(c_, *v, o.at("rivulet"), {"formFlowRate", "breakFlowRate"});
    if (!r.ok()) return;
    const auto form = r.number("formFlowRate", Range::above(0), true);
    const auto breaking = r.number("breakFlowRate", Range::above(0));
    if (!form) return;
    if (breaking && *breaking > *form) {
      r.error("breakFlowRate", fmt::format("the rivulet breaks at {} uL/s, above the {} uL/s it forms at; it must not "
                                           "exceed formFlowRate",
                                           *breaking, *form));
      return;
    }
    if (!(p.contactAngles.receding < 0.5 * std::numbers::pi))
      o.error("contactAngles", fmt::format("a rivulet needs a receding contact angle below 90 degrees, got {} degrees",
                                           p.contactAngles.receding * 180.0 / std::numbers::pi));
    p.rivulet.formFlowRate = *form * kMicrolitre;
    if (breaking) p.rivulet.breakFlowRate = *breaking * kMicrolitre;
  }

  // "contactAngles": [advancing, receding] in degrees, 0 < receding <= advancing < 180.
  void readContactAngles(ObjectReader& o, ContactAngleHysteresis& angles) {
    const Json* v = o.find("contactAngles");
    if (!v) return;
    const auto x = readVec2(c_, *v, o.at("contactAngles"), Range::open(0, 180), "[advancing, receding]");
    if (!x) return;
    if (x->y() > x->x()) {
      o.error("contactAngles", fmt::format("the receding angle ({} degrees) must not exceed the advancing angle ({} "
                                           "degrees)", x->y(), x->x()));
      return;
    }
    angles.advancing = double(x->x()) * std::numbers::pi / 180.0;
    angles.receding = double(x->y()) * std::numbers::pi / 180.0;
  }

  // "contactAngleRegions": [{"center": anchor on the tear's part, "radius": m > 0, "contactAngles":
  // [advancing, receding]}, ...]; their angles also go to params.contactAngleRegions (same index).
  void readContactAngleRegions(ObjectReader& o, size_t asset, ShotLiquidTear& tear) {
    const Json* v = o.find("contactAngleRegions");
    if (!v) return;
    if (!v->is_array()) {
      o.error("contactAngleRegions", "expected an array of regions {\"center\", \"radius\", \"contactAngles\"}, found " +
                                         describeValue(*v));
      return;
    }
    for (size_t i = 0; i < v->size(); ++i) {
      ObjectReader r(c_, (*v)[i], childPointer(o.at("contactAngleRegions"), i), {"center", "radius", "contactAngles"});
      if (!r.ok()) continue;
      const size_t before = c_.errorCount();
      ShotContactAngleRegion region;
      readAnchor(r, "center", asset, tear.part, region.center);
      if (auto x = r.number("radius", Range::above(0), true)) region.radius = *x;
      if (!r.has("contactAngles")) r.missing("contactAngles", "[advancing, receding] in degrees");
      readContactAngles(r, region.contactAngles);
      if (c_.errorCount() != before) continue;
      tear.contactAngleRegions.push_back(region);
      tear.params.contactAngleRegions.push_back(region.contactAngles);
    }
  }

  // ---- flesh -------------------------------------------------------------------------------

  // A simulated flesh volume (docs/shot-format.md "flesh"; ShotFlesh).
  void readFlesh(const Json& v, const std::string& pointer) {
    ObjectReader o(c_, v, pointer,
                   {"asset", "part", "regions", "depth", "tetSize", "youngsModulus", "poisson", "density", "damping",
                    "substeps", "material", "integrator"});
    if (!o.ok()) return;
    const size_t before = c_.errorCount();
    ShotFlesh flesh;
    flesh.pointer = pointer;
    const auto asset = readAssetPart(o, flesh.part);
    if (asset) flesh.asset = *asset;
    if (asset) {
      if (o.has("regions"))
        readSkinRegions(o, *asset, flesh.part, flesh.regions);
      else
        o.missing("regions", "an array of regions {\"center\", \"radius\"} of the skin to simulate the flesh under");
    }
    if (auto x = o.number("depth", Range::above(0))) flesh.volume.depth = *x;
    // The largest tetrahedron's edge: TetGen's volume bound is that of a regular tetrahedron.
    if (auto x = o.number("tetSize", Range::above(0))) flesh.volume.maxTetVolume = flesh::regularTetVolume(*x);
    if (auto x = o.number("youngsModulus", Range::above(0))) flesh.youngsModulus = *x;
    if (auto x = o.number("poisson", Range::open(-1, 0.5))) flesh.poissonRatio = *x;
    if (auto x = o.number("density", Range::above(0))) flesh.dynamics.density = *x;
    if (auto x = o.integer("substeps", Range::closed(1, 64))) flesh.substeps = int(*x);
    static constexpr flesh::FleshMaterial materials[] = {flesh::FleshMaterial::FixedCorotated,
                                                         flesh::FleshMaterial::StVenantKirchhoff};
    if (const auto i = readChoice(o, "material", kFleshMaterials, "flesh material")) flesh.material = materials[*i];
    static constexpr flesh::FleshIntegrator integrators[] = {flesh::FleshIntegrator::BackwardEuler,
                                                             flesh::FleshIntegrator::ImplicitMidpoint};
    if (const auto i = readChoice(o, "integrator", kFleshIntegrators, "integrator")) flesh.dynamics.integrator = integrators[*i];
    if (const Json* d = o.find("damping")) {
      ObjectReader r(c_, *d, o.at("damping"), {"mass", "stiffness"});
      if (r.ok()) {
        if (auto x = r.number("mass", Range::atLeast(0))) flesh.dynamics.massDamping = *x;
        if (auto x = r.number("stiffness", Range::atLeast(0))) flesh.dynamics.stiffnessDamping = *x;
      }
    }
    if (c_.errorCount() == before && asset) shot_.flesh.push_back(flesh);
  }

  // ---- sph ---------------------------------------------------------------------------------

  // An SPH liquid (docs/shot-format.md "sph"; ShotSph).
  void readSph(const Json& v, const std::string& pointer) {
    ObjectReader o(c_, v, pointer,
                   {"material", "start", "particleRadius", "drops", "blocks", "colliders", "restDensity", "viscosity",
                    "surfaceTension", "sigma", "adhesion", "gravity", "surface"});
    if (!o.ok()) return;
    const size_t before = c_.errorCount();
    ShotSph liquid;
    liquid.pointer = pointer;
    if (const Json* m = o.find("material")) {
      const int id = materialReference(*m, o.at("material"));
      if (id >= 0) liquid.materialId = uint32_t(id), liquid.material = m->get<std::string>();
    } else {
      o.missing("material", "the name of a material in 'materials' (e.g. one of type 'water')");
    }
    liquid.startFrame = shot_.frameStart;
    Range upToFirstFrame;
    upToFirstFrame.hi = shot_.frameStart;
    if (auto x = o.integer("start", upToFirstFrame)) liquid.startFrame = int(*x);
    sph::FluidParams& f = liquid.fluid;
    // Tear-scale liquid: 0.15 mm particles make a 2 mm drop of ~1,200 particles.
    f.particleRadius = 1.5e-4;
    if (auto x = o.number("particleRadius", Range::above(0))) f.particleRadius = *x;
    if (auto x = o.number("restDensity", Range::above(0))) f.restDensity = *x;
    if (auto x = o.number("viscosity", Range::closed(0, 1))) f.xsphViscosity = *x;
    if (auto x = o.number("surfaceTension", Range::atLeast(0))) f.surfaceTension = *x;
    if (auto x = o.number("sigma", Range::atLeast(0))) {
      if (o.has("surfaceTension"))
        o.error("sigma", "give one of 'sigma' (N/m) and 'surfaceTension' (Akinci et al.'s gamma), not both", Anchor::Key);
      f.surfaceTension = sph::akinciGammaForSigma(*x, f.restDensity, f.particleRadius);
    }
    if (auto x = o.number("adhesion", Range::atLeast(0))) f.adhesion = *x;
    if (auto x = o.vec3("gravity")) f.gravity = x->cast<double>();
    if (const Json* d = o.find("drops"))
      readArray(*d, o.at("drops"), "drops", [&](const Json& e, const std::string& p) { readSphRelease(e, p, true, liquid); });
    if (const Json* b = o.find("blocks"))
      readArray(*b, o.at("blocks"), "blocks", [&](const Json& e, const std::string& p) { readSphRelease(e, p, false, liquid); });
    if (!o.has("drops") && !o.has("blocks"))
      o.error("drops", "an SPH liquid needs at least one of 'drops' or 'blocks' (the fluid it releases)", Anchor::Key);
    if (const Json* c = o.find("colliders"))
      readArray(*c, o.at("colliders"), "colliders", [&](const Json& e, const std::string& p) { readSphCollider(e, p, liquid); });
    if (const Json* s = o.find("surface")) {
      ObjectReader r(c_, *s, o.at("surface"), {"voxelsPerRadius", "smoothing"});
      if (r.ok()) {
        if (auto x = r.number("voxelsPerRadius", Range::closed(0.5, 8))) liquid.voxelsPerRadius = *x;
        if (auto x = r.integer("smoothing", Range::closed(0, 64))) liquid.smoothing = int(*x);
      }
    }
    if (c_.errorCount() == before) shot_.sph.push_back(liquid);
  }

  // A drop {"center", "radius", "velocity", "frame"} or a block {"min", "max", "velocity", "frame"}.
  void readSphRelease(const Json& v, const std::string& pointer, bool drop, ShotSph& liquid) {
    ObjectReader r(c_, v, pointer,
                   drop ? std::vector<std::string>{"center", "radius", "velocity", "frame"}
                        : std::vector<std::string>{"min", "max", "velocity", "frame"});
    if (!r.ok()) return;
    ShotSphRelease release;
    release.frame = liquid.startFrame;
    if (drop) {
      release.kind = ShotSphRelease::Kind::Drop;
      if (auto x = r.vec3("center", true)) release.center = x->cast<double>();
      if (auto x = r.number("radius", Range::above(0), true)) release.radius = *x;
    } else {
      release.kind = ShotSphRelease::Kind::Block;
      const auto lo = r.vec3("min", true), hi = r.vec3("max", true);
      if (lo && hi) {
        if (!((*hi - *lo).minCoeff() > 0.0f)) r.error("max", "must exceed 'min' in every coordinate");
        release.min = lo->cast<double>();
        release.max = hi->cast<double>();
      }
    }
    if (auto x = r.vec3("velocity")) release.velocity = x->cast<double>();
    if (auto x = r.integer("frame", Range::closed(liquid.startFrame, shot_.frameEnd))) release.frame = int(*x);
    liquid.releases.push_back(release);
  }

  // {"shape": index into "shapes"} or {"asset", "part"}: a static collider, as at the first frame.
  void readSphCollider(const Json& v, const std::string& pointer, ShotSph& liquid) {
    if (v.is_object() && v.contains("shape")) {
      ObjectReader r(c_, v, pointer, {"shape"});
      if (!r.ok()) return;
      if (shot_.shapes.empty()) {
        r.error("shape", "the shot has no 'shapes' to collide with (a shape is named by its index in 'shapes')");
        return;
      }
      if (auto x = r.integer("shape", Range::closed(0, double(shot_.shapes.size()) - 1), true)) {
        liquid.colliderShapes.push_back(size_t(*x));
        liquid.colliderShapePointers.push_back(pointer);
      }
      return;
    }
    ObjectReader r(c_, v, pointer, {"asset", "part", "regions"});
    if (!r.ok()) return;
    ShotSph::Part part;
    part.pointer = pointer;
    if (const auto asset = readAssetPart(r, part.part)) {
      part.asset = *asset;
      readSkinRegions(r, *asset, part.part, part.regions);
      liquid.colliderParts.push_back(part);
    }
  }

  // "regions": [{"center": anchor on the part, "radius": m > 0}, ...], at least one (the caller
  // checks that the key is there when it must be).
  void readSkinRegions(ObjectReader& o, size_t asset, const std::string& part, std::vector<ShotSkinRegion>& regions) {
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

  // One basic pattern: {"pattern": name, "alpha", "beta", "gamma"} (the object itself for a
  // single pattern, so it may hold other keys; those are checked by the caller's reader).
  std::optional<BasicDetailPattern> readPattern(ObjectReader& o) {
    const Json* name = o.find("pattern");
    if (!name) {
      o.missing("pattern", "one of " + quotedList(kDetailPatterns));
      return std::nullopt;
    }
    const auto text = readString(c_, *name, o.at("pattern"));
    if (!text) return std::nullopt;
    BasicDetailPattern pattern;
    const auto it = std::find(kDetailPatterns.begin(), kDetailPatterns.end(), *text);
    if (it == kDetailPatterns.end()) {
      const std::string suggestion = didYouMean(*text, kDetailPatterns);
      o.error("pattern", suggestion.empty() ? fmt::format("unknown detail pattern '{}' (expected one of {})", *text,
                                                          quotedList(kDetailPatterns))
                                            : fmt::format("unknown detail pattern '{}'{}", *text, suggestion));
      return std::nullopt;
    }
    static constexpr DetailPatternKind kinds[] = {DetailPatternKind::ForeheadWrinkles, DetailPatternKind::EyeCornerWrinkles,
                                                  DetailPatternKind::CheekWrinkles,    DetailPatternKind::Frown,
                                                  DetailPatternKind::Dimple,           DetailPatternKind::EyePouch};
    pattern.kind = kinds[it - kDetailPatterns.begin()];
    if (auto x = o.number("alpha", Range::any())) pattern.alpha = float(*x);
    if (auto x = o.number("beta", Range::any())) pattern.beta = float(*x);
    if (auto x = o.number("gamma", Range::any())) pattern.gamma = float(*x);
    return pattern;
  }

  // {"levels": 0..4, "scheme": "loop" | "linear"}: the skin refined under the detail.
  void readSubdivision(const Json& v, const std::string& pointer, ShotDetail& detail) {
    ObjectReader o(c_, v, pointer, {"levels", "scheme"});
    if (!o.ok()) return;
    if (auto x = o.integer("levels", Range::closed(0, kMaxSubdivisionLevels), true)) detail.subdivisionLevels = int(*x);
    const auto scheme = o.string("scheme");
    if (!scheme) return;
    const auto it = std::find(kSubdivisionSchemes.begin(), kSubdivisionSchemes.end(), *scheme);
    if (it == kSubdivisionSchemes.end()) {
      const std::string suggestion = didYouMean(*scheme, kSubdivisionSchemes);
      o.error("scheme", fmt::format("unknown subdivision scheme '{}'{}", *scheme,
                                    suggestion.empty() ? " (expected 'loop' or 'linear')" : suggestion));
      return;
    }
    detail.subdivisionScheme = it == kSubdivisionSchemes.begin() ? RefinementScheme::Loop : RefinementScheme::Linear;
  }

  void readDetail(const Json& v, const std::string& pointer) {
    const std::vector<std::string> regionKeys = {"asset",     "part",     "center",        "tangent",
                                                 "extent",    "innerRadius", "scale",      "coordinateScale",
                                                 "startFrame", "endFrame", "amplitude",    "validFraction",
                                                 "seed",      "subdivision", "patternOrigin"};
    const bool sum = v.is_object() && v.contains("patterns");
    std::vector<std::string> keys = regionKeys;
    if (sum)
      keys.push_back("patterns");
    else
      keys.insert(keys.end(), {"pattern", "alpha", "beta", "gamma"});
    ObjectReader o(c_, v, pointer, keys);
    if (!o.ok()) return;
    const size_t before = c_.errorCount();
    ShotDetail detail;
    if (sum) {
      const Json& list = *o.find("patterns");
      if (!list.is_array() || list.empty()) {
        o.error("patterns", "expected a non-empty array of patterns {\"pattern\": name, \"alpha\", \"beta\", "
                            "\"gamma\"}, found " + describeValue(list));
      } else {
        for (size_t i = 0; i < list.size(); ++i) {
          ObjectReader p(c_, list[i], childPointer(o.at("patterns"), i), {"pattern", "alpha", "beta", "gamma"});
          if (!p.ok()) continue;
          if (auto pattern = readPattern(p)) detail.patterns.push_back(*pattern);
        }
      }
    } else if (auto pattern = readPattern(o)) {
      detail.patterns.push_back(*pattern);
    }
    const auto asset = readAssetPart(o, detail.part);
    if (asset) detail.asset = *asset;
    if (asset) readAnchor(o, "center", *asset, detail.part, detail.center);
    if (auto x = o.vec3("tangent")) {
      if (*x == Vec3::Zero())
        o.error("tangent", "the tangent direction must not be zero");
      else
        detail.tangent = *x;
    }
    if (const Json* e = o.find("extent")) {
      if (auto x = readVec2(c_, *e, o.at("extent"), Range::above(0), "[a, b]")) {
        detail.semiAxisA = x->x();
        detail.semiAxisB = x->y();
      }
    } else {
      o.missing("extent", "[a, b], the semi-axes of the region's ellipse in metres");
    }
    if (auto x = o.number("innerRadius", {0, 1, false, true})) detail.innerRadius = float(*x);
    if (auto x = o.number("scale", Range::any(), true)) detail.scale = float(*x);
    if (auto x = o.number("coordinateScale", Range::above(0))) detail.coordinateScale = float(*x);
    if (const Json* origin = o.find("patternOrigin"))
      if (auto x = readVec2(c_, *origin, o.at("patternOrigin"), Range::any(), "[x, y]")) detail.patternOrigin = *x;
    const auto startFrame = o.number("startFrame", Range::any(), true);
    const auto endFrame = o.number("endFrame", Range::any(), true);
    if (startFrame) detail.startFrame = *startFrame;
    if (endFrame) detail.endFrame = *endFrame;
    if (startFrame && endFrame && *endFrame < *startFrame)
      o.error("endFrame", fmt::format("the detail must end at or after its start: endFrame {} < startFrame {}",
                                      *endFrame, *startFrame));
    if (const Json* a = o.find("amplitude"))
      if (auto x = readAnimatedNumber(c_, *a, o.at("amplitude"), Range::atLeast(0))) detail.amplitude = *x;
    if (auto x = o.number("validFraction", Range::closed(0, 1))) detail.selection.fraction = float(*x);
    if (auto x = o.unsignedInteger("seed")) detail.selection.seed = *x;
    if (const Json* s = o.find("subdivision")) readSubdivision(*s, o.at("subdivision"), detail);
    if (c_.errorCount() == before && asset) shot_.details.push_back(detail);
  }
  // ---- eyes --------------------------------------------------------------------------------

  // A required material member named `key`; false when missing or undefined (reported).
  bool readNamedMaterial(ObjectReader& o, const std::string& key, uint32_t& id) {
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

  // An eye for close-ups (ShotEye): the eyeball shell part, its materials and lashes.
  void readEye(const Json& v, const std::string& pointer) {
    ObjectReader o(c_, v, pointer,
                   {"asset", "part", "cornea", "sclera", "iris", "pupil", "limbusRadius", "pupilRadius", "irisDepth",
                    "lashes"});
    if (!o.ok()) return;
    const size_t before = c_.errorCount();
    ShotEye eye;
    eye.pointer = pointer;
    const auto asset = readAssetPart(o, eye.part);
    if (asset) eye.asset = *asset;
    if (readNamedMaterial(o, "cornea", eye.corneaMaterial) &&
        !dielectricMedium(shot_.materials[eye.corneaMaterial].params))
      o.error("cornea", fmt::format("the cornea material '{}' must be clear: of type 'water' or 'rough_dielectric'",
                                    shot_.materials[eye.corneaMaterial].name));
    readNamedMaterial(o, "sclera", eye.scleraMaterial);
    readNamedMaterial(o, "iris", eye.irisMaterial);
    readNamedMaterial(o, "pupil", eye.pupilMaterial);
    // Millimetres in the file: the anatomy is quoted that way.
    if (auto x = o.number("limbusRadius", Range::closed(2, 12))) eye.params.limbusRadius = float(*x) * 1e-3f;
    if (auto x = o.number("pupilRadius", Range::closed(0.5, 5))) eye.params.pupilRadius = float(*x) * 1e-3f;
    if (auto x = o.number("irisDepth", Range::closed(0.5, 8))) eye.params.irisDepth = float(*x) * 1e-3f;
    if (const Json* l = o.find("lashes"); l && asset) readLashes(*l, o.at("lashes"), *asset, eye);
    if (c_.errorCount() == before && asset) shot_.eyes.push_back(std::move(eye));
  }

  void readLashes(const Json& v, const std::string& pointer, size_t asset, ShotEye& eye) {
    ObjectReader o(c_, v, pointer,
                   {"part", "material", "upper", "lower", "rootRadius", "tipRadius", "minLength", "spread", "seed"});
    if (!o.ok()) return;
    ShotLashes lashes;
    const auto part = o.string("part", true);
    if (part) {
      std::vector<std::string> parts;
      for (const GltfPrimitive& p : shot_.assets[asset].gltf->primitives) appendUnique(parts, p.part);
      if (std::find(parts.begin(), parts.end(), *part) == parts.end())
        o.error("part", fmt::format("asset '{}' has no part '{}'{}", shot_.assets[asset].name, *part,
                                    suggestionOrList(*part, parts, "its parts", "it has no primitives")));
      else
        lashes.part = *part;
    }
    readNamedMaterial(o, "material", lashes.materialId);
    LashParams& p = lashes.params;
    if (auto x = o.integer("upper", Range::closed(0, 400))) p.upper = int(*x);
    if (auto x = o.integer("lower", Range::closed(0, 400))) p.lower = int(*x);
    // Micrometres for the radii, millimetres for the drift: the sizes of hair.
    if (auto x = o.number("rootRadius", Range::closed(5, 200))) p.rootRadius = float(*x) * 1e-6f;
    if (auto x = o.number("tipRadius", Range::closed(1, 200))) p.tipRadius = float(*x) * 1e-6f;
    if (auto x = o.number("minLength", Range::openClosed(0, 1))) p.minLength = float(*x);
    if (auto x = o.number("spread", Range::closed(0, 3))) p.spread = float(*x) * 1e-3f;
    if (auto x = o.unsignedInteger("seed")) p.seed = *x;
    if (p.tipRadius > p.rootRadius)
      o.error("tipRadius", fmt::format("the tip radius ({} um) must not exceed the root radius ({} um)",
                                       p.tipRadius * 1e6f, p.rootRadius * 1e6f));
    if (!lashes.part.empty()) eye.lashes = std::move(lashes);
  }
};

}  // namespace

Shot loadShot(const std::filesystem::path& path) {
  return loadShot(path, [](const fs::path& file) { return std::make_shared<const GltfAsset>(loadGltfAsset(file)); });
}

namespace {

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
                                names.empty() ? "" : " (the shot's assets: " + quotedList(names) + ")"));
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

Shot loadShotWith(const std::filesystem::path& path, const GltfAssetLoader& loadAsset,
                  const std::vector<PerformanceOverride>& performances) {
  Shot shot;
  shot.path = path;
  ParsedJsonFile parsed = readJsonFile(path, "the shot file");
  const JsonSource& source = parsed.source;

  Checker checker(path, source);
  for (const DuplicateKey& d : source.duplicateKeys()) {
    const TextPosition first = source.positionOf(d.firstKeyOffset);
    const std::string key = d.pointer.substr(d.pointer.rfind('/') + 1);
    checker.error(d.pointer, Anchor::Key,
                  fmt::format("duplicate key '{}' (first given at line {}, column {})", key, first.line, first.column));
  }
  applyPerformanceOverrides(parsed.json, performances, checker);
  ShotReader(checker, shot, loadAsset).read(parsed.json);
  if (checker.errorCount() > 0) throw ShotError(checker.diagnostics());
  // On the assets as loaded: the flesh volumes' boundaries are the skin's own tessellation.
  std::vector<FleshProblem> fleshProblems = resolveFleshVolumes(shot);
  // Before any surface point is found: they index the refined triangles.
  refineDetailRegions(shot);
  refineLiquidTrails(shot);
  resolveAttachments(shot);
  resolveTearsAndDetails(shot);
  // After the details' surface points, on the assets as they are now (possibly refined).
  for (const SheddingTearProblem& problem : resolveSheddingTears(shot))
    checker.error(problem.pointer, Anchor::Value, problem.message);
  for (const LiquidTearProblem& problem : resolveLiquidTears(shot))
    checker.error(problem.pointer, Anchor::Value, problem.message);
  for (const EyeProblem& problem : resolveEyes(shot)) checker.error(problem.pointer, Anchor::Value, problem.message);
  for (const FleshProblem& problem : fleshProblems) checker.error(problem.pointer, Anchor::Value, problem.message);
  embedFleshSkins(shot);
  for (const SphProblem& problem : resolveSphLiquids(shot)) checker.error(problem.pointer, Anchor::Value, problem.message);
  if (checker.errorCount() > 0) throw ShotError(checker.diagnostics());
  return shot;
}

}  // namespace

Shot loadShot(const std::filesystem::path& path, const GltfAssetLoader& loadAsset) {
  return loadShotWith(path, loadAsset, {});
}

Shot loadShot(const std::filesystem::path& path, const std::vector<PerformanceOverride>& performances) {
  return loadShotWith(
      path, [](const fs::path& file) { return std::make_shared<const GltfAsset>(loadGltfAsset(file)); }, performances);
}

}  // namespace lacrima
