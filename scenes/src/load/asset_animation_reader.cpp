// Rig, joints, animator controls and performance tracks of a shot asset; see the header.
#include "load/asset_animation_reader.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "asset_parts.hpp"
#include "read/animation_reader.hpp"
#include "lacrima/io/performance_track.hpp"
#include "read/suggest.hpp"

namespace lacrima::shotfile {

namespace {

std::string unknownName(const std::string& what, const std::string& name, const std::vector<std::string>& valid) {
  const std::string suggestion = didYouMean(name, valid);
  return suggestion.empty() ? fmt::format("unknown {} '{}'", what, name)
                            : fmt::format("unknown {} '{}'{}", what, name, suggestion);
}

std::vector<std::string> eyeNames(const ShotAsset& asset) {
  std::vector<std::string> names;
  if (asset.rig)
    for (const EyeballSpec& eye : asset.rig->config().eyes) names.push_back(eye.name);
  return names;
}

std::optional<size_t> indexOf(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return std::nullopt;
  return size_t(it - names.begin());
}

// A part name of the asset at `pointer`, or nullopt (reported with the closest part).
std::optional<std::string> readPart(Checker& c, const Json& v, const std::string& pointer, const GltfAsset& gltf) {
  const auto part = readString(c, v, pointer);
  if (!part) return std::nullopt;
  const std::vector<std::string> parts = partNames(gltf);
  if (indexOf(parts, *part)) return part;
  c.error(pointer, Anchor::Value, unknownName("part", *part, parts));
  return std::nullopt;
}

// [{"name": "left", "fit": "M_ScleraLeft", "parts": ["M_ScleraLeft", "M_IrisLeft"]}, ...]
std::vector<EyeballSpec> readEyes(Checker& c, const Json& v, const std::string& pointer, const GltfAsset& gltf) {
  std::vector<EyeballSpec> eyes;
  if (!v.is_array()) {
    c.error(pointer, Anchor::Value, "expected an array of eyes {\"name\", \"fit\", \"parts\"}, found " + describeValue(v));
    return eyes;
  }
  for (size_t i = 0; i < v.size(); ++i) {
    ObjectReader o(c, v[i], childPointer(pointer, i), {"name", "fit", "parts"});
    if (!o.ok()) continue;
    EyeballSpec eye;
    if (auto name = o.string("name", true)) eye.name = *name;
    if (const Json* fit = o.find("fit")) {
      if (auto part = readPart(c, *fit, o.at("fit"), gltf)) eye.spherePart = *part;
    } else {
      o.missing("fit", "the part whose vertices are fitted with a sphere to find the eye's centre, e.g. the sclera");
    }
    if (const Json* parts = o.find("parts")) {
      if (!parts->is_array()) o.error("parts", "expected an array of part names, found " + describeValue(*parts));
      else
        for (size_t k = 0; k < parts->size(); ++k)
          if (auto part = readPart(c, (*parts)[k], childPointer(o.at("parts"), k), gltf)) eye.parts.push_back(*part);
    } else {
      o.missing("parts", "the parts that rotate with the gaze");
    }
    eyes.push_back(std::move(eye));
  }
  return eyes;
}

// {"preset": "ict"} and/or the rig written out: "headPivot", "jawPivot", "jawWeights" (the
// blendshape whose delta sizes weight the jaw) and "eyes". Members override the preset's.
void readRig(ObjectReader& asset, const Json& v, ShotAsset& out) {
  Checker& c = asset.checker();
  ObjectReader o(c, v, asset.at("rig"), {"preset", "headPivot", "jawPivot", "jawWeights", "eyes"});
  if (!o.ok()) return;
  const size_t before = c.errorCount();
  FaceRigConfig config;
  const auto preset = o.string("preset");
  if (preset && *preset != "ict") {
    o.error("preset", unknownName("rig preset", *preset, {"ict"}) + " (this version knows the ICT face rig 'ict')");
    return;
  }
  if (!preset) {
    if (!o.has("headPivot")) o.missing("headPivot", "a point: the head rotates about it (or give \"preset\")");
    if (!o.has("jawPivot")) o.missing("jawPivot", "a point: the jaw hinge (or give \"preset\")");
  }
  if (const Json* w = o.find("jawWeights")) {
    if (auto name = readString(c, *w, o.at("jawWeights"))) {
      if (indexOf(out.gltf->targetNames, *name)) config.jawWeightTarget = *name;
      else c.error(o.at("jawWeights"), Anchor::Value, unknownName("blendshape", *name, out.gltf->targetNames));
    }
  }
  std::vector<EyeballSpec> eyes;
  if (const Json* e = o.find("eyes")) eyes = readEyes(c, *e, o.at("eyes"), *out.gltf);
  const auto headPivot = o.vec3("headPivot");
  const auto jawPivot = o.vec3("jawPivot");
  if (c.errorCount() != before) return;
  try {
    if (preset) config = ictFaceRigConfig(*out.gltf);
    if (const Json* w = o.find("jawWeights")) config.jawWeightTarget = w->get<std::string>();
    if (headPivot) config.headPivot = *headPivot;
    if (jawPivot) config.jawPivot = *jawPivot;
    if (o.has("eyes")) config.eyes = eyes;
    out.rig = std::make_shared<const FaceRig>(*out.gltf, std::move(config));
  } catch (const InputError& e) {
    o.error(preset ? "preset" : "headPivot", fmt::format("cannot build the rig of asset '{}': {}", out.name, e.what()),
            Anchor::Key);
  }
}

// {"name": number or keys, ...} into channels indexed by `names`.
void readChannels(ObjectReader& asset, const std::string& key, const std::vector<std::string>& names,
                  const std::string& what, Range range, std::vector<AssetChannel>& out) {
  Checker& c = asset.checker();
  const Json& v = *asset.find(key);
  if (!v.is_object()) {
    asset.error(key, fmt::format("expected an object mapping {} names to values, found {}", what, describeValue(v)));
    return;
  }
  for (const auto& item : v.items()) {
    const std::string pointer = childPointer(asset.at(key), item.key());
    const auto index = indexOf(names, item.key());
    if (!index) c.error(pointer, Anchor::Key, unknownName(what, item.key(), names));
    const auto value = readAnimatedNumber(c, item.value(), pointer, range);
    if (index && value) out.push_back(AssetChannel{item.key(), *index, *value});
  }
}

// {"name": gain, ...} of one control.
std::vector<ControlMapping> readGains(Checker& c, const Json& v, const std::string& pointer,
                                      const std::vector<std::string>& names, const std::string& what) {
  std::vector<ControlMapping> gains;
  if (!v.is_object()) {
    c.error(pointer, Anchor::Value, fmt::format("expected an object mapping {} names to gains, found {}", what,
                                                describeValue(v)));
    return gains;
  }
  for (const auto& item : v.items()) {
    const std::string p = childPointer(pointer, item.key());
    if (!indexOf(names, item.key())) c.error(p, Anchor::Key, unknownName(what, item.key(), names));
    if (auto gain = readNumber(c, item.value(), p, Range::any())) gains.push_back({item.key(), float(*gain)});
  }
  return gains;
}

void readControls(ObjectReader& asset, ShotAsset& out) {
  Checker& c = asset.checker();
  const Json& v = *asset.find("controls");
  if (!v.is_object()) {
    asset.error("controls", "expected an object mapping control names to {\"range\", \"blendshapes\", \"joints\", "
                            "\"value\"}, found " + describeValue(v));
    return;
  }
  const size_t before = c.errorCount();
  const std::vector<std::string> channels = FaceControls::jointChannelNames(eyeNames(out));
  std::vector<FaceControl> controls;
  std::vector<std::pair<std::string, AnimatedFloat>> values;
  for (const auto& item : v.items()) {
    ObjectReader o(c, item.value(), childPointer(asset.at("controls"), item.key()),
                   {"range", "blendshapes", "joints", "value"});
    if (!o.ok()) continue;
    FaceControl control;
    control.name = item.key();
    if (const Json* r = o.find("range")) {
      if (auto range = readVec2(c, *r, o.at("range"), Range::any(), "[min, max]")) {
        control.min = range->x();
        control.max = range->y();
        if (!(control.min <= control.max)) o.error("range", "expected [min, max] with min <= max");
      }
    }
    if (const Json* b = o.find("blendshapes"))
      control.blendshapes = readGains(c, *b, o.at("blendshapes"), out.gltf->targetNames, "blendshape");
    if (const Json* j = o.find("joints")) {
      if (!out.rig) o.error("joints", "a control can drive joints only when the asset has a 'rig'", Anchor::Key);
      else control.joints = readGains(c, *j, o.at("joints"), channels, "joint channel");
    }
    if (const Json* x = o.find("value"))
      if (auto value = readAnimatedNumber(c, *x, o.at("value"), Range::any())) values.emplace_back(control.name, *value);
    controls.push_back(std::move(control));
  }
  if (c.errorCount() != before) return;
  try {
    out.controls = std::make_shared<const FaceControls>(out.gltf->targetNames, eyeNames(out), controls);
  } catch (const InputError& e) {
    asset.error("controls", e.what());
    return;
  }
  std::vector<std::string> controlNames;
  for (const FaceControl& control : controls) controlNames.push_back(control.name);
  for (auto& [name, value] : values) out.controlValues.push_back(AssetChannel{name, *indexOf(controlNames, name), value});
}

void readPerformance(ObjectReader& asset, ShotAsset& out, const AssetAnimationContext& context) {
  Checker& c = asset.checker();
  ObjectReader o(c, *asset.find("performance"), asset.at("performance"),
                 {"file", "fps", "startFrame", "nameMap", "filter"});
  if (!o.ok()) return;
  const size_t before = c.errorCount();
  PerformanceCsvOptions options;
  if (auto x = o.number("fps", Range::above(0))) options.sourceFps = float(*x);
  ShotPerformance performance;
  performance.startFrame = context.frameStart;
  if (auto x = o.number("startFrame", Range::any())) performance.startFrame = *x;
  if (const Json* m = o.find("nameMap")) {
    if (!m->is_object()) o.error("nameMap", "expected an object mapping track names to blendshape names, found " +
                                                describeValue(*m));
    else
      for (const auto& item : m->items())
        if (auto name = readString(c, item.value(), childPointer(o.at("nameMap"), item.key())))
          options.nameMap[item.key()] = *name;
  }
  std::optional<AdaptiveFilterOptions> filter;
  if (const Json* f = o.find("filter")) {
    if (f->is_boolean()) {
      if (f->get<bool>()) filter = AdaptiveFilterOptions{};
    } else {
      ObjectReader fo(c, *f, o.at("filter"), {"window", "sharpness"});
      filter = AdaptiveFilterOptions{};
      if (auto x = fo.integer("window", Range::closed(0, 240))) filter->window = int(*x);
      if (auto x = fo.number("sharpness", Range::above(0))) filter->sharpness = float(*x);
    }
  }
  const auto file = o.string("file", true);
  if (!file || c.errorCount() != before) return;
  const std::filesystem::path path(*file);
  performance.file = (path.is_absolute() ? path : context.baseDir / path).lexically_normal();
  try {
    // Columns are blendshapes, or a rig's joint channels (a tracker's head pose), which need a rig.
    const std::vector<std::string> jointNames = FaceControls::jointChannelNames(eyeNames(out));
    std::vector<std::string> validNames = out.gltf->targetNames;
    validNames.insert(validNames.end(), jointNames.begin(), jointNames.end());
    PerformanceTrack track = resampleTrack(readPerformanceTrack(performance.file, validNames, options), float(context.fps));
    for (const std::string& name : track.names)
      if (!out.rig && !indexOf(out.gltf->targetNames, name)) {
        o.error("file", fmt::format("{}: the column '{}' is a joint channel: it needs a 'rig' on the asset (for example "
                                    "\"rig\": {{\"preset\": \"ict\"}})",
                                    performance.file.string(), name));
        return;
      }
    performance.samples = filter ? adaptiveTemporalFilter(track.frames, *filter) : std::move(track.frames);
    for (const std::string& name : track.names) {
      const auto target = indexOf(out.gltf->targetNames, name);
      performance.targets.push_back(target ? *target : ShotPerformance::kNone);
      performance.joints.push_back(target ? ShotPerformance::kNone : *indexOf(jointNames, name));
    }
  } catch (const InputError& e) {
    o.error("file", fmt::format("cannot use the performance track: {}", e.what()));
    return;
  }
  out.performance = std::move(performance);
}

// "animation": {"name" or "index", "startFrame", "speed", "loop"}: one of the glTF file's animations.
void readGltfAnimation(ObjectReader& asset, ShotAsset& out, const AssetAnimationContext& context) {
  Checker& c = asset.checker();
  ObjectReader o(c, *asset.find("animation"), asset.at("animation"), {"name", "index", "startFrame", "speed", "loop"});
  if (!o.ok()) return;
  const size_t before = c.errorCount();
  ShotGltfAnimation playback;
  playback.fps = context.fps;
  playback.startFrame = context.frameStart;
  if (auto x = o.number("startFrame", Range::any())) playback.startFrame = *x;
  if (auto x = o.number("speed", Range::above(0))) playback.speed = *x;
  if (auto x = o.boolean("loop")) playback.loop = *x;
  const auto name = o.string("name");
  const auto index = o.unsignedInteger("index");
  const std::vector<GltfAnimation>& animations = out.gltf->animations;
  std::vector<std::string> names;
  for (const GltfAnimation& a : animations) names.push_back(a.name);
  if (animations.empty()) {
    asset.error("animation", fmt::format("asset '{}' has no glTF animations ({} defines none)", out.name,
                                         out.file.filename().string()),
                Anchor::Key);
    return;
  }
  if (o.has("name") && o.has("index")) {
    o.error("index", "give the animation's 'name' or its 'index', not both", Anchor::Key);
    return;
  }
  if (name) {
    const auto found = indexOf(names, *name);
    if (!found) {
      o.error("name", unknownName("glTF animation", *name, names));
      return;
    }
    playback.index = *found;
  } else if (index) {
    if (*index >= animations.size()) {
      o.error("index", fmt::format("animation index {} does not exist (asset '{}' has {} animation{})", *index, out.name,
                                   animations.size(), animations.size() == 1 ? "" : "s"));
      return;
    }
    playback.index = size_t(*index);
  } else if (!o.has("name") && !o.has("index")) {
    o.missing("name", "the glTF animation to play, or its 'index'");
    return;
  }
  if (c.errorCount() != before) return;
  playback.duration = animations[playback.index].duration();
  out.gltfAnimation = playback;
}

}  // namespace

void readAssetAnimation(ObjectReader& o, ShotAsset& asset, const AssetAnimationContext& context) {
  if (!asset.gltf) return;
  if (const Json* r = o.find("rig")) readRig(o, *r, asset);
  if (o.find("joints")) {
    if (!asset.rig)
      o.error("joints", "joints need a 'rig' on the asset (for example \"rig\": {\"preset\": \"ict\"})", Anchor::Key);
    else
      readChannels(o, "joints", FaceControls::jointChannelNames(eyeNames(asset)), "joint channel", Range::any(),
                   asset.joints);
  }
  if (o.find("controls")) readControls(o, asset);
  if (o.find("performance")) readPerformance(o, asset, context);
  if (o.find("animation")) readGltfAnimation(o, asset, context);
}

}  // namespace lacrima::shotfile
