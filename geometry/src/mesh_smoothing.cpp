// Taubin lambda/mu smoothing; see mesh_smoothing.hpp.
#include "lacrima/geometry/mesh_smoothing.hpp"

#include <fmt/format.h>

#include <algorithm>
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

// next = x + factor * (mean of neighbours - x) for every free representative vertex, next = x for
// the others (Jacobi update). next is the caller's buffer, reused over the iterations: a fresh one
// per step costs a page fault and a zero-fill per 4 KiB of a mesh-sized array.
void umbrellaStep(const std::vector<std::vector<uint32_t>>& neighbours, const std::vector<bool>& boundary, float factor,
                  const std::vector<Vec3d>& x, std::vector<Vec3d>& next) {
  next.resize(x.size());
  for (size_t v = 0; v < x.size(); ++v) {
    if (boundary[v] || neighbours[v].empty()) {
      next[v] = x[v];
      continue;
    }
    Vec3d mean = Vec3d::Zero();
    for (uint32_t n : neighbours[v]) mean += x[n];
    mean /= double(neighbours[v].size());
    next[v] = x[v] + double(factor) * (mean - x[v]);
  }
}

}  // namespace

TaubinSmoother::TaubinSmoother(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap,
                               const TaubinOptions& options)
    : weldMap_(weldMap), options_(options) {
  validate(mesh, weldMap, options);
  // Neighbours of each representative vertex (welded), and whether it lies on the boundary.
  neighbours_.resize(mesh.positions.size());
  boundary_.assign(mesh.positions.size(), false);
  // Every welded edge once per triangle using it, sorted: runs of equal edges count its uses (in the
  // order of a map keyed by the edge, so neighbours are listed in increasing order).
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  edges.reserve(mesh.indices.size());
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = weldMap[mesh.indices[t + k]], b = weldMap[mesh.indices[t + (k + 1) % 3]];
      if (a != b) edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();) {
    size_t end = i + 1;
    while (end < edges.size() && edges[end] == edges[i]) ++end;
    const auto [a, b] = edges[i];
    neighbours_[a].push_back(b);
    neighbours_[b].push_back(a);
    if (end - i == 1) boundary_[a] = boundary_[b] = true;
    i = end;
  }
}

std::vector<Vec3> TaubinSmoother::smoothed(const std::vector<Vec3>& positions) const {
  if (positions.size() != weldMap_.size())
    throw InputError(fmt::format("taubin smoothing: {} positions for {} vertices", positions.size(), weldMap_.size()));
  std::vector<Vec3d> x(positions.size());
  for (size_t v = 0; v < x.size(); ++v) x[v] = positions[v].cast<double>();
  std::vector<Vec3d> next(x.size());
  for (int i = 0; i < options_.iterations; ++i) {
    umbrellaStep(neighbours_, boundary_, options_.lambda, x, next);  // Taubin 1995 eq. 8: the shrinking step ...
    umbrellaStep(neighbours_, boundary_, options_.mu, next, x);      // ... and the inflating one
  }
  std::vector<Vec3> out(positions.size());
  for (size_t v = 0; v < out.size(); ++v) out[v] = x[weldMap_[v]].cast<float>();
  return out;
}

TriangleMesh taubinSmoothed(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap,
                            const TaubinOptions& options) {
  TriangleMesh smoothed = mesh;
  smoothed.positions = TaubinSmoother(mesh, weldMap, options).smoothed(mesh.positions);
  if (!mesh.normals.empty()) computeSmoothNormals(smoothed, weldMap);
  return smoothed;
}

}  // namespace lacrima
