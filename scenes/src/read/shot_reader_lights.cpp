// ShotReader (shot_reader.hpp): the section "lights" (docs/shot-format.md).
#include "read/animation_reader.hpp"
#include "read/shot_reader.hpp"

namespace lacrima::shotfile {

namespace {

const std::vector<std::string> kLightTypes = {"rectangle", "sphere"};

}  // namespace

void ShotReader::readLight(const Json& v, const std::string& pointer) {
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

}  // namespace lacrima::shotfile
