#include "lacrima/flesh/tet_mesh.hpp"

#include <fmt/format.h>

#include <utility>

namespace lacrima::flesh {

std::string findTetMeshDefect(const TetMesh& mesh) {
  const int nodeCount = int(mesh.nodes.size());
  for (size_t i = 0; i < mesh.tets.size(); ++i) {
    for (int corner : mesh.tets[i])
      if (corner < 0 || corner >= nodeCount)
        return fmt::format("tetrahedron {} names node {} of {}", i, corner, nodeCount);
    const double volume = signedVolume(mesh.nodes, mesh.tets[i]);
    if (!(volume > 0.0)) return fmt::format("tetrahedron {} has volume {} (not positive)", i, volume);
  }
  return {};
}

void orientPositively(TetMesh& mesh) {
  for (Tet& t : mesh.tets)
    if (signedVolume(mesh.nodes, t) < 0.0) std::swap(t[2], t[3]);
}

double totalVolume(const TetMesh& mesh) {
  double sum = 0.0;
  for (const Tet& t : mesh.tets) sum += signedVolume(mesh.nodes, t);
  return sum;
}

TetMesh makeBoxTetMesh(const Vec3d& size, int nx, int ny, int nz) {
  TetMesh mesh;
  const auto node = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.nodes.emplace_back(size.x() * i / nx, size.y() * j / ny, size.z() * k / nz);
  // The six tetrahedra of a cube around its diagonal 0-7, corners numbered by their (x, y, z) bits.
  static constexpr int kKuhn[6][4] = {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        int corner[8];
        for (int c = 0; c < 8; ++c) corner[c] = node(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
        for (const auto& t : kKuhn) mesh.tets.push_back({corner[t[0]], corner[t[1]], corner[t[2]], corner[t[3]]});
      }
  orientPositively(mesh);
  return mesh;
}

}  // namespace lacrima::flesh
