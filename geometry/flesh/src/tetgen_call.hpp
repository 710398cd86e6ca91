#pragma once
// TetGen run in a child process: TetGen 1.5 crashes (segmentation fault) on some inputs it
// should reject (a facet piercing another, a dangling facet), and a crash in the renderer's
// process would lose the user's render; in a child it is an error message.
#include <array>
#include <string>
#include <vector>

#include "lacrima/flesh/tet_mesh.hpp"

namespace lacrima::flesh {

struct TetGenResult {
  TetMesh mesh;
  // Per output node: the marker of the facet it lies on (facetMarkers' values), 0 inside.
  std::vector<int> nodeMarkers;
};

// Tetrahedralizes the piecewise linear complex (points, triangular facets and a marker per facet,
// non-zero) with TetGen's `switches`. Throws FleshVolumeError when TetGen reports an error or its
// process dies.
TetGenResult tetrahedralizeInChildProcess(const std::vector<Vec3d>& points, const std::vector<std::array<int, 3>>& facets,
                                          const std::vector<int>& facetMarkers, const std::string& switches);

}  // namespace lacrima::flesh
