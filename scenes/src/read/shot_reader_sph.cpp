// ShotReader (shot_reader.hpp): the section "sph" (docs/shot-format.md).
#include "lacrima/sph/surface_tension.hpp"
#include "read/shot_reader.hpp"

namespace lacrima::shotfile {

// An SPH liquid (docs/shot-format.md "sph"; ShotSph).
void ShotReader::readSph(const Json& v, const std::string& pointer) {
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
void ShotReader::readSphRelease(const Json& v, const std::string& pointer, bool drop, ShotSph& liquid) {
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
void ShotReader::readSphCollider(const Json& v, const std::string& pointer, ShotSph& liquid) {
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

}  // namespace lacrima::shotfile
