// Reading a surface anchor; see surface_anchor_reader.hpp.
#include "read/surface_anchor_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

namespace lacrima::shotfile {

namespace {

constexpr const char* kAnchorForms = "[x, y, z], {\"landmark\": i}, {\"vertex\": i} or {\"uv\": [u, v]}";

// A landmark or vertex index as readInteger would take it (5 or 5.0); 0 for anything else, which
// checkSurfaceAnchor reports.
uint32_t indexAsWritten(const Json& x) {
  if (!x.is_number()) return 0;
  const double d = x.get<double>();
  return d >= 0.0 && d <= double(UINT32_MAX) && d == std::floor(d) ? uint32_t(d) : 0;
}

}  // namespace

std::optional<ShotSurfaceAnchor> readSurfaceAnchor(Checker& c, const Json& value, const std::string& pointer) {
  if (value.is_array()) {
    const auto point = readVec3(c, value, pointer);
    if (!point) return std::nullopt;
    ShotSurfaceAnchor anchor;
    anchor.point = *point;
    return anchor;
  }
  if (!value.is_object() || value.size() != 1) {
    c.error(pointer, Anchor::Value,
            fmt::format("expected a surface anchor, {}; found {}", kAnchorForms, describeValue(value)));
    return std::nullopt;
  }
  ObjectReader o(c, value, pointer, {"landmark", "vertex", "uv"});
  if (!o.ok()) return std::nullopt;
  ShotSurfaceAnchor anchor;
  // The value as written, taken without a report: checkSurfaceAnchor reports a bad one with the
  // bounds the asset gives it.
  if (const Json* x = o.find("landmark")) {
    anchor.kind = ShotSurfaceAnchor::Kind::Landmark;
    anchor.index = indexAsWritten(*x);
  } else if (const Json* x = o.find("vertex")) {
    anchor.kind = ShotSurfaceAnchor::Kind::Vertex;
    anchor.index = indexAsWritten(*x);
  } else if (const Json* x = o.find("uv")) {
    anchor.kind = ShotSurfaceAnchor::Kind::Uv;
    if (x->is_array() && x->size() == 2 && (*x)[0].is_number() && (*x)[1].is_number())
      anchor.uv = Vec2((*x)[0].get<float>(), (*x)[1].get<float>());
  } else {
    return std::nullopt;  // its one key is unknown, and reported
  }
  return anchor;
}

}  // namespace lacrima::shotfile
