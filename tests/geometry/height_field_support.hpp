#pragma once
// A square height-field sheet for geometry tests: quads x quads cells over [-half, half]^2 in
// the xy plane, z = height(x, y), two triangles per cell, counter-clockwise seen from +z.
#include <functional>

#include "lacrima/mesh/mesh.hpp"

namespace lacrima::test {

inline TriangleMesh heightFieldMesh(int quads, float half, const std::function<float(float, float)>& height) {
  TriangleMesh m;
  for (int y = 0; y <= quads; ++y)
    for (int x = 0; x <= quads; ++x) {
      const float px = -half + 2 * half * float(x) / float(quads), py = -half + 2 * half * float(y) / float(quads);
      m.positions.emplace_back(px, py, height(px, py));
    }
  auto v = [quads](int x, int y) { return uint32_t(y * (quads + 1) + x); };
  for (int y = 0; y < quads; ++y)
    for (int x = 0; x < quads; ++x) {
      m.indices.insert(m.indices.end(), {v(x, y), v(x + 1, y), v(x + 1, y + 1)});
      m.indices.insert(m.indices.end(), {v(x, y), v(x + 1, y + 1), v(x, y + 1)});
    }
  return m;
}

}  // namespace lacrima::test
