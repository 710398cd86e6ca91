// ShotReader (shot_reader.hpp): the section "details" (docs/shot-format.md).
#include <fmt/format.h>

#include <algorithm>

#include "read/animation_reader.hpp"
#include "read/shot_reader.hpp"
#include "read/suggest.hpp"

namespace lacrima::shotfile {

namespace {

const std::vector<std::string> kDetailPatterns = {"forehead", "eyeCorner", "cheek", "frown", "dimple", "eyePouch"};
const std::vector<std::string> kSubdivisionSchemes = {"loop", "linear"};
// Each level quadruples the region's triangles: 4 levels turn one triangle into 256.
constexpr int kMaxSubdivisionLevels = 4;

}  // namespace

void ShotReader::readDetail(const Json& v, const std::string& pointer) {
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

// One basic pattern: {"pattern": name, "alpha", "beta", "gamma"} (the object itself for a
// single pattern, so it may hold other keys; those are checked by the caller's reader).
std::optional<BasicDetailPattern> ShotReader::readPattern(ObjectReader& o) {
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
void ShotReader::readSubdivision(const Json& v, const std::string& pointer, ShotDetail& detail) {
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

}  // namespace lacrima::shotfile
