#pragma once
// The water mesh of a bead sitting on the skin (a spherical-cap cross-section,
// elongated by gravity; see BeadShape in sessile_drop.hpp): a closed, outward-oriented cap draped
// over the skin so that its flat side follows the skin at a small offset: above it, or (negative)
// just under it, so the skin under the bead lies inside the water as wetted skin does.
//
// Construction: the unit spherical cap of contact angle theta (base radius 1, sphere radius
// rho = 1 / sin(theta); a point at polar angle psi from the apex has radius rho sin(psi) and height
// rho (cos(psi) - cos(theta)); de Gennes et al. 2004, ch. 1) is scaled to the bead's footprint
// semi-axes (halfLength along `along`, halfWidth across) and its height. Each vertex at (X, Y)
// in the tangent plane of the contact point is then lifted along the normal by the skin's own
// height above that plane at (X, Y) (a ray along the normal against the skin's triangles near
// the bead, the hit nearest the plane on a triangle facing the same way), plus baseOffset. So
// the base is the skin shifted by baseOffset and the dome rides on it; for theta > 90 degrees the
// dome overhangs its base like a real cap. Vertices where no skin is found (off the mesh's edge)
// are not lifted.
#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

struct LiquidBeadPlacement {
  Vec3 contact = Vec3::Zero();      // the bead's centre on the skin
  Vec3 normal = Vec3::UnitZ();      // out of the skin (normalised here)
  Vec3 along = Vec3::UnitX();       // long axis direction; projected onto the tangent plane
  float halfLength = 0.0f;          // footprint semi-axis along `along`, > 0
  float halfWidth = 0.0f;           // footprint semi-axis across, > 0
  float height = 0.0f;              // > 0
  float contactAngle = 1.5f;        // radians, in (0, pi)
  float baseOffset = 2e-5f;         // metres from the skin to the base along the normal, > -height
};

// Dome rings (apex excluded) and base rings (centre excluded) of the mesh, and segments around.
struct LiquidBeadResolution {
  int domeRings = 10;
  int baseRings = 3;
  int segments = 32;
};

// The bead's mesh (counter-clockwise from outside, smooth per-vertex normals) on `skin`; closed
// once coincident vertices are welded: the dome and the base each have their own vertices along
// the contact line, so each side keeps its own normals at that sharp edge.
// Throws InputError for invalid placement values or resolution (domeRings >= 2, baseRings >= 1,
// segments >= 3) or `along` parallel to the normal.
TriangleMesh makeLiquidBeadMesh(const TriangleMesh& skin, const LiquidBeadPlacement& placement,
                                const LiquidBeadResolution& resolution = {});

}  // namespace lacrima
