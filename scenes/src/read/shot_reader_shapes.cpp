// ShotReader (shot_reader.hpp): the section "shapes" (docs/shot-format.md), and the rectangle
// geometry shapes and lights share.
#include <fmt/format.h>

#include "shot_geometry.hpp"
#include "read/shot_reader.hpp"

namespace lacrima::shotfile {

namespace {

const std::vector<std::string> kShapeTypes = {"sphere", "ellipsoid", "rectangle"};

}  // namespace

// Rectangle geometry: edges 'u' and 'v', or 'size' with 'normal' or 'lookAt' (and 'up').
std::optional<RectangleEdges> ShotReader::readRectangle(ObjectReader& o, const Vec3* center) {
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

void ShotReader::readShape(const Json& v, const std::string& pointer) {
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
        warnTexturesWithoutUvs(c_, shot_, o.at("material"), shape.materialId,
                               shape.type == ShotShape::Type::Sphere ? "this sphere" : "this ellipsoid");
    }
  } else {
    o.missing("material", "the name of a material in 'materials'");
  }
  if (c_.errorCount() == before) shot_.shapes.push_back(shape);
}

// {"asset": name, "part": part name}: the shape follows that part's surface.
void ShotReader::readAttachment(const Json& v, const std::string& pointer, ShotShape& shape) {
  ObjectReader o(c_, v, pointer, {"asset", "part"});
  std::string part;
  if (const auto index = readAssetPart(o, part)) {
    shape.attachAsset = shot_.assets[*index].name;
    shape.attachPart = part;
  }
}

}  // namespace lacrima::shotfile
