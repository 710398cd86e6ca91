// ShotReader (shot_reader.hpp): the sections "frames", "output" and "render" (docs/shot-format.md).
#include <fmt/format.h>

#include <algorithm>

#include "frame_pattern.hpp"
#include "read/shot_reader.hpp"
#include "read/suggest.hpp"

namespace lacrima::shotfile {

namespace {

const std::vector<std::string> kSamplerKinds = {"sobol", "independent"};  // order of readSampler's kinds
const std::vector<std::string> kFilterTypes = {"blackman-harris", "gaussian", "mitchell", "box"};  // readFilter's order
// A filter wider than this blurs away the detail it should keep (and 16 px is already 8 pixels
// each way); a typo such as 15 for 1.5 is caught.
constexpr double kMaxFilterWidth = 16.0;

}  // namespace

bool ShotReader::readFrames(const Json& v) {
  ObjectReader o(c_, v, "/frames", {"start", "end", "fps"});
  const auto start = o.integer("start", Range::any(), true);
  const auto end = o.integer("end", start ? Range::atLeast(double(*start)) : Range::any(), true);
  const auto fps = o.number("fps", Range::above(0));
  if (start) shot_.frameStart = int(*start);
  if (end) shot_.frameEnd = int(*end);
  if (fps) shot_.fps = *fps;
  return start && end;
}

void ShotReader::readOutput(const Json& v, bool framesOk) {
  const auto pattern = readString(c_, v, "/output");
  if (!pattern) return;
  shot_.outputPattern = resolve(*pattern).string();
  if (framesOk && shot_.frameStart != shot_.frameEnd && !hasFrameField(*pattern))
    c_.error("/output", Anchor::Value,
             fmt::format("'{}' has no frame number field ('####' or '%04d') but the shot has frames {}-{}: every "
                         "frame would overwrite the last",
                         *pattern, shot_.frameStart, shot_.frameEnd));
}

bool ShotReader::readRender(const Json& v) {
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
void ShotReader::readAovs(ObjectReader& render, RenderSettings& s) {
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
void ShotReader::readAdaptive(ObjectReader& render, RenderSettings& s) {
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
void ShotReader::readBounces(ObjectReader& render, RenderSettings& s) {
  const Json* v = render.find("bounces");
  if (!v) return;
  ObjectReader o(c_, *v, render.at("bounces"), {"diffuse", "glossy", "transmission"});
  const auto range = Range::closed(0, BounceLimits::kUnlimited);
  if (auto x = o.integer("diffuse", range)) s.bounces.diffuse = int(*x);
  if (auto x = o.integer("glossy", range)) s.bounces.glossy = int(*x);
  if (auto x = o.integer("transmission", range)) s.bounces.transmission = int(*x);
}

// "sampler": "sobol" | "independent" (docs/shot-format.md, "Sampling").
void ShotReader::readSampler(ObjectReader& o, RenderSettings& s) {
  static constexpr SamplerKind kinds[] = {SamplerKind::Sobol, SamplerKind::Independent};
  if (const auto i = readChoice(o, "sampler", kSamplerKinds, "sampler")) s.sampler = kinds[*i];
}

// "filter": {"type": "blackman-harris" | "gaussian" | "mitchell" | "box", "width": full width in
// pixels} (docs/shot-format.md, "Pixel filter"). The width defaults per type.
void ShotReader::readFilter(ObjectReader& render, RenderSettings& s) {
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
void ShotReader::readCaustics(ObjectReader& o, RenderSettings& s) {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> spelt;
    for (Caustics mode : kCausticsModes) spelt.push_back(causticsName(mode));
    return spelt;
  }();
  const auto i = readChoice(o, "caustics", names, "caustics mode");
  if (i) s.caustics = kCausticsModes[*i];
}

}  // namespace lacrima::shotfile
