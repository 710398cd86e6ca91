#pragma once
// A tetrahedral mesh in double precision (the flesh simulation's unknowns are its node
// positions), and the per-tetrahedron quantities every part of the simulation shares: the edge
// matrix D = [x1 - x0, x2 - x0, x3 - x0] (Dm in material space, Ds in world space) and the
// signed volume det(D) / 6.
#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

namespace lacrima::flesh {

using Vec3d = Eigen::Vector3d;
using Mat3d = Eigen::Matrix3d;
using Tet = std::array<int, 4>;

struct TetMesh {
  std::vector<Vec3d> nodes;
  std::vector<Tet> tets;  // positively oriented: det(Dm) > 0
};

inline Mat3d edgeMatrix(const std::vector<Vec3d>& x, const Tet& t) {
  Mat3d d;
  d.col(0) = x[size_t(t[1])] - x[size_t(t[0])];
  d.col(1) = x[size_t(t[2])] - x[size_t(t[0])];
  d.col(2) = x[size_t(t[3])] - x[size_t(t[0])];
  return d;
}

inline double signedVolume(const std::vector<Vec3d>& x, const Tet& t) { return edgeMatrix(x, t).determinant() / 6.0; }

// Empty when every index is a node and every tetrahedron has a positive volume; otherwise what
// is wrong with the first one that is not.
std::string findTetMeshDefect(const TetMesh& mesh);

// Every tetrahedron turned to positive orientation (two indices swapped where det(Dm) < 0).
void orientPositively(TetMesh& mesh);

double totalVolume(const TetMesh& mesh);

// A box [0, size] split into nx * ny * nz cubes of six tetrahedra each (the Kuhn split along
// the main diagonal, conforming across cube faces): a mesh with known answers for tests and
// benchmarks.
TetMesh makeBoxTetMesh(const Vec3d& size, int nx, int ny, int nz);

}  // namespace lacrima::flesh
