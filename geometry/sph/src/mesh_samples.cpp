// Boundary samples on a triangle mesh; see meshSurfaceSamples in dfsph.hpp.
#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "lacrima/base/hash.hpp"
#include "lacrima/sph/dfsph.hpp"

namespace lacrima::sph {

namespace {

// A sample's position rounded to a hundredth of the spacing: the same point reached from two
// triangles (a shared vertex or edge point) rounds alike whatever float path computed it.
uint64_t roundedKey(const Vec3d& p, double spacing) {
  const double unit = 0.01 * spacing;
  uint64_t key = 0x5eedULL;
  for (int axis = 0; axis < 3; ++axis) key = hashCombine(key, uint64_t(int64_t(std::llround(p[axis] / unit))));
  return key;
}

// Triangle t's corners, and how many pieces its longest edge is cut into so that no two
// neighbouring sites on it are farther apart than `spacing`.
struct TriangleLattice {
  Vec3d a, b, c;
  int divisions;
};
TriangleLattice triangleLattice(const TriangleMesh& mesh, size_t t, double spacing) {
  const Vec3d a = mesh.positions[mesh.indices[3 * t]].cast<double>();
  const Vec3d b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
  const Vec3d c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  return {a, b, c, std::max(1, int(std::ceil(longest / spacing)))};
}

// Whether triangle t is to be sampled (`selected` empty or of another size: all are).
bool isSelected(const std::vector<bool>& selected, const TriangleMesh& mesh, size_t t) {
  return selected.size() != mesh.triangleCount() || selected[t];
}

}  // namespace

double meshSurfaceSiteCandidates(const TriangleMesh& mesh, double spacing, const std::vector<bool>& selected) {
  double candidates = 0.0;
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
    if (isSelected(selected, mesh, t)) {
      const double n = triangleLattice(mesh, t, spacing).divisions;
      candidates += 0.5 * (n + 1.0) * (n + 2.0);
    }
  return candidates;
}

std::vector<SurfaceSite> meshSurfaceSites(const TriangleMesh& mesh, double spacing, const std::vector<bool>& selected) {
  std::vector<SurfaceSite> sites;
  std::unordered_set<uint64_t> seen;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    if (!isSelected(selected, mesh, t)) continue;
    const auto [a, b, c, n] = triangleLattice(mesh, t, spacing);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const SurfaceSite site{uint32_t(t), double(i) / n, double(j) / n};
        const Vec3d p = a + site.towardsSecond * (b - a) + site.towardsThird * (c - a);
        if (seen.insert(roundedKey(p, spacing)).second) sites.push_back(site);
      }
  }
  return sites;
}

std::vector<Vec3d> sitePositions(const TriangleMesh& mesh, const std::vector<SurfaceSite>& sites) {
  std::vector<Vec3d> positions;
  positions.reserve(sites.size());
  for (const SurfaceSite& site : sites) {
    const size_t t = site.triangle;
    const Vec3d a = mesh.positions[mesh.indices[3 * t]].cast<double>();
    const Vec3d b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
    const Vec3d c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
    positions.push_back(a + site.towardsSecond * (b - a) + site.towardsThird * (c - a));
  }
  return positions;
}

std::vector<Vec3d> meshSurfaceSamples(const TriangleMesh& mesh, double spacing) {
  return sitePositions(mesh, meshSurfaceSites(mesh, spacing));
}

}  // namespace lacrima::sph
