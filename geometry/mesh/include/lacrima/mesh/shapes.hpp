#pragma once
// Tessellated simple shapes for drops, tests and furnace scenes. (Exact spheres are rendered
// analytically by the renderer; these meshes are for shapes that have no exact primitive.)
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

// A closed, outward-oriented UV ellipsoid with analytic normals: centre, semi-axes given as
// columns of `axes` (each column = direction * radius), `rings` latitude bands, `segments`
// longitude slices. Poles are single vertices (no degenerate triangles).
TriangleMesh makeEllipsoid(const Vec3& center, const Mat3& axes, int rings = 48, int segments = 96);

// A rectangle (two triangles) centred at `center` spanning center +- edgeU/2 +- edgeV/2;
// its normal is normalize(edgeU x edgeV).
TriangleMesh makeRectangle(const Vec3& center, const Vec3& edgeU, const Vec3& edgeV);

}  // namespace lacrima
