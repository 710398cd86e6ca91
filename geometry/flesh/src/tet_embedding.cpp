// embedPoints (flesh_volume.hpp): barycentric embedding through a uniform grid of tetrahedra.
#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "lacrima/flesh/flesh_volume.hpp"

namespace lacrima::flesh {

namespace {

Eigen::Vector4d barycentricIn(const TetMesh& mesh, size_t t, const Vec3d& p) {
  const Tet& tet = mesh.tets[t];
  const Mat3d d = edgeMatrix(mesh.nodes, tet);
  const Vec3d w = d.inverse() * (p - mesh.nodes[size_t(tet[0])]);
  return Eigen::Vector4d(1.0 - w.sum(), w.x(), w.y(), w.z());
}

class TetGrid {
 public:
  explicit TetGrid(const TetMesh& mesh) : mesh_(mesh) {
    lo_ = hi_ = mesh.nodes.front();
    for (const Vec3d& p : mesh.nodes) lo_ = lo_.cwiseMin(p), hi_ = hi_.cwiseMax(p);
    // About one tetrahedron a cell.
    const double volume = std::max((hi_ - lo_).prod(), 1e-30);
    cell_ = std::cbrt(volume / double(std::max<size_t>(mesh.tets.size(), 1)));
    for (int k = 0; k < 3; ++k) dims_[k] = std::clamp(int((hi_[k] - lo_[k]) / cell_) + 1, 1, 512);
    cells_.resize(size_t(dims_[0]) * size_t(dims_[1]) * size_t(dims_[2]));
    for (size_t t = 0; t < mesh.tets.size(); ++t) {
      Vec3d a = mesh.nodes[size_t(mesh.tets[t][0])], b = a;
      for (int c : mesh.tets[t]) a = a.cwiseMin(mesh.nodes[size_t(c)]), b = b.cwiseMax(mesh.nodes[size_t(c)]);
      const auto [i0, j0, k0] = cellOf(a);
      const auto [i1, j1, k1] = cellOf(b);
      for (int k = k0; k <= k1; ++k)
        for (int j = j0; j <= j1; ++j)
          for (int i = i0; i <= i1; ++i) cells_[index(i, j, k)].push_back(int(t));
    }
  }

  // The point's cell lists every tetrahedron whose box holds the point; one a hair away (a point
  // just outside the boundary) is listed at the point's cell or at a neighbour, since the slack is
  // far less than a cell. Ties go to the lower tetrahedron index: the same answer in any order.
  TetEmbedding embed(const Vec3d& p, double slack) const {
    TetEmbedding best;
    double bestMin = -std::numeric_limits<double>::infinity();
    const auto consider = [&](int t) {
      const Eigen::Vector4d w = barycentricIn(mesh_, size_t(t), p);
      const double smallest = w.minCoeff();
      if (smallest > bestMin || (smallest == bestMin && t < best.tet)) bestMin = smallest, best = {t, w};
    };
    const auto [i, j, k] = cellOf(p);
    for (int t : cells_[index(i, j, k)]) consider(t);
    if (bestMin < 0.0) {
      for (int dk = -1; dk <= 1; ++dk)
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di)
            if (inGrid(i + di, j + dj, k + dk))
              for (int t : cells_[index(i + di, j + dj, k + dk)]) consider(t);
    }
    return bestMin >= -slack ? best : TetEmbedding{};
  }

 private:
  std::array<int, 3> cellOf(const Vec3d& p) const {
    std::array<int, 3> c{};
    for (int k = 0; k < 3; ++k) c[size_t(k)] = std::clamp(int((p[k] - lo_[k]) / cell_), 0, dims_[k] - 1);
    return c;
  }
  bool inGrid(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < dims_[0] && j < dims_[1] && k < dims_[2];
  }
  size_t index(int i, int j, int k) const { return (size_t(k) * size_t(dims_[1]) + size_t(j)) * size_t(dims_[0]) + size_t(i); }

  const TetMesh& mesh_;
  Vec3d lo_, hi_;
  double cell_ = 1.0;
  int dims_[3] = {1, 1, 1};
  std::vector<std::vector<int>> cells_;
};

}  // namespace

std::vector<TetEmbedding> embedPoints(const TetMesh& mesh, const std::vector<Vec3d>& points, double slack) {
  std::vector<TetEmbedding> out(points.size());
  if (mesh.tets.empty()) return out;
  const TetGrid grid(mesh);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) out[i] = grid.embed(points[i], slack);
  });
  return out;
}

Vec3d embeddedPosition(const TetMesh& topology, const std::vector<Vec3d>& nodes, const TetEmbedding& e) {
  Vec3d sum = Vec3d::Zero();
  for (int c = 0; c < 4; ++c) sum += e.weights[c] * nodes[size_t(topology.tets[size_t(e.tet)][size_t(c)])];
  return sum;
}

}  // namespace lacrima::flesh
