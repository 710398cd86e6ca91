#pragma once
// Points on triangle meshes in surface coordinates (a triangle and barycentric weights): such a
// point follows any deformation of a mesh with the same topology exactly. Tears and drops are
// attached to the skin this way.
#include <cstdint>
#include <optional>

#include "lacrima/base/math.hpp"
#include "lacrima/mesh/mesh.hpp"

namespace lacrima {

// A point on a triangle mesh: triangle index and barycentric weights of its three corners
// (non-negative, summing to 1). Its position follows any deformation of the mesh.
struct SurfacePoint {
  uint32_t triangle = 0;
  Vec3 barycentric = Vec3(1.0f, 0.0f, 0.0f);
};

// Position of a SurfacePoint on `mesh`. Throws InputError for a triangle out of range or
// barycentric weights that are not finite, negative (below -1e-4) or do not sum to 1 (within 1e-3).
Vec3 surfacePosition(const TriangleMesh& mesh, const SurfacePoint& point);

// Unit geometric normal of a triangle (counter-clockwise winding). Throws InputError for a
// degenerate (zero-area) triangle or one out of range.
Vec3 triangleNormal(const TriangleMesh& mesh, uint32_t triangle);

// The nearest point of triangle `triangle` to p (Ericson, "Real-Time Collision Detection",
// 5.1.5): its barycentric weights, and the squared distance as the return value.
float closestPointOnTriangle(const TriangleMesh& mesh, uint32_t triangle, const Vec3& p, Vec3& barycentric);

// The nearest point of the mesh to p (brute force over all triangles; ties keep the lowest
// triangle index; the closest point of a triangle after Ericson, "Real-Time Collision
// Detection", 5.1.5). Throws InputError for an empty mesh.
SurfacePoint closestSurfacePoint(const TriangleMesh& mesh, const Vec3& p);

// The surface point at a vertex: the first triangle (lowest index) using it, with weight 1 at
// that corner. nullopt when no triangle uses the vertex (or it is out of range).
std::optional<SurfacePoint> vertexSurfacePoint(const TriangleMesh& mesh, uint32_t vertex);

// The surface point whose interpolated texture coordinates are `uv`: the first triangle whose
// uv triangle contains it (barycentric weights >= -1e-5, then clamped and renormalised); uv
// triangles of zero area are skipped. nullopt when the mesh has no uvs or no triangle covers uv.
std::optional<SurfacePoint> surfacePointAtUv(const TriangleMesh& mesh, const Vec2& uv);

}  // namespace lacrima
