#pragma once
// The volume swept between two meshes of one topology (an open surface and the same surface with
// its vertices moved): per triangle, the prism from its old to its new corners as three
// tetrahedra (signed: positive where the surface moved along its outward side, the side its
// counter-clockwise winding faces). Exact for a prism whose side faces are planar.
#include <cmath>

#include "lacrima/mesh/mesh.hpp"

namespace lacrima::test {

inline double tetrahedronVolume(const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
  return (b - a).cross(c - a).dot(d - a) / 6.0;
}

inline double sweptVolume(const TriangleMesh& before, const TriangleMesh& after) {
  double volume = 0.0;
  for (size_t t = 0; t < before.triangleCount(); ++t) {
    const uint32_t* v = &before.indices[3 * t];
    const Vec3d a = before.positions[v[0]].cast<double>(), b = before.positions[v[1]].cast<double>(),
                c = before.positions[v[2]].cast<double>();
    const Vec3d a2 = after.positions[v[0]].cast<double>(), b2 = after.positions[v[1]].cast<double>(),
                c2 = after.positions[v[2]].cast<double>();
    // Prism (a b c | a2 b2 c2) = tets (a b c a2) + (b c a2 b2) + (c a2 b2 c2).
    volume += tetrahedronVolume(a, b, c, a2) + tetrahedronVolume(b, c, a2, b2) + tetrahedronVolume(c, a2, b2, c2);
  }
  return volume;
}

}  // namespace lacrima::test
