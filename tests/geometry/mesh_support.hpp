#pragma once
// Measures of triangle meshes shared by the geometry tests.
#include "lacrima/mesh/mesh.hpp"

namespace lacrima::test {

// The total area of the mesh's triangles, summed in double precision.
inline double meshArea(const TriangleMesh& mesh) {
  double sum = 0.0;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Vec3d a = mesh.positions[mesh.indices[3 * t]].cast<double>();
    const Vec3d b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
    const Vec3d c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
    sum += 0.5 * (b - a).cross(c - a).norm();
  }
  return sum;
}

}  // namespace lacrima::test
