// Tessellated ellipsoids and rectangles.
#include <string>

#include <fmt/format.h>

#include "lacrima/base/error.hpp"
#include "lacrima/mesh/shapes.hpp"

namespace lacrima {

namespace {

void requireEllipsoidParameters(const Mat3& axes, int rings, int segments) {
  if (rings < 2 || segments < 3)
    throw InputError(fmt::format("ellipsoid: needs at least 2 rings and 3 segments, got {} and {}", rings, segments));
  const float det = axes.determinant();
  if (!axes.allFinite() || !std::isfinite(det) || det == 0.0f)
    throw InputError("ellipsoid: the semi-axes must be finite and linearly independent (non-zero volume)");
}

// Unit-sphere direction for latitude ring r (0 = north pole .. rings = south pole) and segment s.
// The pole axis is the third column of `axes`.
Vec3 unitSpherePoint(int ring, int rings, int segment, int segments) {
  const float theta = kPi * float(ring) / float(rings);
  const float phi = 2.0f * kPi * float(segment) / float(segments);
  return Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

// Vertex layout: 0 = north pole, then rings-1 circles of `segments` vertices, last = south pole.
// Sharing the seam vertex (segment == segments wraps to 0) and single poles make the mesh
// watertight, which a drop inside a refractive path tracer needs.
void addEllipsoidVertices(TriangleMesh& mesh, const Vec3& center, const Mat3& axes, int rings, int segments) {
  // The surface is p = c + A u for unit u; its normal is A^-T u (the gradient of |A^-1 (p - c)|^2).
  const Mat3 normalMatrix = axes.inverse().transpose();
  const auto addVertex = [&](const Vec3& u) {
    mesh.positions.push_back(center + axes * u);
    mesh.normals.push_back((normalMatrix * u).normalized());
  };
  addVertex(Vec3(0.0f, 0.0f, 1.0f));
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) addVertex(unitSpherePoint(r, rings, s, segments));
  addVertex(Vec3(0.0f, 0.0f, -1.0f));
}

// Triangles counter-clockwise seen from outside the unit sphere (phi grows counter-clockwise
// around +z, theta grows southward).
void addEllipsoidTriangles(TriangleMesh& mesh, int rings, int segments) {
  const uint32_t north = 0;
  const uint32_t south = uint32_t(1 + (rings - 1) * segments);
  const auto ringVertex = [segments](int r, int s) { return uint32_t(1 + (r - 1) * segments + (s % segments)); };
  const auto add = [&mesh](uint32_t a, uint32_t b, uint32_t c) { mesh.indices.insert(mesh.indices.end(), {a, b, c}); };
  for (int s = 0; s < segments; ++s) {
    add(north, ringVertex(1, s), ringVertex(1, s + 1));
    for (int r = 1; r + 1 < rings; ++r) {
      add(ringVertex(r, s), ringVertex(r + 1, s), ringVertex(r + 1, s + 1));
      add(ringVertex(r, s), ringVertex(r + 1, s + 1), ringVertex(r, s + 1));
    }
    add(ringVertex(rings - 1, s), south, ringVertex(rings - 1, s + 1));
  }
}

}  // namespace

TriangleMesh makeEllipsoid(const Vec3& center, const Mat3& axes, int rings, int segments) {
  requireEllipsoidParameters(axes, rings, segments);
  TriangleMesh mesh;
  mesh.name = "ellipsoid";
  mesh.positions.reserve(size_t(2 + (rings - 1) * segments));
  mesh.normals.reserve(mesh.positions.capacity());
  mesh.indices.reserve(size_t(6 * segments * (rings - 1)));
  addEllipsoidVertices(mesh, center, axes, rings, segments);
  addEllipsoidTriangles(mesh, rings, segments);
  // Left-handed axes mirror the sphere: flip the winding so it stays outward (the normals are
  // already outward thanks to the inverse transpose).
  if (axes.determinant() < 0.0f)
    for (size_t i = 0; i < mesh.indices.size(); i += 3) std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
  return mesh;
}

TriangleMesh makeRectangle(const Vec3& center, const Vec3& edgeU, const Vec3& edgeV) {
  const Vec3 normal = edgeU.cross(edgeV);
  const float area = normal.norm();
  if (!(area > 0.0f) || !std::isfinite(area) || !center.allFinite())
    throw InputError("rectangle: the edges must be finite and not parallel (non-zero area)");
  TriangleMesh mesh;
  mesh.name = "rectangle";
  const Vec3 halfU = 0.5f * edgeU, halfV = 0.5f * edgeV;
  mesh.positions = {center - halfU - halfV, center + halfU - halfV, center + halfU + halfV, center - halfU + halfV};
  mesh.uvs = {Vec2(0.0f, 0.0f), Vec2(1.0f, 0.0f), Vec2(1.0f, 1.0f), Vec2(0.0f, 1.0f)};
  mesh.normals.assign(4, normal / area);
  // (p1 - p0) x (p2 - p0) = U x (U + V) = U x V: counter-clockwise seen from the normal's side.
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

}  // namespace lacrima
