// Taubin lambda/mu smoothing; see mesh_smoothing.hpp.
#include "lacrima/mesh/mesh_smoothing.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <utility>

#include "lacrima/base/error.hpp"

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
// per step costs a page fault and a zero-fill per 4 KiB of a mesh-sized array. Each vertex reads
// only x, so the vertices are split between threads and the result does not depend on how.
void umbrellaStep(const std::vector<uint32_t>& start, const std::vector<uint32_t>& list,
                  const std::vector<char>& boundary, float factor, const std::vector<Vec3d>& x,
                  std::vector<Vec3d>& next) {
  next.resize(x.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, x.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t v = r.begin(); v != r.end(); ++v) {
      const uint32_t begin = start[v], end = start[v + 1];
      if (boundary[v] || begin == end) {
        next[v] = x[v];
        continue;
      }
      Vec3d mean = Vec3d::Zero();
      for (uint32_t k = begin; k < end; ++k) mean += x[list[k]];
      mean /= double(end - begin);
      next[v] = x[v] + double(factor) * (mean - x[v]);
    }
  });
}

}  // namespace

TaubinSmoother::TaubinSmoother(const TriangleMesh& mesh, const std::vector<uint32_t>& weldMap,
                               const TaubinOptions& options)
    : weldMap_(weldMap), options_(options) {
  validate(mesh, weldMap, options);
  // Every welded edge once per triangle using it, sorted: runs of equal edges count its uses, and
  // each vertex meets its neighbours in increasing order (the lower ones as the edge's second end
  // first, then the higher ones).
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  edges.reserve(mesh.indices.size());
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = weldMap[mesh.indices[t + k]], b = weldMap[mesh.indices[t + (k + 1) % 3]];
      if (a != b) edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(edges.begin(), edges.end());
  const size_t n = mesh.positions.size();
  boundary_.assign(n, 0);
  std::vector<std::pair<uint32_t, uint32_t>> distinct;
  for (size_t i = 0; i < edges.size();) {
    size_t end = i + 1;
    while (end < edges.size() && edges[end] == edges[i]) ++end;
    distinct.push_back(edges[i]);
    if (end - i == 1) boundary_[edges[i].first] = boundary_[edges[i].second] = 1;
    i = end;
  }
  neighbourStart_.assign(n + 1, 0);
  for (const auto& [a, b] : distinct) ++neighbourStart_[a + 1], ++neighbourStart_[b + 1];
  for (size_t v = 0; v < n; ++v) neighbourStart_[v + 1] += neighbourStart_[v];
  neighbourList_.resize(neighbourStart_[n]);
  std::vector<uint32_t> filled(neighbourStart_.begin(), neighbourStart_.end() - 1);
  for (const auto& [a, b] : distinct) {
    neighbourList_[filled[a]++] = b;
    neighbourList_[filled[b]++] = a;
  }
}

std::vector<Vec3> TaubinSmoother::smoothed(const std::vector<Vec3>& positions) const {
  if (positions.size() != weldMap_.size())
    throw InputError(fmt::format("taubin smoothing: {} positions for {} vertices", positions.size(), weldMap_.size()));
  std::vector<Vec3d> x(positions.size());
  for (size_t v = 0; v < x.size(); ++v) x[v] = positions[v].cast<double>();
  std::vector<Vec3d> next(x.size());
  for (int i = 0; i < options_.iterations; ++i) {
    umbrellaStep(neighbourStart_, neighbourList_, boundary_, options_.lambda, x, next);  // Taubin 1995 eq. 8: shrink ...
    umbrellaStep(neighbourStart_, neighbourList_, boundary_, options_.mu, next, x);      // ... and inflate
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
