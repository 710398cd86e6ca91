#pragma once
// A region of a triangle mesh around a polyline, extracted as a mesh of its own (Lin & Cheng 2013 section
// 4.2 step 1: "the region the tear passes through is extracted from the face"), so that
// nearest-point queries near the polyline look at a few hundred triangles instead of the whole
// face, and give exactly what they give on the whole mesh.
#include <cstdint>
#include <optional>
#include <vector>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"
#include "lacrima/mesh/surface_point.hpp"

namespace lacrima {

struct SurfaceRegion {
  // The extracted triangles, in the order of the full mesh, with their corners in the same order
  // and their vertices' positions (and normals, uvs when the full mesh has them) copied bitwise.
  TriangleMesh mesh;
  std::vector<uint32_t> fullTriangles;  // region triangle -> triangle of the full mesh

  // The same point in the full mesh's triangle numbering (same barycentric weights).
  SurfacePoint toFull(const SurfacePoint& point) const;
  // A point of the full mesh in the region's numbering; nullopt when its triangle is not in the region.
  std::optional<SurfacePoint> fromFull(const SurfacePoint& point) const;
};

// Every triangle of `mesh` that may lie within `radius` of the polyline (a superset: a triangle is
// kept when its bounding sphere comes within `radius` of a segment). A single point is a polyline
// too. Guarantee: for any point q with dist(q, polyline) + dist(q, mesh) <= radius,
// closestSurfacePoint(region.mesh, q) mapped by toFull is bitwise closestSurfacePoint(mesh, q)
// (the nearest triangles and every triangle tied with them are in the region, in the same
// order). Throws InputError for an empty polyline or a negative or non-finite radius.
SurfaceRegion extractSurfaceRegion(const TriangleMesh& mesh, const std::vector<Vec3>& polyline, float radius);

// The radius for a strip of total `width` across a polyline whose vertices lie on the mesh, such
// that every nearest-point query of the strip (a point on the polyline, or the skin point nearest
// to it moved up to width / 2 in any direction) is covered by the guarantee above: a polyline
// point is at most half its segment's length from the skin (both ends are on it), so
//   radius = width + (longest segment) / 2,
// with a little slack for rounding.
float stripRegionRadius(const std::vector<Vec3>& polyline, float width);

}  // namespace lacrima
