#pragma once
// The water mesh of a rivulet running over the skin (the flow in rivulet.hpp): a
// closed, outward-oriented tube swept along stations on the skin. At each station the
// cross-section is the rivulet's parabola h(y) = height (1 - (y / halfWidth)^2) over the base
// y in [-halfWidth, halfWidth] (Duffy & Moffatt 1995's small-width profile), in the plane spanned
// by the station's across direction (normal x along) and its normal, its base `baseOffset` along
// the normal from the contact point (negative: just under the skin, so the wetted skin lies
// inside the water, as for beads: liquid_bead_mesh.hpp). Between stations the surface is ruled
// (straight). Both ends are rounded: the last section shrinks as an ellipsoid's, cos(phi) in
// width and height over sin(phi) times its half-width beyond the end station, to a point.
//
// The stations should lie on the skin about a cell apart (the simulation's trail cells, 0.5 mm):
// the sweep does not follow the skin between them, so a concave stretch of radius R under a
// station spacing L leaves a gap of L^2 / (8 R) under the chord (1.6 um at L = 0.5 mm, R = 2 cm).
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

struct LiquidRivuletStation {
  Vec3 contact = Vec3::Zero();  // the rivulet's middle on the skin
  Vec3 normal = Vec3::UnitZ();  // out of the skin (normalised here)
  Vec3 along = Vec3::UnitX();   // down the rivulet; projected onto the tangent plane
  float halfWidth = 0.0f;       // > 0
  float height = 0.0f;          // middle depth, > 0
};

struct LiquidRivuletResolution {
  int across = 12;     // segments of the parabola from edge to edge
  int baseAcross = 4;  // segments of the flat base
  int capRings = 4;    // rings of each rounded end before its tip
};

// The rivulet's mesh (counter-clockwise from outside, closed, smooth per-vertex normals) through
// `stations` in order down the rivulet (at least one). Throws InputError for invalid stations
// (non-finite, a zero normal, `along` parallel to the normal, non-positive sizes), baseOffset (finite, > -height of every station) or resolution (across >= 2,
// baseAcross >= 1, capRings >= 1).
TriangleMesh makeLiquidRivuletMesh(const std::vector<LiquidRivuletStation>& stations, float baseOffset,
                                   const LiquidRivuletResolution& resolution = {});

}  // namespace lacrima
