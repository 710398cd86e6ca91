// ShotReader (shot_reader.hpp): the section "eyes" (docs/shot-format.md), with their lashes.
#include <fmt/format.h>

#include "read/shot_reader.hpp"

namespace lacrima::shotfile {

// An eye for close-ups (ShotEye): the eyeball shell part, its materials and lashes.
void ShotReader::readEye(const Json& v, const std::string& pointer) {
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

void ShotReader::readLashes(const Json& v, const std::string& pointer, size_t asset, ShotEye& eye) {
  ObjectReader o(c_, v, pointer,
                 {"part", "material", "upper", "lower", "rootRadius", "tipRadius", "minLength", "spread", "seed"});
  if (!o.ok()) return;
  ShotLashes lashes;
  const auto part = o.string("part", true);
  if (part) {
    usePart(o, asset, *part);
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

}  // namespace lacrima::shotfile
