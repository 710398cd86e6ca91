// Particles to a water surface through OpenVDB; see sph_surface.hpp.
#include "lacrima/sph/sph_surface.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/GridOperators.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <mutex>

namespace lacrima::sph {

namespace {

// ParticlesToLevelSet's particle-list interface over positions with one radius.
class ParticleSpheres {
 public:
  using PosType = openvdb::Vec3R;
  ParticleSpheres(const std::vector<Vec3d>& positions, double radius) : positions_(positions), radius_(radius) {}
  size_t size() const { return positions_.size(); }
  void getPos(size_t n, openvdb::Vec3R& p) const { p = openvdb::Vec3R(positions_[n].x(), positions_[n].y(), positions_[n].z()); }
  void getPosRad(size_t n, openvdb::Vec3R& p, openvdb::Real& r) const {
    getPos(n, p);
    r = radius_;
  }

 private:
  const std::vector<Vec3d>& positions_;
  double radius_;
};

void initializeOpenVdbOnce() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

TriangleMesh meshOfLevelSet(const openvdb::FloatGrid& grid) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, 0.0, 0.0);
  TriangleMesh mesh;
  mesh.name = "sph_surface";
  mesh.positions.reserve(points.size());
  for (const openvdb::Vec3s& p : points) mesh.positions.emplace_back(p.x(), p.y(), p.z());
  // VolumeToMesh winds polygons clockwise seen from outside (its level sets are negative inside);
  // lacrima's meshes are counter-clockwise, so each is reversed.
  for (const openvdb::Vec3I& t : triangles) mesh.indices.insert(mesh.indices.end(), {t[2], t[1], t[0]});
  for (const openvdb::Vec4I& q : quads) {
    mesh.indices.insert(mesh.indices.end(), {q[3], q[2], q[1]});
    mesh.indices.insert(mesh.indices.end(), {q[3], q[1], q[0]});
  }
  return mesh;
}

// Vertex normals from the level set's gradient (trilinear between voxel centres): smooth across
// the mesh's voxel-sized facets, whose own normals would show the voxel grid as glitter in
// reflections and refraction.
void setNormalsFromGradient(const openvdb::FloatGrid& grid, TriangleMesh& mesh) {
  const openvdb::Vec3SGrid::Ptr gradient = openvdb::tools::gradient(grid);
  const openvdb::tools::GridSampler<openvdb::Vec3SGrid, openvdb::tools::BoxSampler> sampler(*gradient);
  computeSmoothNormals(mesh, false);  // the fallback where the gradient vanishes
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3& p = mesh.positions[i];
    const openvdb::Vec3s g = sampler.wsSample(openvdb::Vec3R(p.x(), p.y(), p.z()));
    const Vec3 n(g.x(), g.y(), g.z());
    if (n.norm() > 0.0f) mesh.normals[i] = n.normalized();
  }
}

}  // namespace

TriangleMesh surfaceOfParticles(const std::vector<Vec3d>& positions, double particleRadius, const SurfaceParams& params) {
  if (positions.empty()) return {};
  initializeOpenVdbOnce();
  const double voxel = particleRadius / params.voxelsPerRadius;
  const float halfWidth = float(openvdb::LEVEL_SET_HALF_WIDTH);
  openvdb::FloatGrid::Ptr grid = openvdb::createLevelSet<openvdb::FloatGrid>(voxel, halfWidth);
  openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*grid);
  raster.rasterizeSpheres(ParticleSpheres(positions, 2.0 * particleRadius));
  raster.finalize(true);
  openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*grid);
  for (int i = 0; i < params.smoothingIterations; ++i) filter.meanCurvature();
  filter.offset(float(particleRadius));  // positive: the surface moves inwards by r
  TriangleMesh mesh = meshOfLevelSet(*grid);
  setNormalsFromGradient(*grid, mesh);
  return mesh;
}

}  // namespace lacrima::sph
