// The liquid's surface from particles (sph_surface.hpp): a closed, outward-facing mesh whose faces
// lie where the outer particles end, enclosing the particles' volume.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "lacrima/sph/dfsph.hpp"
#include "lacrima/sph/sph_surface.hpp"

namespace lacrima::sph {
namespace sph_surface_test {

// Signed volume by the divergence theorem (positive for an outward-facing closed mesh).
double enclosedVolume(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const Vec3d a = mesh.positions[mesh.indices[3 * t]].cast<double>();
    const Vec3d b = mesh.positions[mesh.indices[3 * t + 1]].cast<double>();
    const Vec3d c = mesh.positions[mesh.indices[3 * t + 2]].cast<double>();
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

// Every directed edge once and its reverse once: closed, consistently wound.
bool closedAndConsistent(const TriangleMesh& mesh) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (size_t t = 0; t < mesh.triangleCount(); ++t)
    for (int e = 0; e < 3; ++e) ++directed[{mesh.indices[3 * t + e], mesh.indices[3 * t + (e + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    if (count != 1) return false;
    const auto reverse = directed.find({edge.second, edge.first});
    if (reverse == directed.end() || reverse->second != 1) return false;
  }
  return true;
}

TEST(SphSurface, ABlockOfParticlesBecomesAClosedBoxWhereItsParticlesEnd) {
  const double r = 0.001, side = 0.02;
  const TriangleMesh mesh = surfaceOfParticles(latticeBlock(Vec3d::Zero(), Vec3d::Constant(side), 2.0 * r), r);
  ASSERT_GT(mesh.triangleCount(), 100u);
  EXPECT_TRUE(closedAndConsistent(mesh));
  const double volume = enclosedVolume(mesh);
  std::printf("[ surface ] %zu triangles, volume %.4e m^3 (block %.4e)\n", mesh.triangleCount(), volume, side * side * side);
  EXPECT_NEAR(volume, side * side * side, 0.08 * side * side * side);  // rounded edges and corners take a little
  Vec3 lo = mesh.positions[0], hi = mesh.positions[0];
  for (const Vec3& p : mesh.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(lo[axis], 0.0, 0.5 * r) << "axis " << axis;
    EXPECT_NEAR(hi[axis], side, 0.5 * r) << "axis " << axis;
  }
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
}

TEST(SphSurface, NoParticlesNoSurface) { EXPECT_EQ(surfaceOfParticles({}, 0.001).triangleCount(), 0u); }

}  // namespace sph_surface_test
}  // namespace lacrima::sph
