// Taubin lambda/mu smoothing; see mesh_smoothing.hpp.
#include "lacrima/geometry/mesh_smoothing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <utility>

#include "lacrima/geometry/error.hpp"

namespace lacrima {

namespace {

void validate(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap, const TaubinOptions& options) {
  if (options.iterations < 0) throw InputError(fmt::format("taubin smoothing: iterations {} < 0", options.iterations));
  if (!(options.lambda > 0.0f && options.lambda < 1.0f))
    throw InputError(fmt::format("taubin smoothing: lambda {} is not in (0, 1)", options.lambda));
  if (!(options.mu < -options.lambda))
    throw InputError(fmt::format("taubin smoothing: mu {} is not below -lambda ({})", options.mu, -options.lambda));
  if (weldMap.size() != mesh.positions.size())
    throw InputError(fmt::format("taubin smoothing: weld map has {} entries for {} vertices", weldMap.size(),
                                 mesh.positions.size()));
  for (uint32_t w : weldMap)
    if (w >= mesh.positions.size()) throw InputError(fmt::format("taubin smoothing: weld map entry {} out of range", w));
  if (mesh.indices.size() % 3 != 0) throw InputError("taubin smoothing: index count is not a multiple of 3");
  for (uint32_t i : mesh.indices)
    if (i >= mesh.positions.size()) throw InputError(fmt::format("taubin smoothing: index {} out of range", i));
}

// Neighbours of each representative vertex (welded), sorted and unique, and whether it lies on
// the boundary (an edge of a single triangle).
struct WeldedGraph {
  std::vector<std::vector<uint32_t>> neighbours;
  std::vector<bool> boundary;
};

WeldedGraph buildGraph(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap) {
  WeldedGraph g;
  g.neighbours.resize(mesh.positions.size());
  g.boundary.assign(mesh.positions.size(), false);
  std::map<std::pair<uint32_t, uint32_t>, int> edgeUse;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = weldMap[mesh.indices[t + k]], b = weldMap[mesh.indices[t + (k + 1) % 3]];
      if (a == b) continue;
      ++edgeUse[{std::min(a, b), std::max(a, b)}];
    }
  for (const auto& [edge, uses] : edgeUse) {
    g.neighbours[edge.first].push_back(edge.second);
    g.neighbours[edge.second].push_back(edge.first);
    if (uses == 1) g.boundary[edge.first] = g.boundary[edge.second] = true;
  }
  return g;
}

// x += factor * (mean of neighbours - x) for every free representative vertex (Jacobi update).
void umbrellaStep(const WeldedGraph& g, float factor, std::vector<Vec3d>& x) {
  std::vector<Vec3d> next = x;
  for (size_t v = 0; v < x.size(); ++v) {
    if (g.boundary[v] || g.neighbours[v].empty()) continue;
    Vec3d mean = Vec3d::Zero();
    for (uint32_t n : g.neighbours[v]) mean += x[n];
    mean /= double(g.neighbours[v].size());
    next[v] = x[v] + double(factor) * (mean - x[v]);
  }
  x = std::move(next);
}

}  // namespace

TriangleMesh taubinSmoothed(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap,
                            const TaubinOptions& options) {
  validate(mesh, weldMap, options);
  const WeldedGraph graph = buildGraph(mesh, weldMap);
  std::vector<Vec3d> x(mesh.positions.size());
  for (size_t v = 0; v < x.size(); ++v) x[v] = mesh.positions[v].cast<double>();
  for (int i = 0; i < options.iterations; ++i) {
    umbrellaStep(graph, options.lambda, x);  // Taubin 1995 eq. 8: the shrinking step ...
    umbrellaStep(graph, options.mu, x);      // ... and the inflating one
  }
  TriangleMesh smoothed = mesh;
  for (size_t v = 0; v < x.size(); ++v) smoothed.positions[v] = x[weldMap[v]].cast<float>();
  if (!mesh.normals.empty()) computeSmoothNormals(smoothed, weldMap);
  return smoothed;
}

}  // namespace lacrima
