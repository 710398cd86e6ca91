// ShotReader (shot_reader.hpp): the liquid tears of the section "tears" (docs/shot-format.md
// "Liquid tears").
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "read/animation_reader.hpp"
#include "read/shot_reader.hpp"

namespace lacrima::shotfile {

// A liquid tear: tear fluid welling at a skin point and running down its flow path (ShotLiquidTear).
// Volumes in microlitres, angles in degrees, welling times in frames, the rest in SI units.
void ShotReader::readLiquidTear(const Json& v, const std::string& pointer) {
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
void ShotReader::readWellingTimes(ObjectReader& o, ShotLiquidTear& tear) {
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
void ShotReader::readWellingRate(ObjectReader& o, ShotLiquidTear& tear) {
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
void ShotReader::readPinning(ObjectReader& o, ShotLiquidTear& tear) {
  const Json* v = o.find("pinning");
  if (!v) return;
  ObjectReader r(c_, *v, o.at("pinning"), {"factor", "patchSize"});
  if (!r.ok()) return;
  if (auto x = r.number("factor", Range::atLeast(1), true)) tear.pinningFactor = *x;
  if (auto x = r.number("patchSize", Range::above(0))) tear.pinningPatchSize = *x;
}

// "rivulet": {"formFlowRate": uL/s > 0, "breakFlowRate": uL/s in (0, formFlowRate] (default half
// of it)}: welling at formFlowRate or faster runs down as a rivulet (LiquidTearParams::rivulet).
void ShotReader::readRivulet(ObjectReader& o, LiquidTearParams& p) {
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
void ShotReader::readContactAngles(ObjectReader& o, ContactAngleHysteresis& angles) {
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
void ShotReader::readContactAngleRegions(ObjectReader& o, size_t asset, ShotLiquidTear& tear) {
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

}  // namespace lacrima::shotfile
