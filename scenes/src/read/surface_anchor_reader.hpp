#pragma once
// Reading a surface anchor (docs/shot-format.md "Surface anchors"): where a tear, detail or region
// sits on a part of an asset, written as a point near the skin, a facial landmark, a vertex or a
// texture coordinate. Checked against the asset once it is loaded (load/surface_anchor_check.hpp),
// resolved to a surface point once the assets are final (resolve/surface_anchor.hpp).
#include <optional>
#include <string>

#include "lacrima/scenes/shot_model.hpp"
#include "read/shot_checker.hpp"

namespace lacrima::shotfile {

// Reads an anchor as written: [x, y, z], {"landmark": i}, {"vertex": i} or {"uv": [u, v]}. Reports
// a value of none of these forms; the index or uv of the last three is taken as it is, to be checked
// against the asset by checkSurfaceAnchor.
std::optional<ShotSurfaceAnchor> readSurfaceAnchor(Checker& c, const Json& value, const std::string& pointer);

}  // namespace lacrima::shotfile
