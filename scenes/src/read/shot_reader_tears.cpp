// ShotReader (shot_reader.hpp): the section "tears" (docs/shot-format.md): dripping and shedding
// tears here, liquid tears in shot_reader_liquid_tears.cpp.
#include "read/shot_reader.hpp"

namespace lacrima::shotfile {

namespace {

const std::vector<std::string> kTearTypes = {"dripping", "shedding", "liquid"};

}  // namespace

void ShotReader::readTear(const Json& v, const std::string& pointer) {
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
void ShotReader::readTearPath(ObjectReader& o, std::vector<Vec3>& path) {
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
void ShotReader::readSheddingTear(const Json& v, const std::string& pointer) {
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

}  // namespace lacrima::shotfile
